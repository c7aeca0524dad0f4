// The sentences with which the models refuse parameter values in the panel (ParamError), collected for
// translation: each as its template (CoreSentences.h), numbers and parameters left out, so that one entry
// serves every value and every parameter of the same kind of refusal.
#pragma once

#include <string>
#include <vector>

namespace pl::ui {

// The templates of the refusals a user can meet in the panel of each built-in preset: every numeric
// parameter below, at and above its bounds and at a few plain values, every choice and every switch,
// each alone from the preset's values. Made as if the machine could give a fixed amount of memory
// (AssumedMemory), so the list is the same on every machine. Sorted, unique.
std::vector<std::string> refusalTemplates();

} // namespace pl::ui
