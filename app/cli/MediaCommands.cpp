// MediaCommands: the experiment is built as `run` builds it, stepped in whole frames of steps, each
// frame drawn by the viewport's painter into an image (Qt's offscreen platform: no display, no OpenGL
// window) and handed to the encoder. Everything the options can get wrong is refused before the file
// is opened.
#include "MediaCommands.h"

#include "Commands.h"
#include "OptionChecks.h"
#include "RunSupport.h"

#include <qcustomplot.h> // before SeriesPlot.h, which names QCPAxis

#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "common/StopRequest.h"
#include "plots/SeriesPlot.h"
#include "plots/SeriesPlotSpecs.h"
#include "record/ClipFrames.h"
#include "record/ClipWriter.h"
#include "report/LabReport.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace pl::cli {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Without --steps or a preset's run length, a report runs what a class watches in this many seconds at
// the kind's watchable pace (its registration's watchableRate), and at least kReportFewestSteps: the state
// its description promises "within seconds" (gas-classroom's Maxwell–Boltzmann speeds; 1000 steps, 0.175 T,
// were too few).
constexpr double kReportWatchedSeconds = 4.0;
constexpr long long kReportFewestSteps = 1000;
constexpr long long kReportSamples = 400; // rows of the report's plots over the run

std::string timeUnitOf(const std::string& kind) {
    if (const ModelDescriptor* model = findModel(kind))
        for (const SeriesColumn& column : model->series)
            if (column.name == "time") return column.unit;
    return {};
}

// The names of a kind's plots, for the refusal of an unknown --plot.
std::string plotNames(const std::string& kind) {
    std::string names;
    if (const ModelDescriptor* model = findModel(kind))
        for (const PlotSpec& plot : model->plots) names += (names.empty() ? "" : ", ") + plot.name;
    return names;
}

const ui::SeriesPlotSpec* plotSpec(const std::string& kind, const std::string& name) {
    for (const ui::SeriesPlotSpec& spec : ui::seriesPlotSpecs())
        if (spec.objectName.toStdString() == name && spec.kinds.contains(QString::fromStdString(kind)))
            return &spec;
    return nullptr;
}

// The preset as the experiment's file or built-in name has it: its name and description (a running
// model keeps neither). Read after prepare() has read it, so it cannot fail here.
Preset describedAs(const std::string& experiment) {
    try {
        return openExperiment(experiment).snapshot.preset;
    } catch (const std::exception&) {
        return {};
    }
}

// Drawing text and plots needs a Qt application; the offscreen platform needs no display (and makes
// no OpenGL window, which it cannot show).
class OffscreenApplication {
public:
    OffscreenApplication()
        : application_(
              (qInstallMessageHandler(quietPlatform), qputenv("QT_QPA_PLATFORM", "offscreen"), argc_),
              argv_) {}
    ~OffscreenApplication() { qInstallMessageHandler(nullptr); }

private:
    // The offscreen platform's notices (no window-size hints, no runtime folder) say nothing about the
    // clip or the report; everything else still reaches stderr.
    static void quietPlatform(QtMsgType type, const QMessageLogContext& context, const QString& message) {
        if (message.contains(QLatin1String("propagateSizeHints")) ||
            message.contains(QLatin1String("XDG_RUNTIME_DIR")))
            return;
        std::cerr << qPrintable(qFormatLogMessage(type, context, message)) << '\n';
    }
    int argc_ = 1;
    char name_[16] = "particlelab-cli";
    char* argv_[2] = {name_, nullptr};
    QApplication application_;
};

// A plot of the scene laid out and refreshed as a shown dock, without a window.
std::unique_ptr<ui::SeriesPlot> hiddenPlot(ui::SimulationController& controller,
                                           const ui::SeriesPlotSpec& spec, QSize size) {
    auto plot = std::make_unique<ui::SeriesPlot>(&controller, spec);
    plot->setAttribute(Qt::WA_DontShowOnScreen);
    plot->resize(size);
    plot->show();
    return plot;
}

// What both commands check before anything runs: --out is not the input and can be written, then the
// experiment builds. Returns the exit code of a refusal (its sentence printed), or 0 with `built` set.
template <class Options> int buildForOutput(const Options& options, std::unique_ptr<Model>& built) {
    if (const std::string refusal =
            sharedFileRefusal({{"--out", options.out}}, {{"the input", experimentFile(options.preset)}});
        !refusal.empty()) {
        std::cerr << "particlelab-cli: " << refusal << "\n";
        return kBadInput;
    }
    try {
        checkOutputPath(options.out);
    } catch (const FileError& e) {
        std::cerr << "particlelab-cli: " << e.what() << "\n";
        return kCannotWrite;
    }
    return prepareOrRefuse(options.preset, options.sets, options.seed, options.backend, built);
}

