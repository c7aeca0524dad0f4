// PresentBoard: the registration speaks first; the fallbacks use only the Model interface and the
// parameter keys the UI reacts to in every kind (docs/architecture.md), never a kind's name.
#include "PresentBoard.h"

#include "ViewChooser.h"
#include "catalog/ModelCatalog.h"
#include "common/SceneTools.h"

#include <algorithm>
#include <cmath>

namespace pl::ui {

namespace {
constexpr std::size_t kFallbackReadouts = 4;

const PresentSpec* specOf(const Model& model) {
    const ModelDescriptor* descriptor = findModel(model.kind());
    return descriptor ? &descriptor->present : nullptr;
}

bool hasParameter(const Model& model, const char* key, ParamKind kind) {
    const ParamSpec* spec = findSpec(model.paramSpecs(), key);
    return spec && spec->kind == kind;
}

double realParameter(const ParamValues& values, const std::string& key) {
    const auto it = values.find(key);
    if (it == values.end()) return 0.0;
    const auto* value = std::get_if<double>(&it->second);
    return value ? *value : 0.0;
}
} // namespace

std::vector<PresentReadout> presentReadouts(const Model& model) {
    if (const PresentSpec* spec = specOf(model); spec && !spec->readouts.empty()) return spec->readouts;
    std::vector<PresentReadout> out;
    const ModelDescriptor* descriptor = findModel(model.kind());
    if (!descriptor) return out;
    for (const SeriesColumn& column : descriptor->series) {
        if (column.name == "step") continue; // the time says the same, in the kind's units
        out.push_back({column.name, column.label.empty() ? column.name : column.label, column.unit});
        if (out.size() == kFallbackReadouts) break;
    }
    return out;
}

std::string presentPlot(const Model& model) {
    if (const PresentSpec* spec = specOf(model); spec && !spec->plot.empty()) return spec->plot;
    const ModelDescriptor* descriptor = findModel(model.kind());
    if (!descriptor) return {};
    if (!descriptor->distributions.empty()) return descriptor->distributions.front();
    return descriptor->plots.empty() ? std::string() : descriptor->plots.front().name;
}

std::vector<LessonControl> lessonControls(Model& model) {
    if (const PresentSpec* spec = specOf(model); spec && !spec->controls.empty()) return spec->controls;
    std::vector<LessonControl> out;
    const bool tools = model.tools() != nullptr;
    if (tools) out.push_back(LessonControl::Heat);
    if (particleCountControl(model)) out.push_back(LessonControl::ParticleCount);
    if (hasParameter(model, "gravity", ParamKind::Real)) out.push_back(LessonControl::Gravity);
    if (hasParameter(model, "gravity_on", ParamKind::Boolean)) out.push_back(LessonControl::GravitySwitch);
    if (tools && hasParameter(model, "piston_enabled", ParamKind::Boolean))
        out.push_back(LessonControl::Piston);
    if (tools) out.push_back(LessonControl::SpawnTool);
    out.push_back(LessonControl::Pace);
    if (model.sampledFields() && hasParameter(model, ViewChooser::kKey, ParamKind::Choice))
        out.push_back(LessonControl::FieldView);
    return out;
}

double gravityMaximum(const Model& model) {
    const ParamValues values = model.params();
    const double now = std::abs(realParameter(values, "gravity"));
    const PresentSpec* spec = specOf(model);
    if (spec && spec->gravityMaximum) return std::max(spec->gravityMaximum(values), 2 * now);
    const ParamSpec* gravity = findSpec(model.paramSpecs(), "gravity");
    double fallback = 2 * now;
    if (gravity) {
        if (const auto* d = std::get_if<double>(&gravity->defaultValue))
            fallback = std::max(fallback, 2 * std::abs(*d));
        if (fallback <= 0) fallback = gravity->max;
    }
    return fallback > 0 ? fallback : 1.0;
}

const ParticleCountControl* particleCountControl(const Model& model) {
    const PresentSpec* spec = specOf(model);
    if (!spec) return nullptr;
    const ParticleCountControl& control = spec->particleCount;
    return control.count && control.largest && control.restartWith ? &control : nullptr;
}

} // namespace pl::ui
