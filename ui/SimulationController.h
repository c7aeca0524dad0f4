// Owns the model and time: play / pause / single step / reset, the pace (automatic: as many steps as a
// share of each frame's time allows, up to the scene's watchable rate; or a fixed, signed number of steps
// per frame), the direction of time, a frame timer, the heat / cool control, blow-up handling, and the
// time-series store the plots read. Views only read from it; every edit of
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
    // The largest fixed pace: a fast machine's automatic pace in the lightest scenes stays below it.
    static constexpr int kMaxStepsPerFrame = 1000;
    // Automatic pace: the model steps for at most this much of each frame [ms] (half of a 60 Hz frame),
    // so the viewport and the plots keep the rest; less where frames are missed (a slow paint, another
    // program on the cores).
    static constexpr double kStepShareOfFrameMs = 8.3;
    // Full Heat (or Cool) at the scene's watchable pace changes kT by a factor 2 in this many seconds of
    // wall time; the rate itself is per simulated time (heatRatePerTime()).
    static constexpr double kHeatDoublingSeconds = 4.0;

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
    // The pace. Automatic (the default of every scene): each frame steps for up to kStepShareOfFrameMs,
    // never faster than the scene's watchable rate (ModelDescriptor::watchableRate). Fixed: |n| steps a
    // frame. Both run in direction() (−1: time backwards, where the scene is reversible).
    bool automaticPace() const { return automatic_; }
    int direction() const { return direction_; }
    // Signed steps per frame: the fixed number, or in automatic pace the last frame's steps (0 until the
    // first frame ran).
    int stepsPerFrame() const { return automatic_ ? direction_ * lastFrameSteps_ : direction_ * fixedSteps_; }
    double stepsPerSecond() const { return stepsPerSecond_; }
    // Simulated time per second of wall time, measured [the kind's time unit / s].
    double simulatedPerSecond() const { return simulatedPerSecond_; }
    // The scene's watchable rate [time unit / s] and the time unit, from its registration.
    double watchableRate() const;
    QString timeUnit() const;
    // Relative change of kT per simulated time at full Heat [1 / time unit]: ln 2 over kHeatDoublingSeconds
    // of the watchable rate's simulated time, so the gas warms as much per simulated second at any pace.
    double heatRatePerTime() const;

    // Calls atStep after every step whose count is a multiple of `every` (0: none), before the frame is
    // shown: a recording's frames are states after a fixed number of steps, whatever the frame rate.
    // At the automatic pace a frame takes no more steps once `ready` says the watcher cannot take a state
    // without waiting (an encoder behind): the frame is shown on time and the encoder catches up in the
    // time it leaves, rather than the window's thread waiting inside the step loop.
    void watchSteps(int every, std::function<void()> atStep, std::function<bool()> ready = {});

    // Applies parameter values (all or nothing). Returns the error naming the key, or empty.
    QString setParameters(const ParamValues& values);
    // Parameters changed since the last reset that only a reset applies. The model keeps the values its
    // state was built with until then (SimulationParameters.cpp).
    const ParamValues& pendingUntilReset() const { return pending_; }
    // The values the user set: the model's, with those that wait for Reset. What the panel shows.
    ParamValues parameterValues() const;
    // The experiment as set up: the model's preset with the values that wait for Reset (saved, rebuilt).
    Preset experimentPreset() const;
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
    // A fixed pace: |n| ≤ kMaxStepsPerFrame steps per frame, the sign chooses the direction of time
    // (0: time stands while running).
    void setStepsPerFrame(int n);
    // The automatic pace, in the present direction of time.
    void setAutomaticPace();
    // Runs time the other way, keeping the pace (refused, with a notice, where the scene is not reversible).
    void reverse();
    // −1 (cool) … 1 (heat), proportional: kT changes by exp(rate × heatRatePerTime() × simulated time)
    // while it is non-zero.
    void setHeatRate(double rate);
    // Advances one frame's worth of steps and notifies views (the timer calls it; tests may too).
    void advanceFrame();
    // Appends one row of the model's observables to the series store.
    void sample();
    // The viewport showed a frame: the automatic pace measures the time between frames shown and gives
    // the steps less of a frame where frames are missed.
    void frameShown();

signals:
    void modelReplaced();
    void frameAdvanced();
    void runningChanged(bool running);
    void failed(const QString& message);
    void edited();
    void parametersChanged();
    void paceChanged();                  // automatic or fixed, the fixed number or the direction
    void notice(const QString& message); // one line for the status bar

private:
    void applyDirection(); // direction_ as the model's direction of time
    int stepsThisFrame();  // the pace's steps for the frame about to run
    void noteFrameCost(int steps, qint64 nanoseconds);
    // The model's tools when the user may edit them now.
    SceneTools* editableTools();
    void restartSeries();
    // After a tool put a body down: tells how many particles it left no room for (particleCount() before).
    void noteBodyPutDown(std::size_t particlesBefore);
    bool runComplete() const; // the model's planned run length is reached
    void stepModel();         // one step, and the step watch

    std::unique_ptr<Model> model_;
    gl::Backend backend_ = gl::Backend::Auto;
    SeriesStore series_;
    ParamValues pending_;
    ParamValues applied_;  // the values the state was last built with (load, reset)
    QString importedFrom_; // empty while the model is ours to run
    QTimer timer_;
    bool automatic_ = true;
    int direction_ = 1;
    int fixedSteps_ = 5;
    int lastFrameSteps_ = 0;
    double heatRate_ = 0.0;
    double stepsPerSecond_ = 0.0;
    double simulatedPerSecond_ = 0.0;
    int framesSinceSample_ = 0;
    QElapsedTimer rateClock_;
    long long stepsSinceClock_ = 0;
    int watchEvery_ = 0;
    std::function<void()> watch_;
    std::function<bool()> watchReady_;
    double simulatedSinceClock_ = 0.0;
    // Automatic pace: the wall clock between frames, the simulated time the watchable rate still allows,
    // and the measured cost of one step [ns] (0 until measured).
    QElapsedTimer frameClock_;
    double allowance_ = 0.0;
    double nanosecondsPerStep_ = 0.0;
    double stepBudgetMs_ = kStepShareOfFrameMs;
    QElapsedTimer shownClock_; // between frames shown while running
    // The parameters changed last since the state was built ("Stiffness k (to 1e+12)"): a blow-up's
    // message names them, as the likely cause, rather than always the time step.
    QString lastChange_;
};

} // namespace pl::ui
