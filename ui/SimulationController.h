// Owns the model and time: play / pause / single step / reset, signed steps per frame (negative runs
// time backwards through the model's direction of time), a frame timer, the heat / cool control,
// blow-up handling, and the time-series store the plots read. Views only read from it; every edit of
// the model (parameters, the mouse tools, heat / cool) goes through it, so the document knows it is
// modified and one rule holds in every scene.
#pragma once

#include "SeriesStore.h"
#include "catalog/ModelCatalog.h"
#include "gl/Backends.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <functional>
#include <memory>

namespace pl::ui {

class SimulationController : public QObject {
    Q_OBJECT
public:
    explicit SimulationController(QObject* parent = nullptr);
    // The write-up's speed slider went to 10; 20 lets a slow machine keep up with a fast one's model time.
    static constexpr int kMaxStepsPerFrame = 20;

    // Loads a preset, and with a snapshot's state continues from it. On error the current experiment is
    // kept and the message returned; empty on success.
    QString load(const Preset& preset, const StateRecord* state = nullptr);
    // Runs a model built elsewhere as load() runs its own: the command line's record and report build
    // theirs from its options (--set, --seed, a snapshot) and use the plots of the app.
    void adopt(std::unique_ptr<Model> model);
    // Shows a run computed elsewhere (a LAMMPS run read back): its last state in the viewport and
    // histograms, its series in the plots. Read-only until the next load(): time does not run and
    // parameters do not change. source says where the data came from, for the status line.
    void showImported(std::unique_ptr<Model> model, TimeSeries series, const QString& source);
    bool isReadOnly() const { return !importedFrom_.isEmpty(); }
    const QString& importedFrom() const { return importedFrom_; }
    // Where new models compute (auto: the GPU for scenes large enough to gain from it). Changing it
    // restarts the experiment from its current parameters on the new backend.
    gl::Backend backend() const { return backend_; }
    void setBackend(gl::Backend backend);
    Model* model() const { return model_.get(); }
    SeriesStore* series() { return &series_; }
    bool isRunning() const { return timer_.isActive(); }
    int stepsPerFrame() const { return stepsPerFrame_; }
    double stepsPerSecond() const { return stepsPerSecond_; }

    // Calls atStep after every step whose count is a multiple of `every` (0: none), before the frame is
    // shown: a recording's frames are states after a fixed number of steps, whatever the frame rate.
    void watchSteps(int every, std::function<void()> atStep);

    // Applies parameter values (all or nothing). Returns the error naming the key, or empty.
    QString setParameters(const ParamValues& values);
    // Parameters changed since the last reset that only a reset applies.
    const ParamValues& pendingUntilReset() const { return pending_; }
    // Something the user did changed the experiment (tools, parameters): the document is modified.
    void noteEdited();

    // The scene's tools for reading (obstacles, the piston); nullptr when it has none or is read-only.
    const SceneTools* tools() const;
    // The mouse tools. Each edits the model, notes the edit and returns true; false (nothing done) when
    // the scene has no such tool or the index names no obstacle. A steered body heads for its target at
    // the scene's tool speed while time runs and is placed there at once while it stands still.
    bool addObstacle(const Obstacle& obstacle);
    bool removeObstacle(std::size_t index);
    bool steerObstacle(std::size_t index, double x, double y);
    bool releaseObstacle(std::size_t index); // it coasts on to its last target and stops there
    bool steerPiston(double x);
    // −1 compresses, +1 expands, 0 stops (at the scene's piston speed, while time runs).
    bool drivePiston(int direction);
    // Fills the rectangle (a point when the corners coincide) at the scene's temperature; the sentence
    // for the status bar, empty when the scene cannot spawn.
    QString spawnInRectangle(double x0, double y0, double x1, double y1);
    // Heat (factor > 1) or cool the particles at once: kinetic energy × factor.
    bool scaleKineticEnergy(double factor);

public slots:
    void play();
    void pause();
    void togglePlay();
    void stepOnce();
    void reset();
    // −20 … 20: |n| steps per frame, the sign chooses the direction of time.
    void setStepsPerFrame(int n);
    // −1 (cool) … 1 (heat): kinetic energy changes by up to ±0.6 % per time step while it is non-zero.
    void setHeatRate(double rate);
    // Advances one frame's worth of steps and notifies views (the timer calls it; tests may too).
    void advanceFrame();
    // Appends one row of the model's observables to the series store.
    void sample();

signals:
    void modelReplaced();
    void frameAdvanced();
    void runningChanged(bool running);
    void failed(const QString& message);
    void edited();
    void parametersChanged();
    void stepsPerFrameChanged(int n);
    void notice(const QString& message); // one line for the status bar

private:
    void applyDirection(); // the sign of stepsPerFrame_ as the model's direction of time
    // The model's tools when the user may edit them now.
    SceneTools* editableTools();
    void restartSeries();
    bool runComplete() const; // the model's planned run length is reached
    void stepModel();         // one step, and the step watch

    std::unique_ptr<Model> model_;
    gl::Backend backend_ = gl::Backend::Auto;
    SeriesStore series_;
    ParamValues pending_;
    QString importedFrom_; // empty while the model is ours to run
    QTimer timer_;
    int stepsPerFrame_ = 5;
    double heatRate_ = 0.0;
    double stepsPerSecond_ = 0.0;
    int framesSinceSample_ = 0;
    QElapsedTimer rateClock_;
    long long stepsSinceClock_ = 0;
    int watchEvery_ = 0;
    std::function<void()> watch_;
};

} // namespace pl::ui
