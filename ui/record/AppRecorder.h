// Recording in the app: Record starts a clip of the running scene, Stop finishes it. A frame is taken
// after every kAppStepsPerClipFrame steps inside the controller's stepping (SimulationController::
// watchSteps), never per shown frame, so the clip shows simulated time evenly whatever the frame rate;
// the frame is drawn and encoded on the clip's worker thread (ClipWriter) while the scene stays live.
#pragma once

#include "ClipFrames.h"

#include <QObject>
#include <QString>
#include <memory>

namespace pl::ui {

class ClipWriter;
class SimulationController;

inline constexpr int kAppStepsPerClipFrame = 10; // as the CLI's --steps-per-frame: the app's pace
inline constexpr int kAppClipFps = 30;
inline constexpr QSize kAppClipSize{1280, 720};

class AppRecorder : public QObject {
    Q_OBJECT
public:
    explicit AppRecorder(SimulationController* controller, QObject* parent = nullptr);
    ~AppRecorder() override;

    // Starts a clip at path (format by its suffix) titled `title`. Returns why it cannot, or empty.
    QString start(const QString& path, const QString& title);
    // Finishes the clip (its queued frames are encoded first, at most a few).
    void stop();
    bool isRecording() const { return writer_ != nullptr; }
    long long frames() const { return frames_; }
    double seconds() const { return static_cast<double>(frames_) / kAppClipFps; } // clip length so far

signals:
    void recordingChanged(bool recording);
    void progressed(double seconds);        // after each frame taken
    void finished(const QString& sentence); // what was written, or why the clip ended early

private:
    void capture();
    void end(const QString& problem);

    SimulationController* controller_;
    std::unique_ptr<ClipWriter> writer_;
    ClipLook look_;
    QString path_;
    long long frames_ = 0;
};

} // namespace pl::ui
