// SimulationController: fixed-dt stepping driven by a frame timer, so the physics never depends on the
// frame rate (a slow machine runs the same trajectory, only slower). The automatic pace chooses how many
// of those steps a frame takes: as many as fit in a share of the frame, measured as it runs, up to the
// scene's watchable rate of simulated time per wall second.
#include "SimulationController.h"

#include "FrameProfile.h"
#include "ImportedRunModel.h"
#include "ViewChooser.h"
#include "catalog/ModelCatalog.h"
#include "i18n/Translations.h"
#include "viewport/QtGlContext.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pl::ui {

namespace {
constexpr int kFrameIntervalMs = 16; // ~60 frames per second
constexpr int kFramesPerSample = 3;  // ~20 rows per second for the plots
// Automatic pace: the most steps one frame takes (a GPU queues steps faster than it runs them, so the
// measured cost per step, not the clock inside the loop, bounds it there), and the most wall time [s] of
// watchable simulated time a frame may catch up after a slow one, so a stall never turns into a burst.
constexpr int kMaxAutomaticSteps = 20000;
constexpr double kMaxCatchUpSeconds = 0.05;
constexpr double kCostSmoothing = 0.25; // weight of the newest frame in the cost per step
constexpr double kNanosecondsPerMs = 1e6;
// The steps always get this much of a frame: where the paint alone misses frames, fewer steps would not
// bring them back, only slow the scene down.
constexpr double kMinStepBudgetMs = 4.0;
// A frame shown later than 1.5 frame intervals after the previous one was missed (a timer tick went by
// without a frame); each missed frame takes 20 % off the steps' share, each frame on time gives back
// 1 %: the pace settles where about one frame in twenty is missed, above 55 frames per second.
constexpr double kMissedFrameMs = 1.5 * kFrameIntervalMs;
constexpr double kBudgetDecrease = 0.8, kBudgetIncrease = 1.01;
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
        emit notice(tr("Warning: %1").arg(coreSentence(warning)));
    pending_.clear();
    lastChange_.clear();
    applied_ = model_->params();
    // The pace belongs to the scene: a new one starts automatic and forward, whatever the last one ran at.
    automatic_ = true;
    direction_ = 1;
    lastFrameSteps_ = 0;
    nanosecondsPerStep_ = 0.0;
    allowance_ = 0.0;
    stepBudgetMs_ = kStepShareOfFrameMs;
    applyDirection();
    restartSeries();
    emit modelReplaced();
    emit paceChanged();
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
    const QString problem = load(experimentPreset());
    if (!problem.isEmpty())
        emit notice(problem);
    else
        emit notice(tr("Computing on the %1 now; the experiment restarted from its parameters.")
                        .arg(model_->backend() == "gl" ? tr("GPU") : tr("CPU")));
    if (wasRunning) play();
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
    const std::size_t before = model_->particleCount();
    tools->addObstacle(obstacle);
    noteBodyPutDown(before);
    noteEdited();
    return true;
}