// --data: a folder, made here if missing, before anything runs. A file of that name is refused (exit 2),
// a folder that cannot be made or written is kCannotWrite. Returns 0 when the folder is ready (or none
// was asked for).
int dataFolderRefusal(const std::string& dataDir) {
    if (dataDir.empty()) return kOk;
    const QString path = QString::fromStdString(dataDir);
    const QFileInfo info(path);
    if (info.exists() && !info.isDir()) {
        std::cerr << "particlelab-cli: --data '" << dataDir
                  << "' is a file; name a folder for the plots' CSV files\n";
        return kBadInput;
    }
    if (!QDir().mkpath(path) || !QFileInfo(path).isWritable()) {
        std::cerr << "particlelab-cli: cannot write the plots' CSV files into --data '" << dataDir << "'\n";
        return kCannotWrite;
    }
    return kOk;
}

} // namespace

int recordClip(const RecordOptions& options) {
    StopSignals stop("particlelab-cli"); // a signal from here on ends the set-up at once, saying so
    setThreads(options.threads);
    ClipFormat format{};
    int width = 0, height = 0;
    long long frames = 0;
    if (const std::string refusal = recordOptionsRefusal(options, format, width, height, frames);
        !refusal.empty()) {
        std::cerr << "particlelab-cli: " << refusal << "\n";
        return kBadInput;
    }
    std::unique_ptr<Model> built;
    const auto setUpStart = Clock::now();
    if (const int refused = buildForOutput(options, built)) return refused;
    const double setUpSeconds = secondsSince(setUpStart);
    const std::string kind = built->kind();
    if (!options.plot.empty() && !plotSpec(kind, options.plot)) {
        std::cerr << "particlelab-cli: --plot '" << options.plot << "' is no plot of a " << kind
                  << " scene; its plots are " << plotNames(kind) << "\n";
        return kBadInput;
    }
    const Preset described = describedAs(options.preset);
    const std::string title = described.name;

    OffscreenApplication application;
    ui::SimulationController controller;
    controller.adopt(std::move(built));
    Model& model = *controller.model();
    std::unique_ptr<ui::SeriesPlot> plot;
    ui::ClipLook look;
    look.size = QSize(width, height);
    look.fps = options.fps;
    look.captions = !options.noCaptions;
    look.title = QString::fromStdString(title);
    look.timeUnit = QString::fromStdString(timeUnitOf(kind));
    if (!options.plot.empty()) {
        plot = hiddenPlot(controller, *plotSpec(kind, options.plot),
                          QSize(static_cast<int>(std::lround(ui::kClipPlotShare * width)), height));
        look.plot = plot->plot();
    }

    stop.runStarts(); // a signal from here on ends the clip after its current frame, finished
    const auto start = Clock::now();
    long long written = 0;
    std::string codec;
    int exitCode = kOk;
    try {
        ui::ClipWriter encoder(options.out, width, height, options.fps,
                               ui::colourScaleHints(model.sceneView()));
        codec = encoder.codecDescription();
        InterruptibleStepper stepper(model, setUpSeconds);
        for (long long frame = 0; frame < frames; ++frame) {
            if (frame > 0)
                for (long long s = 0; s < options.stepsPerFrame && !model.failure() && !stop.caught(); ++s)
                    stepper.step(); // a step undone by a signal leaves the last whole one to finish on
            if (stop.caught()) break;
            model.checkHealthNow();
            if (model.failure()) break; // no frame of an exploded state
            if (plot) {
                controller.sample();
                plot->refresh();
            }
            encoder.write(ui::clipFrame(look, model.sceneView(), model.time(), frame));
            written = encoder.framesWritten();
            if (!options.quiet && ::isatty(2)) std::fprintf(stderr, "\rframe %lld/%lld", frame + 1, frames);
        }
        if (!options.quiet && ::isatty(2)) std::fputc('\n', stderr);
        try {
            encoder.finish();
        } catch (...) {
            written = encoder.framesWritten();
            throw;
        }
        written = encoder.framesWritten();
    } catch (const ui::VideoError& e) {
        // The encoder holds a few frames back, and a container writes in pieces (an MP4 fragment a second):
        // what plays is what reached the file, which the number of frames encoded only bounds.
        std::cerr << "particlelab-cli: " << e.what() << "; '" << options.out
                  << "' keeps what reached it before, up to " << written << " frames\n";
        exitCode = kCannotWrite;
    } catch (const std::bad_alloc&) {
        std::cerr << "particlelab-cli: the recording ran out of memory; the " << written
                  << " frames written before are kept\n";
        exitCode = kModelFailed;
    }
    const double wall = secondsSince(start);
    if (exitCode != kOk) return exitCode;
    if (auto failure = model.failure()) {
        std::cerr << "particlelab-cli: the model stopped: " << failure->message() << "; the clip '"
                  << options.out << "' ends at its last frame before, frame " << written << "\n";
        return kModelFailed;
    }
    if (const int signal = stop.caught()) {
        std::cerr << "particlelab-cli: stopped by " << StopSignals::name(signal) << " at step "
                  << model.stepCount() << "; the clip '" << options.out << "' holds the " << written
                  << " frames written until then\n";
        return StopSignals::exitCode(signal);
    }
    if (!options.quiet)
        std::fprintf(
            stderr,
            "particlelab-cli: wrote %s: %lld frames at %d frames/s, %s; %.1f frames per wall second\n",
            options.out.c_str(), written, options.fps, codec.c_str(), wall > 0 ? written / wall : 0.0);
    return kOk;
}

