// The desktop window under a real X server: loads presets, runs frames forwards and backwards, keeps the
// running experiment on a bad preset, and saves a screenshot someone can look at.
#include "MainWindow.h"
#include "SimulationController.h"
#include "SpeedHistogramPlot.h"
#include "md/MdModel.h"

#include <QDir>
#include <QMessageBox>
#include <QTimer>
#include <QtTest>
#include <qcustomplot.h>

using namespace pl;

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void runsTheClassroomGasAndSavesAScreenshot() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* controller = window.controller();
        for (int frame = 0; frame < 400; ++frame) controller->advanceFrame();
        QCOMPARE(controller->model()->stepCount(), 400LL * controller->stepsPerFrame());
        window.histogram()->refresh();
        QTest::qWait(100); // let the queued replot and repaints run, as the event loop does for a user
        QVERIFY(window.histogram()->plot()->plottableCount() >= 1);
        QVERIFY(window.histogram()->plot()->graph(0)->dataCount() > 100); // the Maxwell–Boltzmann curve

        QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
        const QImage shot = window.grab().toImage();
        QVERIFY(shot.save(QString(PARTICLELAB_SCREENSHOT_DIR) + "/mainwindow-gas-classroom.png"));
        // Not a blank window: the view holds many colours of the thermal palette.
        QSet<QRgb> colours;
        for (int y = 0; y < shot.height(); y += 4)
            for (int x = 0; x < shot.width(); x += 4) colours.insert(shot.pixel(x, y));
        QVERIFY(colours.size() > 50);
    }

    void negativeSpeedRunsTimeBackwards() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-seed"));
        auto* controller = window.controller();
        const MdState start = static_cast<const MdModel*>(controller->model())->state();
        controller->setStepsPerFrame(5);
        for (int frame = 0; frame < 20; ++frame) controller->advanceFrame();
        controller->setStepsPerFrame(-5);
        for (int frame = 0; frame < 20; ++frame) controller->advanceFrame();
        const MdState& back = static_cast<const MdModel*>(controller->model())->state();
        std::map<std::uint32_t, double> startX; // large gases are kept in spatial order: match by id
        for (std::size_t i = 0; i < start.size(); ++i) startX[start.id[i]] = start.x[i];
        double worst = 0;
        for (std::size_t i = 0; i < back.size(); ++i)
            worst = std::max(worst, std::abs(back.x[i] - startX.at(back.id[i])));
        QVERIFY(worst < 1e-12);
        QVERIFY(std::abs(controller->model()->time()) < 1e-12);
    }

    void badPresetKeepsTheRunningExperiment() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        window.controller()->advanceFrame();
        const auto* before = window.controller()->model();
        // Dismiss the error dialog as soon as it appears.
        QTimer::singleShot(0, [] {
            for (QWidget* w : QApplication::topLevelWidgets())
                if (auto* box = qobject_cast<QMessageBox*>(w)) box->accept();
        });
        QVERIFY(!window.openPreset("/nonexistent/preset.json"));
        QCOMPARE(window.controller()->model(), before);
        QCOMPARE(window.controller()->model()->stepCount(), 5LL);
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
