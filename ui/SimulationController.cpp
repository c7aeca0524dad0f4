// SimulationController: fixed-dt stepping driven by a frame timer, so the physics never depends on the
// frame rate (a slow machine runs the same trajectory, only slower).
#include "SimulationController.h"

#include "FrameProfile.h"
#include "ImportedRunModel.h"
#include "viewport/QtGlContext.h"

#include <algorithm>
#include <cmath>

namespace pl::ui {

namespace {
constexpr int kFrameIntervalMs = 16; // ~60 frames per second
constexpr int kFramesPerSample = 3;  // ~20 rows per second for the plots
// Relative kinetic-energy change per time step at rate ±1: heating acts per step of model time, so a
// held slider warms the gas as much per simulated second at 1 as at 20 steps per frame (at the default
// 5 steps per frame, 3 % a frame).
constexpr double kHeatPerStepAtFull = 0.006;
} // namespace

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
    timer_.setInterval(kFrameIntervalMs);
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &SimulationController::advanceFrame);
}

QString SimulationController::load(const Preset& preset, const StateRecord* state) {
    gl::BackendChoice next;
    try {
        next = gl::createModel(preset.model, backend_, &preset, appComputeContext());
        if (state) next.model->restoreState(*state);
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    if (!next.message.empty()) emit notice(QString::fromStdString(next.message));
    adopt(std::move(next.model));
    return {};
}

void SimulationController::adopt(std::unique_ptr<Model> model) {
    model_ = std::move(model);
    importedFrom_.clear();
    if (const std::string warning = model_->accuracyWarning(); !warning.empty())
        emit notice(tr("Warning: %1").arg(QString::fromStdString(warning)));
    pending_.clear();
    if (stepsPerFrame_ < 0 && !model_->reversible()) setStepsPerFrame(-stepsPerFrame_);
    applyDirection();
    restartSeries();
    emit modelReplaced();
}

void SimulationController::showImported(std::unique_ptr<Model> model, TimeSeries series,
                                        const QString& source) {
    pause();
    // The run's last row says where it ended; the imported state itself starts its counters at zero.
    const auto& columns = series.columns();
    const auto last = [&series, &columns](const char* name) {
        const auto it = std::find(columns.begin(), columns.end(), name);
        return it == columns.end() || series.rows() == 0
                   ? 0.0
                   : series.row(series.rows() - 1)[static_cast<std::size_t>(it - columns.begin())];
    };
    model_ = std::make_unique<ImportedRunModel>(std::move(model), static_cast<std::int64_t>(last("step")),
                                                last("time"));
    importedFrom_ = source;
    pending_.clear();
    series_.replace(std::move(series));
    emit modelReplaced();
}

void SimulationController::setBackend(gl::Backend backend) {
    if (backend == backend_) return;
    backend_ = backend;
    if (!model_ || isReadOnly()) return; // the next experiment loaded computes there
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
    if (isReadOnly()) return tr("This run is read-only: open a preset to change parameters.");
    try {
        model_->setParams(values);
    } catch (const ParamError& e) { // in the panel's words: each parameter by its label
        const auto& specs = model_->paramSpecs();
        return QString::fromStdString(nameParameters(e.message(), [&specs](const std::string& key) {
            const ParamSpec* spec = findSpec(specs, key);
            return spec ? spec->label : key;
        }));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    for (const auto& [key, value] : values) {
        const ParamSpec* spec = findSpec(model_->paramSpecs(), key);
        if (spec && !spec->appliesLive) pending_[key] = value;
    }
    noteEdited();
    emit parametersChanged();
    return {};
}

void SimulationController::noteEdited() {
    emit edited();
}

const SceneTools* SimulationController::tools() const {
    return model_ && !isReadOnly() ? model_->tools() : nullptr;
}

SceneTools* SimulationController::editableTools() {
    return model_ && !isReadOnly() ? model_->tools() : nullptr;
}

bool SimulationController::addObstacle(const Obstacle& obstacle) {
    SceneTools* tools = editableTools();
    if (!tools) return false;
    tools->addObstacle(obstacle);
    noteEdited();
    return true;
}

bool SimulationController::removeObstacle(std::size_t index) {
    SceneTools* tools = editableTools();
    if (!tools || index >= tools->obstacles().size()) return false;
    tools->removeObstacle(index);
    noteEdited();
    return true;
}

bool SimulationController::steerObstacle(std::size_t index, double x, double y) {
    SceneTools* tools = editableTools();
    if (!tools || index >= tools->obstacles().size()) return false;
    if (isRunning())
        tools->dragObstacle(index, x, y);
    else
        tools->placeObstacle(index, x, y);
    noteEdited();
    return true;
}

bool SimulationController::releaseObstacle(std::size_t index) {
    SceneTools* tools = editableTools();
    if (!tools || index >= tools->obstacles().size()) return false;
    tools->releaseObstacle(index);
    return true;
}

bool SimulationController::steerPiston(double x) {
    SceneTools* tools = editableTools();
    if (!tools || !tools->hasPiston()) return false;
    if (isRunning())
        tools->dragPiston(x);
    else
        tools->placePiston(x);
    noteEdited();
    return true;
}

bool SimulationController::drivePiston(int direction) {
    SceneTools* tools = editableTools();
    if (!tools || !tools->hasPiston()) return false;
    tools->drivePiston(direction);
    noteEdited();
    return true;
}

QString SimulationController::spawnInRectangle(double x0, double y0, double x1, double y1) {
    SceneTools* tools = editableTools();
    if (!tools) return {};
    const std::string said = tools->spawnInRectangle(x0, y0, x1, y1);
    noteEdited();
    return QString::fromStdString(said);
}

bool SimulationController::scaleKineticEnergy(double factor) {
    SceneTools* tools = editableTools();
    if (!tools) return false;
    tools->scaleKineticEnergy(factor);
    noteEdited();
    return true;
}

bool SimulationController::runComplete() const {
    return model_ && model_->plannedSteps() > 0 && model_->stepCount() >= model_->plannedSteps();
}

void SimulationController::play() {
    if (!model_ || model_->failure() || isReadOnly()) return;
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
    if (!model_ || isReadOnly()) return;
    pause();
    stepModel();
    sample();
    emit frameAdvanced();
}

void SimulationController::watchSteps(int every, std::function<void()> atStep) {
    watchEvery_ = every > 0 && atStep ? every : 0;
    watch_ = std::move(atStep);
}

void SimulationController::stepModel() {
    model_->step();
    if (watchEvery_ > 0 && !model_->failure() && model_->stepCount() % watchEvery_ == 0) watch_();
}

void SimulationController::reset() {
    if (!model_ || isReadOnly()) return;
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
    if (!model_ || isReadOnly() || stepsPerFrame_ == 0) return;
    const int direction = stepsPerFrame_ > 0 ? 1 : -1;
    if (direction < 0 && !model_->reversible()) return; // setStepsPerFrame() refused it already
    if (model_->timeDirection() != direction) model_->setTimeDirection(direction);
}

void SimulationController::restartSeries() {
    series_.restart(model_->seriesColumns());
    framesSinceSample_ = 0;
    sample();
}

void SimulationController::sample() {
    if (!model_) return;
    model_->checkHealthNow(); // no row of an exploded state reaches the plots
    if (!model_->failure()) series_.append(model_->sampleSeries());
}

void SimulationController::advanceFrame() {
    if (!model_ || isReadOnly()) return;
    int steps = std::abs(stepsPerFrame_);
    if (model_->plannedSteps() > 0)
        steps = static_cast<int>(
            std::clamp<std::int64_t>(model_->plannedSteps() - model_->stepCount(), 0, steps));
    // The frame's steps of heating at once: one O(N) rescale a frame instead of one a step.
    if (heatRate_ != 0.0 && steps > 0 && model_->tools() && model_->particleCount() > 0)
        model_->tools()->scaleKineticEnergy(std::exp(kHeatPerStepAtFull * heatRate_ * steps));
    {
        const FramePartTimer timer(FramePart::Step);
        for (int s = 0; s < steps && !model_->failure(); ++s) stepModel();
    }
    stepsSinceClock_ += steps;
    if (rateClock_.isValid() && rateClock_.elapsed() > 500) {
        stepsPerSecond_ =
            1000.0 * static_cast<double>(stepsSinceClock_) / static_cast<double>(rateClock_.restart());
        stepsSinceClock_ = 0;
    }
    if (steps > 0 && ++framesSinceSample_ >= kFramesPerSample) {
        framesSinceSample_ = 0;
        const FramePartTimer timer(FramePart::Sample); // the row, and the plots' data refresh it triggers
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
