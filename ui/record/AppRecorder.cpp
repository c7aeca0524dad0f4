// AppRecorder: the scene is copied in the window's thread right after the step (a SceneView, O(N)); the
// drawing and encoding follow on the worker. A new experiment, a failure or a write error end the clip.
#include "AppRecorder.h"

#include "ClipWriter.h"
#include "SimulationController.h"
#include "catalog/ModelCatalog.h"

namespace pl::ui {

AppRecorder::AppRecorder(SimulationController* controller, QObject* parent)
    : QObject(parent), controller_(controller) {
    connect(controller, &SimulationController::modelReplaced, this, [this] {
        if (isRecording()) end(tr("the experiment was replaced"));
    });
    connect(controller, &SimulationController::failed, this, [this](const QString&) {
        if (isRecording()) end(tr("the model stopped"));
    });
}

AppRecorder::~AppRecorder() {
    if (isRecording()) controller_->watchSteps(0, {});
}

QString AppRecorder::start(const QString& path, const QString& title) {
    const Model* model = controller_->model();
    if (!model || isRecording()) return tr("Nothing to record.");
    look_ = ClipLook{};
    look_.size = kAppClipSize;
    look_.fps = kAppClipFps;
    look_.title = title;
    if (const ModelDescriptor* kind = findModel(model->kind()))
        for (const SeriesColumn& column : kind->series)
            if (column.name == "time") look_.timeUnit = QString::fromStdString(column.unit);
    try {
        writer_ =
            std::make_unique<ClipWriter>(path.toStdString(), kAppClipSize.width(), kAppClipSize.height(),
                                         kAppClipFps, colourScaleHints(model->sceneView()));
    } catch (const VideoError& e) {
        return QString::fromStdString(e.what());
    }
    path_ = path;
    frames_ = 0;
    capture(); // the first frame: the state as it is now
    controller_->watchSteps(kAppStepsPerClipFrame, [this] { capture(); });
    emit recordingChanged(true);
    return {};
}

void AppRecorder::capture() {
    if (!writer_) return;
    const Model* model = controller_->model();
    try {
        writer_->writeDrawn([look = look_, scene = model->sceneView(), time = model->time(),
                             index = frames_] { return clipFrame(look, scene, time, index); });
    } catch (const VideoError& e) {
        end(QString::fromStdString(e.what()));
        return;
    }
    ++frames_;
    emit progressed(seconds());
}

void AppRecorder::stop() {
    if (isRecording()) end({});
}

void AppRecorder::end(const QString& problem) {
    controller_->watchSteps(0, {});
    QString error = problem;
    try {
        writer_->finish();
    } catch (const VideoError& e) {
        if (error.isEmpty()) error = QString::fromStdString(e.what());
    }
    const long long written = writer_->framesWritten();
    writer_.reset();
    emit recordingChanged(false);
    const QString summary =
        tr("%1 (%2 s of clip)")
            .arg(path_, QString::number(static_cast<double>(written) / kAppClipFps, 'f', 1));
    emit finished(error.isEmpty() ? tr("Clip saved, %1").arg(summary)
                                  : tr("The clip ended early (%1); saved %2").arg(error, summary));
}

} // namespace pl::ui
