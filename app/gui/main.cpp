// particlelab: the desktop application. Usage: particlelab [PRESET|FILE] [--screenshot FILE [--frames N]].
#include "MainWindow.h"
#include "SimulationController.h"

#include <QApplication>
#include <QCommandLineParser>
#include <cstdio>

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setApplicationName("ParticleLab");
    QApplication::setOrganizationName("ParticleLab");
    QCommandLineParser parser;
    parser.setApplicationDescription("ParticleLab: an interactive physics lab of particles");
    parser.addHelpOption();
    parser.addPositionalArgument("preset", "Built-in preset name or preset file (default: gas-seed)");
    const QCommandLineOption screenshot("screenshot",
                                        "Run --frames frames, save the window as a PNG and quit.", "file");
    const QCommandLineOption frames("frames", "Frames to run before --screenshot (default 300).", "count",
                                    "300");
    parser.addOption(screenshot);
    parser.addOption(frames);
    parser.process(app);
    const QStringList args = parser.positionalArguments();

    pl::ui::MainWindow window;
    if (!window.openPreset(args.isEmpty() ? QStringLiteral("gas-seed") : args.first())) return 2;
    window.resize(1280, 800);
    window.show();
    if (parser.isSet(screenshot)) {
        for (int f = 0; f < parser.value(frames).toInt(); ++f) window.controller()->advanceFrame();
        QApplication::processEvents(); // let queued plot replots and repaints run
        const bool saved = window.grab().save(parser.value(screenshot));
        if (!saved)
            std::fprintf(stderr, "particlelab: cannot write %s\n", qPrintable(parser.value(screenshot)));
        return saved ? 0 : 4;
    }
    window.controller()->play();
    return QApplication::exec();
}
