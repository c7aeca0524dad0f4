// Collects the core's visible texts for translation; Qt-free, so the generator that writes them for
// lupdate links only particlelab_core.
#include "CoreStrings.h"

#include "CoreRefusals.h"
#include "CoreSentences.h"

#include "catalog/ModelCatalog.h"
#include "common/sweep/CellOutcome.h"
#include "gas/GasIntegratorTable.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>

namespace pl::ui {

namespace {

bool hasDigit(const std::string& text) {
    return std::any_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

// A C++ string literal of text: quotes, backslashes and control characters escaped, UTF-8 kept.
std::string literal(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char code[8];
                std::snprintf(code, sizeof code, "\\%03o", static_cast<unsigned char>(c));
                out += code;
            } else {
                out += c;
            }
        }
    }
    return out + "\"";
}

} // namespace

std::vector<std::string> coreDisplayStrings() {
    std::set<std::string> texts;
    const auto add = [&texts](const std::string& text) {
        if (!text.empty()) texts.insert(text);
    };
    for (const ModelDescriptor& info : modelCatalog()) {
        add(info.title);
        add(info.units.name); // the parameter panel's first line and its tooltip
        add(info.units.summary);
        for (const ParamSpec& spec : *info.specs) {
            add(spec.label);
            add(spec.unit); // mostly symbols that stay as they are, but some are words ("steps")
            add(spec.group);
            add(spec.tooltip);
            for (const std::string& choice : spec.choices) add(choice); // shown translated, kept as keys
        }
        // The series docks' titles, axes and legends.
        for (const PlotSpec& plot : info.plots) {
            add(plot.title);
            for (const PlotPanel* panel : {&plot.upper, &plot.lower}) {
                add(panel->yLabel);
                add(panel->xLabel);
                for (const PlotCurve& curve : panel->curves) add(curve.label);
            }
        }
        // Present mode's readouts.
        for (const PresentReadout& readout : info.present.readouts) {
            add(readout.label);
            add(readout.unit);
        }
    }
    // The methods lab's legend of how each cell of a sweep ended.
    using methods::CellOutcome;
    for (const CellOutcome outcome :
         {CellOutcome::Stable, CellOutcome::Inaccurate, CellOutcome::Unstable, CellOutcome::OverCompressed,
          CellOutcome::Exploded, CellOutcome::Rejected})
        add(methods::outcomeName(outcome));
    // The gas's integrators, described in the methods lab's integrator choice.
    for (const GasIntegratorInfo& scheme : gasIntegrators()) add(scheme.description);
    // Scene legends and histogram names are made by the models at run time: every built-in preset's
    // freshly reset model shows them.
    for (const BuiltinPreset& builtin : builtinPresets()) {
        const auto model = instantiate(builtin.preset);
        if (const std::string warning = model->accuracyWarning(); !warning.empty())
            add(sentenceTemplate(warning).text);
        const SceneView view = model->sceneView();
        for (const std::string* text : {&view.xLabel, &view.yLabel, &view.colourLabel, &view.hint})
            add(*text);
        // Texts with numbers as their templates (CoreSentences.h): beam legends, histogram summaries.
        for (const std::string& category : view.categories)
            add(hasDigit(category) ? sentenceTemplate(category).text : category);
        for (const NamedHistogram& histogram : model->histograms()) {
            add(histogram.label);
            add(histogram.axis);
            add(sentenceTemplate(histogram.summary).text);
        }
        // Sampled fields: the probe's and the Profile dock's names, and each field's legend title as the
        // `view` choice shows it.
        if (const SampledFields* fields = model->sampledFields()) {
            for (const FieldChoice& choice : fields->fieldChoices()) add(choice.label);
            if (const ParamSpec* spec = findSpec(model->paramSpecs(), "view"))
                for (const std::string& choice : spec->choices) {
                    model->setParams({{"view", choice}});
                    const SceneView fieldView = model->sceneView();
                    if (fieldView.field) add(fieldView.field->label);
                    add(fieldView.hint); // before the window opens
                }
        }
    }
    // The panel's refusals of parameter values.
    for (const std::string& refusal : refusalTemplates()) add(refusal);
    return {texts.begin(), texts.end()};
}

std::string coreStringsSource(const std::vector<std::string>& texts) {
    std::string out =
        "// Generated by particlelab_core_strings from the core's tables: never edited, never compiled;\n"
        "// lupdate reads it so that resources/translations/*.ts hold the core's texts.\n"
        "static const char* const coreTexts[] = {\n";
    for (const std::string& text : texts)
        out += "    QT_TRANSLATE_NOOP(" + literal(kCoreContext) + ", " + literal(text) + "),\n";
    return out + "};\n";
}

} // namespace pl::ui