void SimulationController::noteBodyPutDown(std::size_t particlesBefore) {
    // A body put down on the particles moves them out of its way; where a crowd leaves no room, the scene
    // refuses those it cannot place, as spawning does, and the user is told.
    const std::size_t now = model_->particleCount();
    if (now < particlesBefore)
        emit notice(tr("%n particle(s) had no room beside the new body and were removed.", "",
                       static_cast<int>(particlesBefore - now)));
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
    const std::size_t before = model_->particleCount();
    if (isRunning())
        tools->dragObstacle(index, x, y);
    else
        tools->placeObstacle(index, x, y);
    noteBodyPutDown(before);
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
    simulatedSinceClock_ = 0.0;
    frameClock_.invalidate();
    shownClock_.invalidate();
    allowance_ = 0.0;
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

void SimulationController::watchSteps(int every, std::function<void()> atStep, std::function<bool()> ready) {
    watchEvery_ = every > 0 && atStep ? every : 0;
    watch_ = std::move(atStep);
    watchReady_ = watchEvery_ > 0 ? std::move(ready) : std::function<bool()>{};
}

void SimulationController::stepModel() {
    model_->step();
    if (watchEvery_ > 0 && !model_->failure() && model_->stepCount() % watchEvery_ == 0) watch_();
}

void SimulationController::setStepsPerFrame(int n) {
    n = std::clamp(n, -kMaxStepsPerFrame, kMaxStepsPerFrame);
    if (n < 0 && model_ && !model_->reversible()) {
        n = 0;
        emit notice(
            tr("This scene cannot run backwards: its collisions are random, so time has one direction."));
    }
    automatic_ = false;
    fixedSteps_ = std::abs(n);
    if (n != 0) direction_ = n > 0 ? 1 : -1;
    applyDirection();
    emit paceChanged();
}

void SimulationController::setAutomaticPace() {
    automatic_ = true;
    emit paceChanged();
}

void SimulationController::reverse() {
    if (model_ && !model_->reversible() && direction_ > 0) {
        emit notice(
            tr("This scene cannot run backwards: its collisions are random, so time has one direction."));
        return;
    }
    direction_ = -direction_;
    applyDirection();
    emit paceChanged();
}

void SimulationController::setHeatRate(double rate) {
    heatRate_ = std::clamp(rate, -1.0, 1.0);
}

double SimulationController::watchableRate() const {
    const ModelDescriptor* kind = model_ ? findModel(model_->kind()) : nullptr;
    return kind ? kind->watchableRate : 0.0;
}

QString SimulationController::timeUnit() const {
    const ModelDescriptor* kind = model_ ? findModel(model_->kind()) : nullptr;
    return kind ? QString::fromStdString(kind->units.time) : QString();
}

double SimulationController::heatRatePerTime() const {
    const double rate = watchableRate();
    return rate > 0 ? std::log(2.0) / (kHeatDoublingSeconds * rate) : 0.0;
}

void SimulationController::applyDirection() {
    if (!model_ || isReadOnly()) return;
    if (direction_ < 0 && !model_->reversible()) direction_ = 1; // a new scene that cannot run back
    if (model_->timeDirection() != direction_) model_->setTimeDirection(direction_);
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

int SimulationController::stepsThisFrame() {
    if (!automatic_) {
        lastFrameSteps_ = fixedSteps_;
        return fixedSteps_;
    }
    // The watchable rate's simulated time since the last frame, plus what a short frame left over.
    // A frame asked for while time stands (a test, --screenshot) counts as one frame interval.
    const double rate = watchableRate();
    const bool timed = isRunning() && frameClock_.isValid();
    const double wall =
        timed ? static_cast<double>(frameClock_.restart()) / 1000.0 : kFrameIntervalMs / 1000.0;
    if (isRunning() && !timed) frameClock_.start();
    allowance_ = rate > 0 ? std::min(allowance_ + rate * wall, rate * kMaxCatchUpSeconds)
                          : std::numeric_limits<double>::infinity(); // a kind without a rate: the share alone
    // The share of the frame at the cost per step measured so far (the loop also watches the clock).
    if (nanosecondsPerStep_ <= 0) return 1; // the first frame measures
    return static_cast<int>(std::clamp(stepBudgetMs_ * kNanosecondsPerMs / nanosecondsPerStep_ * 4.0, 1.0,
                                       static_cast<double>(kMaxAutomaticSteps)));
}

void SimulationController::frameShown() {
    if (!isRunning()) {
        shownClock_.invalidate();
        return;
    }
    const bool measured = shownClock_.isValid();
    const double interval =
        measured ? static_cast<double>(shownClock_.nsecsElapsed()) / kNanosecondsPerMs : 0.0;
    shownClock_.start();
    if (!measured) return;
    // Multiplicative decrease when a frame was missed, slow recovery up to the share: the frame rate stays
    // near 60 while the steps take what the paint leaves.
    if (interval > kMissedFrameMs)
        stepBudgetMs_ = std::max(kMinStepBudgetMs, stepBudgetMs_ * kBudgetDecrease);
    else
        stepBudgetMs_ = std::min(kStepShareOfFrameMs, stepBudgetMs_ * kBudgetIncrease);
}

void SimulationController::noteFrameCost(int steps, qint64 nanoseconds) {
    if (steps <= 0) return;
    const double perStep = static_cast<double>(nanoseconds) / steps;
    nanosecondsPerStep_ = nanosecondsPerStep_ <= 0
                              ? perStep
                              : (1 - kCostSmoothing) * nanosecondsPerStep_ + kCostSmoothing * perStep;
}

void SimulationController::advanceFrame() {
    if (!model_ || isReadOnly()) return;
    int limit = stepsThisFrame();
    if (model_->plannedSteps() > 0)
        limit = static_cast<int>(
            std::clamp<std::int64_t>(model_->plannedSteps() - model_->stepCount(), 0, limit));
    const double startTime = model_->time();
    int steps = 0;
    {
        const FramePartTimer timer(FramePart::Step);
        QElapsedTimer clock;
        clock.start();
        const qint64 budget = static_cast<qint64>(stepBudgetMs_ * kNanosecondsPerMs);
        if (automatic_) {
            while (steps < limit && !model_->failure() && std::abs(model_->time() - startTime) < allowance_ &&
                   clock.nsecsElapsed() < budget && (!watchReady_ || watchReady_())) {
                stepModel();
                ++steps;
            }
            model_->finishPendingWork(); // a GPU's queued steps count in the cost they took
            noteFrameCost(steps, clock.nsecsElapsed());
            lastFrameSteps_ = steps;
        } else {
            for (; steps < limit && !model_->failure(); ++steps) stepModel();
        }
    }
    const double simulated = std::abs(model_->time() - startTime);

    if (automatic_ && std::isfinite(allowance_)) allowance_ -= simulated;
    // Heating acts per simulated time: one O(N) rescale a frame for the frame's steps.
    if (heatRate_ != 0.0 && simulated > 0 && model_->tools() && model_->particleCount() > 0 &&
        !model_->failure())
        model_->tools()->scaleKineticEnergy(std::exp(heatRatePerTime() * heatRate_ * simulated));
    stepsSinceClock_ += steps;
    simulatedSinceClock_ += simulated;
    if (rateClock_.isValid() && rateClock_.elapsed() > 500) {
        const double seconds = static_cast<double>(rateClock_.restart()) / 1000.0;
        stepsPerSecond_ = static_cast<double>(stepsSinceClock_) / seconds;
        simulatedPerSecond_ = simulatedSinceClock_ / seconds;
        stepsSinceClock_ = 0;
        simulatedSinceClock_ = 0.0;
    }
    if (steps > 0 && ++framesSinceSample_ >= kFramesPerSample) {
        framesSinceSample_ = 0;
        const FramePartTimer timer(FramePart::Sample); // the row, and the plots' data refresh it triggers
        sample();
    }
    emit frameAdvanced();
    if (auto failure = model_->failure()) {
        pause();
        const QString message = QString::fromStdString(failure->message());
        emit failed(lastChange_.isEmpty()
                        ? message
                        : tr("The last change before it: %1. Set it back, or press Reset (Ctrl+R).\n\n%2")
                              .arg(lastChange_, message));
    } else if (isRunning() && runComplete()) {
        if (framesSinceSample_ != 0) sample(); // the last step is always in the plots
        framesSinceSample_ = 0;
        pause();
        emit notice(tr("Run complete: %1 steps.").arg(model_->stepCount()));
    }
}

} // namespace pl::ui
