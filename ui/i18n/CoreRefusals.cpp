// Collects the refusals by asking the models themselves, so a sentence is written once, in the core, and
// a new check reaches the catalogue without a list kept by hand.
#include "CoreRefusals.h"

#include "CoreSentences.h"

#include "catalog/ModelCatalog.h"
#include "common/MemoryBudget.h"

#include <cmath>
#include <memory>
#include <set>

namespace pl::ui {

namespace {

// The values a user can give a parameter in the panel: the field takes any number and the boxes their
// choices, so a text that is no number never reaches the model.
std::vector<ParamValue> valuesToTry(const ParamSpec& spec) {
    switch (spec.kind) {
    case ParamKind::Real:
    case ParamKind::Integer: {
        std::vector<ParamValue> values{
            spec.min, spec.max, spec.min - 1.0 - std::abs(spec.min), spec.max + 1.0 + std::abs(spec.max), 0.0,
            -1.0,     1.0};
        if (spec.kind == ParamKind::Integer) values.emplace_back(spec.min + 0.5);
        return values;
    }
    case ParamKind::Boolean:
        return {true, false};
    case ParamKind::Choice:
        return {spec.choices.begin(), spec.choices.end()};
    case ParamKind::Color:
        return {};
    }
    return {};
}

void collect(std::set<std::string>& texts, Model& model, double memoryBytes) {
    const AssumedMemory memory(memoryBytes);
    const ParamValues original = model.params();
    for (const ParamSpec& spec : model.paramSpecs())
        for (const ParamValue& value : valuesToTry(spec)) {
            try {
                model.setParams({{spec.key, value}});
                model.setParams(original);
            } catch (const ParamError& e) {
                texts.insert(sentenceTemplate(e.message()).text);
            }
        }
}

} // namespace

std::vector<std::string> refusalTemplates() {
    constexpr double kMiB = 1024.0 * 1024.0;
    std::set<std::string> texts;
    for (const BuiltinPreset& builtin : builtinPresets()) {
        std::unique_ptr<Model> model;
        {
            const AssumedMemory plenty(65536 * kMiB);
            model = instantiate(builtin.preset);
        }
        // A workstation's, a classroom laptop's, a busy one's and an exhausted one's free memory: the
        // memory refusals name sizes in GiB, MiB and KiB, and a run whose particles alone do not fit.
        for (const double bytes : {65536 * kMiB, 4096 * kMiB, 256 * kMiB, kMiB / 4})
            collect(texts, *model, bytes);
    }
    return {texts.begin(), texts.end()};
}

} // namespace pl::ui
