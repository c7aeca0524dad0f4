// Recording in the app: Record starts a clip of the running scene, Stop finishes it. A frame is taken
// after every `stepsPerFrame` steps inside the controller's stepping (SimulationController::watchSteps),
// never per shown frame, so the clip shows simulated time evenly whatever the frame rate; the frame is
// drawn and encoded on the clip's worker thread (ClipWriter) while the scene stays live. Frames the
// encoder has not caught up with wait in a queue of a few seconds; Stop encodes them in the background
// (draining) and Cancel drops them, finishing the clip with what was encoded.
#pragma once

#include "ClipFrames.h"

#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <thread>

namespace pl::ui {

class ClipWriter;
class SeriesPlot;
class SimulationController;

inline constexpr int kAppStepsPerClipFrame = 10; // as the CLI's --steps-per-frame; where no pace is known
inline constexpr int kAppClipFps = 30;
inline constexpr QSize kAppClipSize{1280, 720};
// The most the queue of frames waiting for the encoder may hold, in seconds of clip and in bytes: a
// burst of slow encoding never stalls the scene, and a huge scene never fills the memory.
inline constexpr int kAppQueueSeconds = 4;
inline constexpr int kMaxStepsPerClipFrame = 100000;
inline constexpr double kAppQueueBytes = 512.0 * 1024 * 1024;

// The steps between two frames that show `watchableRate` simulated time per second of clip [time unit/s]
// at `fps` with a step of `dt` [time unit]; at least 1. kAppStepsPerClipFrame where the rate is unknown.
int watchableStepsPerFrame(double watchableRate, double dt, int fps);
// The same for the controller's scene (its kind's watchable rate and |dt|).
int watchableStepsPerFrame(const SimulationController& controller, int fps);
// |dt| of the controller's scene [its unit of time]; 0 without a model.
double stepTime(const SimulationController& controller);

// What the Record dialog chose (RecordDialog.h); the size and frame rate are the CLI's defaults.
struct AppClipOptions {
    QSize size = kAppClipSize; // [px]
    int fps = kAppClipFps;     // [frames/s]
    // Model steps between two frames; 0: the scene's watchable pace at this frame rate (as the dialog
    // offers), so that a clip frame is rarely wanted faster than the encoder can take it.
    int stepsPerFrame = 0;
    bool captions = true; // the title and the time readout
    QString plot;         // a plot's object name ("energyPlot") beside the scene; empty: none
};

class AppRecorder : public QObject {
    Q_OBJECT
public:
    explicit AppRecorder(SimulationController* controller, QObject* parent = nullptr);
    ~AppRecorder() override;

    // Starts a clip at path (format by its suffix) titled `title`. Returns why it cannot, or empty.
    QString start(const QString& path, const QString& title, const AppClipOptions& options = {});
    // Stops taking frames. The frames still queued are encoded in the background (draining(), then
    // finished()); with none queued the clip is finished at once.
    void stop();
    // Drops the frames still queued: the clip ends with those encoded (a playable file).
    void cancelDraining();
    // Stops and waits until the clip is finished (closing the window, a new experiment).
    void finishNow();
    bool isRecording() const { return writer_ != nullptr && !draining_; }
    bool isDraining() const { return draining_; }
    long long frames() const { return frames_; }            // taken
    long long framesInLastClip() const { return encoded_; } // in the file, once finished() was sent
    double seconds() const { return static_cast<double>(frames_) / options_.fps; } // clip length so far
    const AppClipOptions& options() const { return options_; }

signals:
    void recordingChanged(bool recording);
    void progressed(double seconds);              // after each frame taken
    void draining(long long left, long long all); // frames still to encode after Stop, of those queued then
    void finished(const QString& sentence);       // what was written, or why the clip ended early

private:
    void capture();
    void end(const QString& problem);
    void drained();
    std::size_t queueLimit() const;

    SimulationController* controller_;
    std::unique_ptr<ClipWriter> writer_;
    std::unique_ptr<SeriesPlot> plot_; // hidden: the docks stay as they are
    ClipLook look_;
    AppClipOptions options_;
    QString path_;
    QString problem_; // why the clip ends early, kept while it drains
    long long frames_ = 0;
    long long queuedAtStop_ = 0;
    long long encoded_ = 0;
    bool draining_ = false;
    QTimer drainPoll_;
    std::thread finisher_; // finishes the container off the window's thread
};

} // namespace pl::ui
