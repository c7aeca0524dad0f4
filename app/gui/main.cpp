// particlelab: the desktop application.
// Usage: particlelab [PRESET|FILE] [--backend cpu|gl|auto] [--screenshot FILE [--frames N]]
//                    [--measure-fps SECONDS] [--record CLIP] [--present]
//        particlelab --lab PAGE --plot FILE [--csv FILE]   (a methods-lab page, no window)
//        particlelab --help | --version                    (answered without a display)
#include "Autosave.h"
#include "ExperimentDocument.h"
#include "FrameProfile.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "common/ThreadGovernor.h"
#include "i18n/Translations.h"
#include "methods/LabBatch.h"
#include "present/PresentMode.h"
#include "record/AppRecorder.h"
#include "viewport/ViewportCore.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QTimer>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <unistd.h>

namespace {

// The desktop app shares its cores with the display: the GL rasteriser (on a machine without a GPU),
// the X server, the compositor. OpenMP workers that spin at a barrier for up to milliseconds before they
// sleep (libgomp's default, 300 000 spins) starve them, and a worker the scheduler sets aside stalls
// every step. Spinning 3000 times (tens of µs) still catches the barriers inside a step, then sleeps
// (BENCHMARKS.md, "App frame rate": gas-write-up 59–62 fps against 35 by default on an idle machine, 32
// against 9 beside two busy processes). libgomp reads GOMP_SPINCOUNT and OMP_WAIT_POLICY once, when it
// loads, before main: unless the user set either, the process starts itself again with the spin count
// set (same pid, same arguments).
void spinOpenMpWorkersBriefly(char** argv) {
#ifdef __linux__
    if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
    // The binary's own path rather than /proc/self/exe, so the process keeps its name ("exe" otherwise).
    char path[4096];
    const ssize_t length = readlink("/proc/self/exe", path, sizeof path - 1);
    if (length <= 0) return;
    path[length] = '\0';
    setenv("GOMP_SPINCOUNT", "3000", 1);
    execv(path, argv); // returns only on failure: then go on with the default policy
#else
    (void)argv;
#endif
}

// The viewport asks for a frame after each tick's steps (QWindow::requestUpdate), which Qt answers after
// an idle timer of 5 ms by default. A tick whose steps take 10 ms then leaves no room for the paint and
// the swap before the next tick, and a frame holds two ticks (BENCHMARKS.md, "fluid-obstacle's frame";
// without the idle time fluid-obstacle drew 31–41 fps against 30–33, "Frames right after the steps").
// Only windows that paint through requestUpdate see it (the viewport); widgets repaint through their own
// posted events. Unless the user set it.
void drawFramesRightAfterTheSteps() {
    if (!qEnvironmentVariableIsSet("QT_QPA_UPDATE_IDLE_TIME")) qputenv("QT_QPA_UPDATE_IDLE_TIME", "0");
}

// The program's options, described once: --help, the man page (help2man reads --help) and main() use them.
struct CommandLine {
    const QCommandLineOption screenshot{"screenshot",
                                        "Run --frames frames, save the window as a PNG and quit.", "file"};
    const QCommandLineOption frames{"frames", "Frames to run before --screenshot (default 300).", "count",
                                    "300"};
    const QCommandLineOption measureFps{
        "measure-fps", "Run for this many seconds as a user would, print the frame rate and quit.",
        "seconds"};
    const QCommandLineOption record{
        "record",
        "Record the run as Simulation > Record clip does, to this file (MP4, WebM "
        "or GIF by its suffix); with --measure-fps until it quits.",
        "file"};
    const QCommandLineOption present{
        "present", "Open in present mode: full screen, the viewport, one plot and a lesson's controls."};
    const QCommandLineOption backend{"backend", "Compute backend: cpu, gl or auto (default: as last chosen).",
                                     "name"};
    const QCommandLineOption lab{"lab",
                                 "Run a methods-lab page (" + pl::ui::labPageNames().join(", ") +
                                     ") without a window, save its plot to --plot (PNG, SVG or PDF) and "
                                     "quit; needs no display.",
                                 "page"};
    const QCommandLineOption plotFile{"plot", "Image file of --lab's plot.", "file"};
    const QCommandLineOption csvFile{"csv", "CSV file of --lab's plot data.", "file"};

