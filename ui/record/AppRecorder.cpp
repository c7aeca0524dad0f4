// AppRecorder: the scene is copied in the window's thread right after the step (a SceneView, O(N)), and
// a chosen plot is drawn there too (QCustomPlot belongs to that thread); composing and encoding follow on
// the worker. A new experiment, a failure or a write error end the clip; Stop drains the queue on a
// thread of its own so the window stays live while the last frames are encoded.
#include "AppRecorder.h"

#include <qcustomplot.h> // before SeriesPlot.h, which names QCPAxis

#include "ClipWriter.h"
#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "plots/SeriesPlotSpecs.h"

#include <algorithm>
#include <cmath>

namespace pl::ui {

namespace {
constexpr int kDrainPollMs = 100;             // how often the draining progress is reported
constexpr double kBytesPerSceneParticle = 16; // SceneView: x, y, radius, value as floats
} // namespace

int watchableStepsPerFrame(double watchableRate, double dt, int fps) {
    if (!(watchableRate > 0) || !(dt > 0) || fps < 1) return kAppStepsPerClipFrame;
    const double steps = std::round(watchableRate / (dt * fps));
    return static_cast<int>(std::clamp(steps, 1.0, static_cast<double>(kMaxStepsPerClipFrame)));
}

int watchableStepsPerFrame(const SimulationController& controller, int fps) {
    return watchableStepsPerFrame(controller.watchableRate(), stepTime(controller), fps);
}

double stepTime(const SimulationController& controller) {
    const Model* model = controller.model();
    if (!model) return 0.0;
    const ParamValues params = model->params();
    const auto dt = params.find("dt");
    return dt != params.end() && std::holds_alternative<double>(dt->second)
               ? std::abs(std::get<double>(dt->second))
               : 0.0;
}

AppRecorder::AppRecorder(SimulationController* controller, QObject* parent)
    : QObject(parent), controller_(controller) {
    connect(controller, &SimulationController::modelReplaced, this, [this] {
        if (isRecording()) end(tr("the experiment was replaced"));
    });
    connect(controller, &SimulationController::failed, this, [this](const QString&) {
        if (isRecording()) end(tr("the model stopped"));
    });
    drainPoll_.setInterval(kDrainPollMs);
    connect(&drainPoll_, &QTimer::timeout, this, [this] {
        if (draining_ && writer_) emit draining(writer_->framesQueued(), queuedAtStop_);
    });
}

AppRecorder::~AppRecorder() {
    finishNow();
}

QString AppRecorder::start(const QString& path, const QString& title, const AppClipOptions& options) {
    const Model* model = controller_->model();
    if (draining_) return tr("The previous clip is still being finished.");
    if (!model || isRecording()) return tr("Nothing to record.");
    options_ = options;
    if (options_.stepsPerFrame < 1)
        options_.stepsPerFrame = watchableStepsPerFrame(*controller_, options.fps);
    look_ = ClipLook{};
    look_.size = options.size;
    look_.fps = options.fps;
    look_.captions = options.captions;
    look_.title = title;
    look_.timeUnit = controller_->timeUnit();
    plot_.reset();
    if (!options.plot.isEmpty()) {
        const QString kind = QString::fromStdString(model->kind());
        for (const SeriesPlotSpec& spec : seriesPlotSpecs())
            if (spec.objectName == options.plot && spec.kinds.contains(kind)) {
                plot_ = std::make_unique<SeriesPlot>(controller_, spec);
                plot_->setAttribute(Qt::WA_DontShowOnScreen); // refreshed as a shown dock, no window
                plot_->resize(plotPicture(plot_->plot(), options.size).size());
                plot_->show();
            }
        if (!plot_) return tr("The scene has no plot '%1'.").arg(options.plot);
    }
    try {
        writer_ = std::make_unique<ClipWriter>(
            path.toStdString(), options.size.width(), options.size.height(), options.fps,
            colourScaleHints(model->sceneView()), queueLimit(), EncoderShare::BesideLiveScene);
    } catch (const VideoError& e) {
        plot_.reset();
        return QString::fromStdString(e.what());
    }
    path_ = path;
    problem_.clear();
    frames_ = 0;
    capture(); // the first frame: the state as it is now
    controller_->watchSteps(
        options_.stepsPerFrame, [this] { capture(); }, [this] { return !writer_ || writer_->hasRoom(); });
    emit recordingChanged(true);
    return {};
}

// Frames a few seconds of clip long, fewer where one frame's scene (and plot) is large.
std::size_t AppRecorder::queueLimit() const {
    const SceneView scene = controller_->model()->sceneView();
    double bytes = kBytesPerSceneParticle * static_cast<double>(scene.size());
    if (scene.field) bytes += sizeof(float) * static_cast<double>(scene.field->value.size());
    if (plot_) bytes += 4.0 * kClipPlotShare * options_.size.width() * options_.size.height();
    const double fitting = kAppQueueBytes / std::max(bytes, 1.0);
    const double wanted = static_cast<double>(kAppQueueSeconds) * options_.fps;
    return static_cast<std::size_t>(std::clamp(fitting, static_cast<double>(kClipQueueFrames), wanted));
}

void AppRecorder::capture() {
    if (!writer_ || draining_) return;
    const Model* model = controller_->model();
    ClipLook look = look_;
    if (plot_) look.plotImage = plotPicture(plot_->plot(), look.size);
    try {
        writer_->writeDrawn([look = std::move(look), scene = model->sceneView(), time = model->time(),
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
    problem_ = problem;
    draining_ = true;
    queuedAtStop_ = writer_->framesQueued();
    emit recordingChanged(false);
    if (queuedAtStop_ > 0) {
        emit draining(queuedAtStop_, queuedAtStop_);
        drainPoll_.start();
    }
    // The encoder's own delay (x264's look-ahead) is flushed there too, away from the window's thread.
    finisher_ = std::thread([this] {
        try {
            writer_->finish();
        } catch (const VideoError& e) {
            const QString error = QString::fromStdString(e.what());
            QMetaObject::invokeMethod(
                this,
                [this, error] {
                    if (problem_.isEmpty()) problem_ = error;
                },
                Qt::QueuedConnection);
        }
        QMetaObject::invokeMethod(
            this, [this] { drained(); }, Qt::QueuedConnection);
    });
}

void AppRecorder::cancelDraining() {
    if (draining_ && writer_) writer_->dropQueued();
}

void AppRecorder::finishNow() {
    if (isRecording()) {
        controller_->watchSteps(0, {});
        draining_ = true;
        finisher_ = std::thread([this] {
            try {
                writer_->finish();
            } catch (const VideoError&) { // the clip keeps what reached it; nobody is left to tell
            }
        });
    }
    if (finisher_.joinable()) finisher_.join();
    writer_.reset();
    plot_.reset();
    draining_ = false;
    drainPoll_.stop();
}

void AppRecorder::drained() {
    if (!writer_) return; // finishNow() came first
    if (finisher_.joinable()) finisher_.join();
    drainPoll_.stop();
    const long long written = encoded_ = writer_->framesWritten();
    const bool cancelled = written < frames_ && problem_.isEmpty();
    writer_.reset();
    plot_.reset();
    draining_ = false;
    const QString summary =
        tr("%1 (%2 s of clip)")
            .arg(path_, QString::number(static_cast<double>(written) / options_.fps, 'f', 1));
    if (!problem_.isEmpty())
        emit finished(tr("The clip ended early (%1); saved %2").arg(problem_, summary));
    else if (cancelled)
        emit finished(tr("Encoding cancelled; saved the frames encoded, %1").arg(summary));
    else
        emit finished(tr("Clip saved, %1").arg(summary));
}

} // namespace pl::ui
