// SimulationController: fixed-dt stepping driven by a frame timer.
#include "SimulationController.h"

#include <cmath>

namespace pl::ui {

namespace {
constexpr int kFrameIntervalMs = 16; // ~60 frames per second
constexpr int kMaxStepsPerFrame = 10;
} // namespace

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
    timer_.setInterval(kFrameIntervalMs);
    connect(&timer_, &QTimer::timeout, this, &SimulationController::advanceFrame);
}

QString SimulationController::load(const Preset& preset) {
    std::unique_ptr<Model> next;
    try {
        next = instantiate(preset);
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    model_ = std::move(next);
    const auto values = model_->params();
    const auto it = values.find("dt");
    baseDt_ = it != values.end() ? std::abs(std::get<double>(it->second)) : 0.0;
    applyDirection();
    emit modelReplaced();
    return {};
}

void SimulationController::play() {
    if (!model_ || model_->failure()) return;
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
    emit frameAdvanced();
}

void SimulationController::reset() {
    if (!model_) return;
    model_->reset();
    applyDirection();
    emit frameAdvanced();
}

void SimulationController::setStepsPerFrame(int n) {
    stepsPerFrame_ = std::clamp(n, -kMaxStepsPerFrame, kMaxStepsPerFrame);
    applyDirection();
}

void SimulationController::applyDirection() {
    if (!model_ || baseDt_ == 0.0 || stepsPerFrame_ == 0) return;
    const double signedDt = stepsPerFrame_ > 0 ? baseDt_ : -baseDt_;
    const auto values = model_->params();
    if (std::get<double>(values.at("dt")) != signedDt) model_->setParams({{"dt", signedDt}});
}

void SimulationController::advanceFrame() {
    if (!model_) return;
    const int steps = std::abs(stepsPerFrame_);
    for (int s = 0; s < steps && !model_->failure(); ++s) model_->step();
    stepsSinceClock_ += steps;
    if (rateClock_.isValid() && rateClock_.elapsed() > 500) {
        stepsPerSecond_ =
            1000.0 * static_cast<double>(stepsSinceClock_) / static_cast<double>(rateClock_.restart());
        stepsSinceClock_ = 0;
    }
    emit frameAdvanced();
    if (auto failure = model_->failure()) {
        pause();
        emit failed(QString::fromStdString(failure->message()));
    }
}

} // namespace pl::ui