    void describe(QCommandLineParser& parser) const {
        parser.setApplicationDescription("ParticleLab: an interactive physics lab of particles");
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addPositionalArgument(
            "preset",
            "Built-in preset name, experiment (.particlelab, .json) or snapshot (.plsnap) file "
            "(default: gas-write-up)",
            "[preset]");
        for (const QCommandLineOption* option :
             {&lab, &plotFile, &csvFile, &backend, &screenshot, &frames, &measureFps, &record, &present})
            parser.addOption(*option);
    }
};

bool environmentHas(const char* name) {
    const char* value = std::getenv(name);
    return value && *value;
}

// What needs no window is answered before the QApplication, whose platform plugin aborts the process when
// it finds no display: --version, --help (by a core application, which needs none) and the refusal of a
// window without a display. A methods-lab page draws no window: without a display it uses Qt's offscreen
// platform. Returns the exit code where the program is done.
std::optional<int> answerWithoutDisplay(int argc, char** argv) {
    bool help = false, helpAll = false, version = false, lab = false, platformChosen = false;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--") break; // what follows is a file name
        help = help || arg == "-h" || arg == "-?" || arg == "--help";
        helpAll = helpAll || arg == "--help-all";
        version = version || arg == "-v" || arg == "--version";
        lab = lab || arg == "--lab" || arg.starts_with("--lab=");
        platformChosen = platformChosen || arg.starts_with("-platform") || arg.starts_with("--platform");
    }
    const bool display = environmentHas("DISPLAY") || environmentHas("WAYLAND_DISPLAY") ||
                         environmentHas("QT_QPA_PLATFORM") || platformChosen;
    if (version) {
        std::printf("particlelab %s\n", PARTICLELAB_VERSION);
        return 0;
    }
    // --help-all adds the options of Qt's GUI (-platform, -style, …), which only the QApplication knows.
    if (help || (helpAll && !display)) {
        QCoreApplication app(argc, argv);
        QCommandLineParser parser;
        const CommandLine options;
        options.describe(parser);
        (void)parser.parse(QCoreApplication::arguments()); // help is shown whatever else the line holds
        parser.showHelp(0);                                // exits
    }
    if (display) return std::nullopt;
    if (lab) {
        setenv("QT_QPA_PLATFORM", "offscreen", 1);
        return std::nullopt;
    }
    std::fprintf(stderr, "particlelab: there is no display to open the window on (neither DISPLAY nor "
                         "WAYLAND_DISPLAY is set): start it in a desktop session, or use particlelab-cli "
                         "to run experiments without a window.\n");
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    spinOpenMpWorkersBriefly(argv);
    if (const std::optional<int> exitCode = answerWithoutDisplay(argc, argv)) return *exitCode;
    // The scene steps on the team of threads it measures fastest: one, where another program holds a
    // core (ThreadGovernor.h).
    pl::setThreadPolicy(pl::adaptiveUnlessUserFixed());
    drawFramesRightAfterTheSteps();
    // The GPU models' context shares buffers with the viewports (ui/viewport/QtGlContext.h).
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    QApplication::setApplicationName("ParticleLab");
    QApplication::setOrganizationName("ParticleLab");
    QApplication::setDesktopFileName("particlelab");
    QApplication::setWindowIcon(QIcon::fromTheme("particlelab", QIcon(":/icons/particlelab.svg")));
    pl::ui::installLanguage(pl::ui::savedLanguage()); // before any widget is made: they translate once
    QApplication::setApplicationVersion(PARTICLELAB_VERSION);
    QCommandLineParser parser;
    const CommandLine options;
    options.describe(parser);
    parser.process(app);
    const QStringList args = parser.positionalArguments();
    if (parser.isSet(options.lab)) {
        if (!parser.isSet(options.plotFile)) {
            std::fprintf(stderr, "particlelab: --lab needs --plot FILE\n");
            return 2;
        }
        const QString error = pl::ui::runLabPage(parser.value(options.lab), parser.value(options.plotFile),
                                                 parser.value(options.csvFile));
        if (!error.isEmpty()) std::fprintf(stderr, "particlelab: %s\n", qPrintable(error));
        return error.isEmpty() ? 0 : (error.startsWith("unknown page") ? 2 : 4);
    }

