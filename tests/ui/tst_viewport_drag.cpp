// The Drag tool through real mouse events on the viewport while time runs: the disc goes where the hand
// took it, at the tool speed, and the gas's kT hardly changes, at 1 and at 20 steps per frame; in the
// fluid write-up a drag in empty space pours; screenshots before and after the drag are saved to look at.
#include "MainWindow.h"
#include "SimulationController.h"
#include "fluid/FluidModel.h"
#include "gas/GasModel.h"
#include "viewport/ViewportCore.h"

#include <QDir>
#include <QElapsedTimer>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>

using namespace pl;

namespace {

QPoint widgetPoint(ui::MainWindow& window, double x, double y) {
    return window.viewportCore()->transform().toWidget(x, y).toPoint();
}

void saveScreenshot(ui::MainWindow& window, const QString& name) {
    QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
    window.windowImage().save(QString(PARTICLELAB_SCREENSHOT_DIR) + "/" + name + ".png");
}

// Lets the frame timer run the simulation for ms of wall time, as it does for a user.
void runFor(int ms) {
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) QTest::qWait(5);
}

} // namespace

class TestViewportDrag : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void dragAcrossTheGasKeepsItsTemperature_data() {
        QTest::addColumn<int>("stepsPerFrame");
        QTest::newRow("1 step per frame") << 1;
        QTest::newRow("20 steps per frame") << 20;
    }

    void dragAcrossTheGasKeepsItsTemperature() {
        QFETCH(int, stepsPerFrame);
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* controller = window.controller();
        auto* gas = static_cast<GasModel*>(controller->model());
        gas->addObstacle({Obstacle::Shape::Disc, -0.6, 0.0, 0.12});
        controller->setStepsPerFrame(20);
        for (int f = 0; f < 150; ++f) controller->advanceFrame(); // toward Maxwell–Boltzmann, around the disc
        controller->setStepsPerFrame(stepsPerFrame);
        QCOMPARE(controller->stepsPerFrame(), stepsPerFrame);
        const double before = gas->observe().kT;
        if (stepsPerFrame == 1) saveScreenshot(window, "drag-gas-before");

        // Half a second of wall time from x = −0.6 to 0.6, the frame timer running.
        QWidget* view = window.viewport();
        controller->play();
        QTest::mousePress(view, Qt::LeftButton, {}, widgetPoint(window, -0.6, 0.0));
        constexpr int kMoves = 25;
        for (int i = 1; i <= kMoves; ++i) {
            QTest::mouseMove(view, widgetPoint(window, -0.6 + 1.2 * i / kMoves, 0.0));
            runFor(20);
        }
        QTest::mouseRelease(view, Qt::LeftButton, {}, widgetPoint(window, 0.6, 0.0));
        QVERIFY(gas->bodiesMoving()); // far behind the hand: it moves at the tool speed
        const double lag = 0.6 - gas->obstacles()[0].x;
        QVERIFY2(lag > 0.1, qPrintable(QString::number(lag)));
        controller->pause();
        if (stepsPerFrame == 1) {
            QTest::qWait(50);
            saveScreenshot(window, "drag-gas-during"); // the disc behind the hand, its target dashed
        }

        // Then let it arrive (as fast as this machine goes) and the gas settle.
        controller->setStepsPerFrame(20);
        for (int f = 0; f < 2000 && gas->bodiesMoving(); ++f) controller->advanceFrame();
        for (int f = 0; f < 25; ++f) controller->advanceFrame();
        QVERIFY(!gas->bodiesMoving());
        QVERIFY(!gas->failure());
        QVERIFY(std::abs(gas->obstacles()[0].x - 0.6) < 0.01);
        const double ratio = gas->observe().kT / before;
        qInfo("kT %.4f -> %.4f (× %.4f) dragging at %d steps per frame", before, before * ratio, ratio,
              stepsPerFrame);
        QVERIFY2(std::abs(ratio - 1) < 0.1, qPrintable(QString::number(ratio)));
        if (stepsPerFrame == 1) {
            QTest::qWait(50);
            saveScreenshot(window, "drag-gas-after");
        }
    }

    void draggingEmptySpaceInTheFluidSeedPours() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("fluid-write-up"));
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QCOMPARE(window.viewportCore()->tool(), ui::ViewportTool::Drag);
        auto* fluid = static_cast<FluidModel*>(window.controller()->model());
        QCOMPARE(fluid->particleCount(), std::size_t(0));
        QWidget* view = window.viewport();
        const QPoint a = widgetPoint(window, 10, 30), b = widgetPoint(window, 20, 35);
        QTest::mousePress(view, Qt::LeftButton, {}, a);
        QTest::mouseMove(view, b);
        QTest::mouseRelease(view, Qt::LeftButton, {}, b);
        QVERIFY2(fluid->particleCount() > 50, qPrintable(QString::number(fluid->particleCount())));
        for (std::size_t i = 0; i < fluid->particleCount(); ++i) {
            QVERIFY(fluid->state().x[i] >= 9.9 && fluid->state().x[i] <= 20.1);
            QVERIFY(fluid->state().y[i] >= 29.9 && fluid->state().y[i] <= 35.1);
        }
        // The view did not pan: the same world point is under the same pixel.
        QCOMPARE(widgetPoint(window, 10, 30), a);
    }
};

QTEST_MAIN(TestViewportDrag)
#include "tst_viewport_drag.moc"
