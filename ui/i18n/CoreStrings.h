// The English texts the Qt-free core shows in the UI (scene titles, parameter labels, groups and tooltips,
// legend and axis names), collected from the core's own tables so that none is written a second time.
#pragma once

#include <string>
#include <vector>

namespace pl::ui {

// Qt Linguist context of every core text; the UI translates them with
// QCoreApplication::translate(kCoreContext, text) where it displays them (ui/i18n/Translations.h).
inline constexpr const char* kCoreContext = "pl::core";

// Every distinct core text a user can see: model titles and unit systems, each model's ParamSpec label,
// unit, group and tooltip, and the legend, axis and hint texts of every built-in preset's scene and
// histograms. Sorted, unique, no empty entries. Texts with numbers in them (histogram summaries, beam
// legends) change with every frame or parameter: they are included as their templates (CoreSentences.h).
std::vector<std::string> coreDisplayStrings();

// The texts as C++ that lupdate reads: one QT_TRANSLATE_NOOP(kCoreContext, "…") per text.
std::string coreStringsSource(const std::vector<std::string>& texts);

} // namespace pl::ui