    pl::ui::MainWindow window;
    if (parser.isSet(options.backend)) {
        try {
            window.controller()->setBackend(
                pl::gl::backendFromName(parser.value(options.backend).toStdString()));
        } catch (const std::invalid_argument& e) {
            std::fprintf(stderr, "particlelab: %s\n", e.what());
            return 2;
        }
    }
    if (!window.document()->open(args.isEmpty() ? QStringLiteral("gas-write-up") : args.first(), true))
        return 2;
    window.show(); // at the size it had last time, or one that fits the screen (MainWindow::readSettings)
    if (!parser.isSet(options.screenshot) && !parser.isSet(options.measureFps))
        window.autosave()->offerRestore();
    if (parser.isSet(options.present)) window.presentMode()->setActive(true);
    if (parser.isSet(options.screenshot)) {
        for (int f = 0; f < parser.value(options.frames).toInt(); ++f) window.controller()->advanceFrame();
        QApplication::processEvents(); // let queued plot replots and repaints run
        const bool saved = window.windowImage().save(parser.value(options.screenshot));
        if (!saved)
            std::fprintf(stderr, "particlelab: cannot write %s\n",
                         qPrintable(parser.value(options.screenshot)));
        return saved ? 0 : 4;
    }
    if (parser.isSet(options.record)) {
        const QString problem =
            window.recorder()->start(parser.value(options.record), window.document()->title());
        if (!problem.isEmpty()) {
            std::fprintf(stderr, "particlelab: %s\n", qPrintable(problem));
            return 2;
        }
    }
    window.controller()->play();
    if (parser.isSet(options.measureFps)) {
        // Frames actually drawn by the viewport while the simulation runs at its normal frame timer.
        QElapsedTimer clock; // lives until exec() returns, after the measurement
        clock.start();
        pl::ui::FrameProfile::instance().setEnabled(true);
        const long long startStep = window.controller()->model()->stepCount();
        // A preset with a run length stops before the measurement ends: its rate is the one while it ran
        // (the viewport's last whole second, or 0 where it ran less than one), and the line says it stopped.
        struct Stop {
            bool stopped = false;
            double seconds = 0;
            std::size_t frames = 0;
            long long steps = 0;
        } stop;
        QObject::connect(
            window.controller(), &pl::ui::SimulationController::runningChanged, &app, [&](bool running) {
                if (running || stop.stopped) return;
                stop = {true, clock.elapsed() / 1000.0, pl::ui::FrameProfile::instance().frames(),
                        window.controller()->model()->stepCount()};
            });
        QTimer::singleShot(static_cast<int>(1000 * parser.value(options.measureFps).toDouble()), &app, [&] {
            const double seconds = stop.stopped ? stop.seconds : clock.elapsed() / 1000.0;
            const double fps = stop.stopped ? (seconds > 0 ? static_cast<double>(stop.frames) / seconds : 0.0)
                                            : window.viewportCore()->framesPerSecond();
            const long long steps =
                (stop.stopped ? stop.steps : window.controller()->model()->stepCount()) - startStep;
            const long long clipFrames = window.recorder()->frames();
            window.recorder()->stop();
            std::printf("{\"preset\": \"%s\", \"seconds\": %.2f, \"fps\": %.1f, \"steps_per_second\": %.0f, "
                        "\"stopped\": %s, \"clip_frames\": %lld, \"frame_parts\": %s}\n",
                        qPrintable(window.document()->title()), seconds, fps,
                        seconds > 0 ? static_cast<double>(steps) / seconds : 0.0,
                        stop.stopped ? "true" : "false", clipFrames,
                        qPrintable(pl::ui::FrameProfile::instance().report()));
            std::fflush(stdout);
            window.document()->setModified(false);
            // A clip still encoding its queued frames is finished before the window goes.
            if (window.recorder()->isDraining())
                QObject::connect(window.recorder(), &pl::ui::AppRecorder::finished, &app,
                                 &QApplication::quit);
            else
                QApplication::quit();
        });
    }
    return QApplication::exec();
}
