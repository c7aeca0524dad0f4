// SimulationController: fixed-dt stepping driven by a frame timer, so the physics never depends on the
// frame rate (a slow machine runs the same trajectory, only slower).
#include "SimulationController.h"

#include "gpu/QtGlContext.h"

#include <cmath>

namespace pl::ui {

namespace {
constexpr int kFrameIntervalMs = 16; // ~60 frames per second
constexpr int kMaxStepsPerFrame = 10;
constexpr int kFramesPerSample = 3;          // ~20 rows per second for the plots
constexpr double kHeatPerFrameAtFull = 0.03; // relative kinetic-energy change per frame at rate ±1
} // namespace

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
    timer_.setInterval(kFrameIntervalMs);
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &SimulationController::advanceFrame);
}

QString SimulationController::load(const Preset& preset) {
    gl::BackendChoice next;
    try {
        next = gl::createModel(preset.model, backend_, &preset, appComputeContext());
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    model_ = std::move(next.model);
    if (!next.message.empty()) emit notice(QString::fromStdString(next.message));
    pending_.clear();
    if (stepsPerFrame_ < 0 && !model_->reversible()) setStepsPerFrame(-stepsPerFrame_);
    const auto values = model_->params();
    const auto it = values.find("dt");
    baseDt_ = it != values.end() ? std::abs(std::get<double>(it->second)) : 0.0;
    applyDirection();
    restartSeries();
    emit modelReplaced();
    return {};
}

void SimulationController::setBackend(gl::Backend backend) {
    if (backend == backend_) return;
    backend_ = backend;
    if (!model_) return;
    const bool wasRunning = isRunning();
    pause();
    const QString problem = load(model_->toPreset());
    if (!problem.isEmpty())
        emit notice(problem);
    else
        emit notice(tr("Computing on the %1 now; the experiment restarted from its parameters.")
                        .arg(model_->backend() == "gl" ? tr("GPU") : tr("CPU")));
    if (wasRunning) play();
}

QString SimulationController::setParameters(const ParamValues& values) {
    if (!model_) return tr("No experiment is loaded.");
    try {
        model_->setParams(values);
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    for (const auto& [key, value] : values) {
        const ParamSpec* spec = findSpec(model_->paramSpecs(), key);
        if (spec && !spec->appliesLive) pending_[key] = value;
    }
    if (const auto it = values.find("dt"); it != values.end()) {
        baseDt_ = std::abs(std::get<double>(it->second));
        applyDirection();
    }
    noteEdited();
    emit parametersChanged();
    return {};
}

void SimulationController::noteEdited() {
    emit edited();
}

bool SimulationController::runComplete() const {
    return model_ && model_->plannedSteps() > 0 && model_->stepCount() >= model_->plannedSteps();
}

void SimulationController::play() {
    if (!model_ || model_->failure()) return;
    if (runComplete()) {
        emit notice(tr("The run is complete (%1 steps): Reset to run it again, or raise the run length.")
                        .arg(model_->plannedSteps()));
        return;
    }
    rateClock_.start();
    stepsSinceClock_ = 0;
    timer_.start();
    emit runningChanged(true);
}

void SimulationController::pause() {
    timer_.stop();
    emit runningChanged(false);
}

void SimulationController::togglePlay() {
    isRunning() ? pause() : play();
}

void SimulationController::stepOnce() {
    if (!model_) return;
    pause();
    model_->step();
    sample();
    emit frameAdvanced();
}

void SimulationController::reset() {
    if (!model_) return;
    model_->reset();
    pending_.clear();
    applyDirection();
    restartSeries();
    emit parametersChanged();
    emit frameAdvanced();
}

void SimulationController::setStepsPerFrame(int n) {
    stepsPerFrame_ = std::clamp(n, -kMaxStepsPerFrame, kMaxStepsPerFrame);
    if (stepsPerFrame_ < 0 && model_ && !model_->reversible()) {
        stepsPerFrame_ = 0;
        emit notice(
            tr("This scene cannot run backwards: its collisions are random, so time has one direction."));
    }
    applyDirection();
    emit stepsPerFrameChanged(stepsPerFrame_);
}

void SimulationController::setHeatRate(double rate) {
    heatRate_ = std::clamp(rate, -1.0, 1.0);
}

void SimulationController::applyDirection() {
    if (!model_ || baseDt_ == 0.0 || stepsPerFrame_ == 0 || !model_->reversible()) return;
    const double signedDt = stepsPerFrame_ > 0 ? baseDt_ : -baseDt_;
    const auto values = model_->params();
    if (std::get<double>(values.at("dt")) != signedDt) model_->setParams({{"dt", signedDt}});
}

void SimulationController::restartSeries() {
    series_.restart(model_->seriesColumns());
    framesSinceSample_ = 0;
    sample();
}

void SimulationController::sample() {
    if (model_) series_.append(model_->sampleSeries());
}

void SimulationController::advanceFrame() {
    if (!model_) return;
    if (heatRate_ != 0.0 && model_->tools() && model_->particleCount() > 0)
        model_->tools()->scaleKineticEnergy(std::exp(kHeatPerFrameAtFull * heatRate_));
    int steps = std::abs(stepsPerFrame_);
    if (model_->plannedSteps() > 0)
        steps = static_cast<int>(
            std::clamp<std::int64_t>(model_->plannedSteps() - model_->stepCount(), 0, steps));
    for (int s = 0; s < steps && !model_->failure(); ++s) model_->step();
    stepsSinceClock_ += steps;
    if (rateClock_.isValid() && rateClock_.elapsed() > 500) {
        stepsPerSecond_ =
            1000.0 * static_cast<double>(stepsSinceClock_) / static_cast<double>(rateClock_.restart());
        stepsSinceClock_ = 0;
    }
    if (steps > 0 && ++framesSinceSample_ >= kFramesPerSample) {
        framesSinceSample_ = 0;
        sample();
    }
    emit frameAdvanced();
    if (auto failure = model_->failure()) {
        pause();
        emit failed(QString::fromStdString(failure->message()));
    } else if (isRunning() && runComplete()) {
        if (framesSinceSample_ != 0) sample(); // the last step is always in the plots
        framesSinceSample_ = 0;
        pause();
        emit notice(tr("Run complete: %1 steps.").arg(model_->stepCount()));
    }
}

} // namespace pl::ui
