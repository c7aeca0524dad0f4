// Owns the model and time: play / pause / single step / reset, signed steps per frame (negative runs
// time backwards), a frame timer, and blow-up handling. Views only read from it.
#pragma once

#include "catalog/ModelCatalog.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <memory>

namespace pl::ui {

class SimulationController : public QObject {
    Q_OBJECT
public:
    explicit SimulationController(QObject* parent = nullptr);

    // Loads a preset (built-in name or path). On error the current experiment is kept and the message
    // returned; empty on success.
    QString load(const Preset& preset);
    Model* model() const { return model_.get(); }
    bool isRunning() const { return timer_.isActive(); }
    int stepsPerFrame() const { return stepsPerFrame_; }
    double stepsPerSecond() const { return stepsPerSecond_; }

public slots:
    void play();
    void pause();
    void togglePlay();
    void stepOnce();
    void reset();
    // −10 … 10 as in the seed's speed slider: |n| steps per frame, the sign chooses the direction of time.
    void setStepsPerFrame(int n);
    // Advances one frame's worth of steps and notifies views (the timer calls it; tests may too).
    void advanceFrame();

signals:
    void modelReplaced();
    void frameAdvanced();
    void runningChanged(bool running);
    void failed(const QString& message);

private:
    void applyDirection();

    std::unique_ptr<Model> model_;
    QTimer timer_;
    int stepsPerFrame_ = 5;
    double baseDt_ = 0.0;
    double stepsPerSecond_ = 0.0;
    QElapsedTimer rateClock_;
    long long stepsSinceClock_ = 0;
};

} // namespace pl::ui