namespace {

// The steps a class watches in kReportWatchedSeconds at the kind's watchable pace (simulated time per
// wall second, in the kind's unit of time), at least kReportFewestSteps.
long long watchedSteps(const Model& model) {
    const ModelDescriptor* kind = findModel(model.kind());
    const ParamValues params = model.params();
    const auto dt = params.find("dt");
    if (!kind || !(kind->watchableRate > 0) || dt == params.end() ||
        !std::holds_alternative<double>(dt->second))
        return kReportFewestSteps;
    const double steps =
        std::ceil(kReportWatchedSeconds * kind->watchableRate / std::abs(std::get<double>(dt->second)));
    return std::max(kReportFewestSteps,
                    static_cast<long long>(std::min(steps, static_cast<double>(kMaxSteps))));
}

} // namespace

int writeReport(const ReportOptions& options) {
    StopSignals stop("particlelab-cli");
    setThreads(options.threads);
    if (!ui::isReportPath(QString::fromStdString(options.out))) {
        std::cerr << "particlelab-cli: --out '" << options.out << "' needs the suffix .pdf or .html\n";
        return kBadInput;
    }
    std::unique_ptr<Model> built;
    const auto setUpStart = Clock::now();
    if (const int refused = buildForOutput(options, built)) return refused;
    if (const int refused = dataFolderRefusal(options.dataDir))
        return refused; // made once the experiment builds
    const double setUpSeconds = secondsSince(setUpStart);
    const long long planned = built->plannedSteps();
    const long long steps = options.steps.value_or(planned > 0 ? planned : watchedSteps(*built));
    const std::string kind = built->kind();
    const Preset described = describedAs(options.preset);

    OffscreenApplication application;
    ui::SimulationController controller;
    controller.adopt(std::move(built));
    Model& model = *controller.model();
    InterruptibleStepper stepper(model, setUpSeconds);
    stop.runStarts(); // a signal stops the run after its step; the report shows what was run
    const long long every = std::max(1LL, steps / kReportSamples);
    for (long long s = 1; s <= steps && !model.failure() && !stop.caught(); ++s) {
        if (!stepper.step()) break; // undone half way by a signal: the report ends at the last whole step
        if (s % every == 0 || s == steps) controller.sample();
    }
    const QString problem = ui::exportLabReport(
        controller, QString::fromStdString(described.name), QString::fromStdString(described.description),
        QString::fromStdString(options.out), QString::fromStdString(options.dataDir));
    if (!problem.isEmpty()) {
        std::cerr << "particlelab-cli: " << problem.toStdString() << "\n";
        return kCannotWrite;
    }
    if (auto failure = model.failure()) {
        std::cerr << "particlelab-cli: the model stopped: " << failure->message()
                  << "; the report shows the run until then\n";
        return kModelFailed;
    }
    if (const int signal = stop.caught()) {
        std::cerr << "particlelab-cli: stopped by " << StopSignals::name(signal) << " at step "
                  << model.stepCount() << "; the report shows the run until then\n";
        return StopSignals::exitCode(signal);
    }
    return kOk;
}

} // namespace pl::cli
