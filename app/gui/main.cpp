// particlelab: the desktop application. Usage: particlelab [PRESET|FILE] (default gas-seed).
#include "MainWindow.h"
#include "SimulationController.h"

#include <QApplication>
#include <QCommandLineParser>

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setApplicationName("ParticleLab");
    QApplication::setOrganizationName("ParticleLab");
    QCommandLineParser parser;
    parser.setApplicationDescription("ParticleLab: an interactive physics lab of particles");
    parser.addHelpOption();
    parser.addPositionalArgument("preset", "Built-in preset name or preset file (default: gas-seed)");
    parser.process(app);
    const QStringList args = parser.positionalArguments();

    pl::ui::MainWindow window;
    if (!window.openPreset(args.isEmpty() ? QStringLiteral("gas-seed") : args.first())) return 2;
    window.resize(1280, 800);
    window.show();
    window.controller()->play();
    return QApplication::exec();
}
