// SimulationController's parameters: values that act at once go to the model; values that only a Reset
// applies wait here, so the model keeps those its state was built with and every readout, plot and
// picture describes what is simulated (a mass typed in must not change kT before the disks have it).
#include "SimulationController.h"

#include "ViewChooser.h"
#include "i18n/Translations.h"

namespace pl::ui {

namespace {

bool waitsForReset(const Model& model, const std::string& key) {
    const ParamSpec* spec = findSpec(model.paramSpecs(), key);
    return spec && !spec->appliesLive;
}

} // namespace

QString SimulationController::setParameters(const ParamValues& values) {
    if (!model_) return tr("No experiment is loaded.");
    if (isReadOnly()) return tr("This run is read-only: open a preset to change parameters.");
    const ParamValues inUse = model_->params();
    ParamValues checked = pending_; // the waiting values are checked together with the new ones
    for (const auto& [key, value] : values) checked[key] = value;
    try {
        model_->setParams(checked);
    } catch (const ParamError& e) { // in the panel's words and language: each parameter by its label
        return coreRefusal(e.message(), model_->paramSpecs());
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    ParamValues builtWith;
    for (const auto& [key, value] : checked) {
        const auto current = inUse.find(key);
        if (!waitsForReset(*model_, key) || current == inUse.end()) continue;
        builtWith[key] = current->second;
        // A value set back to the one the state has waits for nothing.
        if (current->second == value)
            pending_.erase(key);
        else
            pending_[key] = value;
    }
    // The model goes back to the values its state was built with. Should those not fit the new live
    // values (a cross-field rule between the two), the model keeps the new ones: they still wait for Reset.
    try {
        if (!builtWith.empty()) model_->setParams(builtWith);
    } catch (const std::exception&) {
    }
    // Show (the `view` of a scene with sampled fields) chooses what is drawn, not the experiment.
    const bool viewOnly = values.size() == 1 && values.begin()->first == ViewChooser::kKey;
    if (!viewOnly) noteEdited();
    emit parametersChanged();
    return {};
}

ParamValues SimulationController::parameterValues() const {
    if (!model_) return {};
    ParamValues values = model_->params();
    for (const auto& [key, value] : pending_) values[key] = value;
    return values;
}

Preset SimulationController::experimentPreset() const {
    Preset preset = model_->toPreset();
    for (const auto& [key, value] : pending_) preset.params[key] = value;
    return preset;
}

void SimulationController::reset() {
    if (!model_ || isReadOnly()) return;
    // The state is rebuilt from the values it was loaded or last reset with and the changes that waited:
    // disks spawned since are no part of the experiment (Reset gives the preset's count back).
    ParamValues buildWith;
    for (const auto& [key, value] : applied_)
        if (waitsForReset(*model_, key)) buildWith[key] = value;
    for (const auto& [key, value] : pending_) buildWith[key] = value;
    try {
        model_->setParams(buildWith);
        model_->reset();
    } catch (const ParamError& e) {
        emit notice(tr("Cannot reset: %1").arg(coreRefusal(e.message(), model_->paramSpecs())));
        return;
    } catch (const std::exception& e) {
        emit notice(tr("Cannot reset: %1").arg(QString::fromStdString(e.what())));
        return;
    }
    pending_.clear();
    applied_ = model_->params();
    applyDirection();
    restartSeries();
    emit parametersChanged();
    emit frameAdvanced();
}

} // namespace pl::ui
