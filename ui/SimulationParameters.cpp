// SimulationController's parameters: values that act at once go to the model; values that only a Reset
// applies wait here, so the model keeps those its state was built with and every readout, plot and
// picture describes what is simulated (a mass typed in must not change kT before the disks have it).
#include "SimulationController.h"

#include "ViewChooser.h"
#include "i18n/Translations.h"

#include <QLocale>

namespace pl::ui {

namespace {

// A value as the panel shows it: a number in the interface's language, a choice or a switch as written.
QString shownValue(const ParamValue& value) {
    if (const double* number = std::get_if<double>(&value)) return QLocale().toString(*number, 'g', 6);
    if (const bool* flag = std::get_if<bool>(&value))
        return *flag ? QStringLiteral("on") : QStringLiteral("off");
    return QString::fromStdString(std::get<std::string>(value));
}

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
    const std::string unstableBefore = model_->stabilityRefusal();
    try {
        model_->setParams(checked);
    } catch (const ParamError& e) { // in the panel's words and language: each parameter by its label
        return coreRefusal(e.message(), model_->paramSpecs());
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    // A value that puts the step beyond a known stability bound (the gas's dt·ω beyond its integrator's
    // limit) is refused before a step is taken with it, naming the values that fit; the model keeps the
    // ones it had. A scene already beyond it can still be changed (back) without this.
    if (const std::string unstable = model_->stabilityRefusal();
        !unstable.empty() && unstableBefore.empty()) {
        try {
            model_->setParams(inUse);
        } catch (const std::exception&) {
        }
        QStringList changed;
        for (const auto& [key, value] : values)
            if (const ParamSpec* spec = findSpec(model_->paramSpecs(), key))
                changed << translatedLabel(*spec);
        return tr("%1 would make every step unstable: %2")
            .arg(changed.join(QStringLiteral(", ")), coreSentence(unstable));
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
    if (!viewOnly) {
        noteEdited();
        QStringList changed;
        for (const auto& [key, value] : values)
            if (const ParamSpec* spec = findSpec(model_->paramSpecs(), key))
                changed << tr("%1 (to %2)").arg(translatedLabel(*spec), shownValue(value));
        lastChange_ = changed.join(QStringLiteral(", "));
    }
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
    lastChange_.clear();
    applied_ = model_->params();
    applyDirection();
    restartSeries();
    emit parametersChanged();
    emit frameAdvanced();
}

} // namespace pl::ui
