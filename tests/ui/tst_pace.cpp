// The automatic pace through the window as a teacher uses it: each scene starts automatic and forward,
// a fixed number stays available, reversal works in both, the scene's watchable rate caps it, and at the
// default pace a disc dragged across gas-classroom by real mouse events keeps up with the hand and the
// gas's kT, and a slow compression by the Compress key follows the adiabat T·A = const in a few seconds.
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "catalog/ModelCatalog.h"
#include "common/ThreadGovernor.h"
#include "gas/GasModel.h"
#include "viewport/ViewportCore.h"

#include <QAction>
#include <QElapsedTimer>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QtTest>

using namespace pl;

namespace {

QPoint widgetPoint(ui::MainWindow& window, double x, double y) {
    return window.viewportCore()->transform().toWidget(x, y).toPoint();
}

// Lets the frame timer run the simulation for ms of wall time, as it does for a user.
void runFor(int ms) {
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) QTest::qWait(5);
}

double area(const GasModel& gas) {
    const GasParams& p = gas.parameters();
    return (gas.pistonX() - p.left()) * p.boxHeight;
}

// The mean kT over ms of wall time while time runs (the gas relaxes at fixed area).
double meanKT(ui::MainWindow& window, int ms) {
    auto* gas = static_cast<GasModel*>(window.controller()->model());
    double sum = 0;
    int n = 0;
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) {
        QTest::qWait(20);
        sum += gas->observe().kT;
        ++n;
    }
    return sum / n;
}

} // namespace

class TestPace : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        test::useCleanTestSettings();
        // As the app runs (app/gui/main.cpp): the team of threads that steps fastest, one where the
        // X server and the rasteriser hold a core.
        setThreadPolicy(adaptiveUnlessUserFixed());
    }

    void everyKindDeclaresAWatchableRate() {
        for (const ModelDescriptor& kind : modelCatalog()) {
            QVERIFY2(kind.watchableRate > 0, kind.kind.c_str());
            QVERIFY2(!kind.units.time.empty(), kind.kind.c_str());
        }
    }

    void thePaceBelongsToTheScene() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        auto* controller = window.controller();
        auto* speed = window.findChild<QSpinBox*>("stepsPerFrame");
        auto* automatic = window.findChild<QAction*>("autoPaceAction");
        QVERIFY(speed && automatic);
        QVERIFY(controller->automaticPace());
        QVERIFY(automatic->isChecked());
        QVERIFY(speed->prefix().size() > 0);
        // A number typed in the box fixes the pace; Auto brings the automatic one back.
        speed->setValue(7);
        QVERIFY(!controller->automaticPace());
        QVERIFY(!automatic->isChecked());
        QCOMPARE(controller->stepsPerFrame(), 7);
        const auto before = controller->model()->stepCount();
        controller->advanceFrame();
        QCOMPARE(controller->model()->stepCount(), before + 7);
        automatic->trigger();
        QVERIFY(controller->automaticPace());
        speed->setValue(20);
        // The next scene starts at its own default pace.
        QVERIFY(window.openPreset("fluid-dam-break"));
        QVERIFY(controller->automaticPace());
        QCOMPARE(controller->direction(), 1);
        QVERIFY(automatic->isChecked());
    }

    void reversalWorksInBothPaces() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        auto* controller = window.controller();
        for (int f = 0; f < 5; ++f) controller->advanceFrame();
        const double t0 = controller->model()->time();
        QVERIFY(t0 > 0);
        controller->reverse(); // automatic, backwards
        QVERIFY(controller->automaticPace());
        QCOMPARE(controller->model()->timeDirection(), -1);
        controller->advanceFrame();
        const double t1 = controller->model()->time();
        QVERIFY2(t1 < t0, qPrintable(QString("%1 -> %2").arg(t0).arg(t1)));
        QVERIFY(controller->stepsPerFrame() < 0);
        controller->setStepsPerFrame(3); // fixed, forward
        controller->reverse();
        QCOMPARE(controller->stepsPerFrame(), -3);
        controller->advanceFrame();
        QVERIFY(controller->model()->time() < t1);
        // A scene whose collisions are random refuses to run back, in either pace.
        QVERIFY(window.openPreset("dsmc-bkw"));
        QSignalSpy notices(controller, &ui::SimulationController::notice);
        controller->reverse();
        QCOMPARE(controller->direction(), 1);
        QCOMPARE(notices.count(), 1);
    }

    void theWatchableRateCapsTheAutomaticPace() {
        // The DSMC cell steps in microseconds: without the cap a frame would run its whole course.
        ui::MainWindow window;
        QVERIFY(window.openPreset("dsmc-write-up"));
        QVERIFY(test::showActive(window));
        auto* controller = window.controller();
        const double rate = controller->watchableRate();
        QVERIFY(rate > 0);
        controller->play();
        QElapsedTimer clock;
        clock.start();
        runFor(1000);
        const double wall = clock.elapsed() / 1000.0;
        const QString status = window.findChild<QLabel*>("statusLine")->text();
        controller->pause();
        const double perSecond = controller->model()->time() / wall;
        qInfo("dsmc-write-up: %.4g s of model time per second, cap %.4g", perSecond, rate);
        QVERIFY2(perSecond <= rate * 1.1, qPrintable(QString::number(perSecond)));
        QVERIFY2(perSecond > 0.3 * rate, qPrintable(QString::number(perSecond)));
        // The status bar says steps a second and model time a second while time runs, and that it stands
        // once paused.
        QVERIFY2(status.contains("steps/s") && status.contains(" s per second"), qPrintable(status));
        const QString paused = window.findChild<QLabel*>("statusLine")->text();
        QVERIFY2(paused.contains("stopped") && !paused.contains("fps"), qPrintable(paused));
    }

    void dragFollowsTheHandAtTheDefaultPace() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(test::showActive(window));
        auto* controller = window.controller();
        Preset withDisc = controller->model()->toPreset(); // the disks are placed around the disc
        withDisc.obstacles.push_back({Obstacle::Shape::Disc, -0.6, 0.0, 0.12});
        QVERIFY(controller->load(withDisc).isEmpty());
        auto* gas = static_cast<GasModel*>(controller->model());
        controller->play(); // toward Maxwell–Boltzmann around the disc, at the default pace
        runFor(3000);
        QVERIFY(controller->automaticPace());
        const double before = meanKT(window, 500);

        // Half a second of wall time from x = −0.6 to 0.6, the frame timer running.
        QWidget* view = window.viewport();
        QElapsedTimer clock;
        clock.start();
        const double t0 = gas->time();
        QTest::mousePress(view, Qt::LeftButton, {}, widgetPoint(window, -0.6, 0.0));
        constexpr int kMoves = 25;
        for (int i = 1; i <= kMoves; ++i) {
            QTest::mouseMove(view, widgetPoint(window, -0.6 + 1.2 * i / kMoves, 0.0));
            runFor(20);
        }
        QTest::mouseRelease(view, Qt::LeftButton, {}, widgetPoint(window, 0.6, 0.0));
        while (gas->bodiesMoving() && clock.elapsed() < 20000) QTest::qWait(2);
        const qint64 arrived = clock.elapsed();
        const double simulated = gas->time() - t0;
        QVERIFY(!gas->bodiesMoving());
        QVERIFY(std::abs(gas->obstacles()[0].x - 0.6) < 0.01);
        const double after = meanKT(window, 1000);
        controller->pause();
        QVERIFY(!gas->failure());
        const double ratio = after / before;
        // The disc crosses 1.2 L at the tool speed: the simulated time it needs, and the wall time the
        // pace gives it.
        const double needed = 1.2 / gas->toolSpeed();
        qInfo("drag: at the target %lld ms after the press (%.3f T simulated, %.3f T needed, %.2f T/s, %.0f "
              "steps/s); kT %.4f -> %.4f (× %.4f)",
              arrived, simulated, needed, simulated / (arrived / 1000.0), controller->stepsPerSecond(),
              before, after, ratio);
        QVERIFY2(std::abs(ratio - 1) < 0.1, qPrintable(QString::number(ratio)));
        // It lags the hand by the tool speed only (a frame's steps of margin), never by a stalled pace.
        QVERIFY2(simulated < needed * 1.05 + 0.05, qPrintable(QString::number(simulated)));
        // The pace the drag ran at: the old 5 steps per frame took about 90 s. (Arriving within 2 s needs
        // 2 T/s, about 11 400 steps/s: a quiet machine's share of the frame, not a shared one's.)
        QVERIFY2(arrived <= 30000, qPrintable(QString::number(arrived)));
    }

    void heatIsARatePerSimulatedTime() {
        // The same simulated time held at full Heat warms the gas alike at 1 and at 40 steps per frame;
        // at a quarter of the slider, a quarter of it. Measured as the energy heating added: kinetic
        // energy × (exp(rate × heatRatePerTime × simulated time) − 1).
        const auto measured = [](int stepsPerFrame, double rate, int frames) {
            ui::MainWindow window;
            if (!window.openPreset("gas-classroom")) return 0.0;
            auto* controller = window.controller();
            auto* gas = static_cast<GasModel*>(controller->model());
            controller->setStepsPerFrame(20);
            for (int f = 0; f < 100; ++f) controller->advanceFrame(); // off the lattice
            controller->setStepsPerFrame(stepsPerFrame);
            const GasObservables before = gas->observe();
            const double t0 = gas->time();
            controller->setHeatRate(rate);
            for (int f = 0; f < frames; ++f) controller->advanceFrame();
            controller->setHeatRate(0.0);
            const double expected =
                before.kinetic * std::expm1(rate * controller->heatRatePerTime() * (gas->time() - t0));
            return (gas->observe().total - before.total) / expected;
        };
        const double slow = measured(1, 1.0, 2000), fast = measured(40, 1.0, 50),
                     gentle = measured(40, 0.25, 50);
        qInfo("energy heating added / expected: %.4f at 1 step per frame, %.4f at 40, %.4f at a quarter",
              slow, fast, gentle);
        QVERIFY2(std::abs(slow - 1) < 0.15, qPrintable(QString::number(slow)));
        QVERIFY2(std::abs(fast - 1) < 0.15, qPrintable(QString::number(fast)));
        QVERIFY2(std::abs(gentle - 1) < 0.15, qPrintable(QString::number(gentle)));
    }

    void fullHeatTakesSecondsToDoubleKT() {
        // Held to the right at the default pace: kT doubles in no less than 3 s of wall time (the rate is
        // ln 2 per 4 s of the watchable pace); 4 s where the machine reaches that pace, longer where not.
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(test::showActive(window));
        auto* controller = window.controller();
        auto* gas = static_cast<GasModel*>(controller->model());
        QSlider* heat = window.findChild<QSlider*>("heatSlider");
        QVERIFY(heat);
        controller->play();
        runFor(1000);
        const double before = gas->observe().kT;
        QElapsedTimer clock;
        clock.start();
        heat->setSliderDown(true);
        heat->setValue(heat->maximum());
        while (gas->observe().kT < 2 * before && clock.elapsed() < 60000) QTest::qWait(5);
        const qint64 doubled = clock.elapsed();
        heat->setSliderDown(false); // released: it springs back and heating stops
        QCOMPARE(heat->value(), 0);
        const double held = gas->observe().kT;
        runFor(300);
        controller->pause();
        qInfo("full Heat: kT %.4f -> %.4f in %lld ms (%.2f T/s)", before, held, doubled,
              controller->simulatedPerSecond());
        QVERIFY2(doubled >= 3000, qPrintable(QString::number(doubled)));
        QVERIFY2(doubled <= 55000, qPrintable(QString::number(doubled))); // it does heat
        QVERIFY2(gas->observe().kT < 1.05 * held, "heating stops when the slider is let go");
    }

    void slowCompressionFollowsTheAdiabatAtTheDefaultPace() {
        // A dilute gas (area fraction 0.3 %), an ideal 2D gas: γ = 2, so T·A is constant on the adiabat.
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(test::showActive(window));
        auto* controller = window.controller();
        QVERIFY(controller
                    ->setParameters({{"count_a", 400.0},
                                     {"diameter_a", 0.006},
                                     {"stiffness", 2e5},
                                     {"init_velocity", std::string("maxwell-boltzmann")},
                                     {"init_kT", 0.5},
                                     {"piston_enabled", true}})
                    .isEmpty());
        controller->reset();
        auto* gas = static_cast<GasModel*>(controller->model());
        QVERIFY(gas->hasPiston());
        controller->play();
        const double kT0 = meanKT(window, 500), a0 = area(*gas);

        // Ctrl+Left compresses at the piston speed; pressed again it holds the piston, at half the area.
        QElapsedTimer clock;
        clock.start();
        QTest::keyClick(&window, Qt::Key_Left, Qt::ControlModifier);
        QCOMPARE(gas->pistonDirection(), -1);
        while (gas->pistonX() > 0.0 && clock.elapsed() < 60000) QTest::qWait(2);
        QTest::keyClick(&window, Qt::Key_Left, Qt::ControlModifier);
        const qint64 wall = clock.elapsed();
        QCOMPARE(gas->pistonDirection(), 0);
        const double kT1 = meanKT(window, 1500), a1 = area(*gas);
        controller->pause();
        QVERIFY(!gas->failure());
        const double ratio = kT1 * a1 / (kT0 * a0);
        qInfo("compression to A/2: %lld ms (%.0f steps/s); kT %.4f -> %.4f, A %.4f -> %.4f, T·A ratio %.4f",
              wall, controller->stepsPerSecond(), kT0, kT1, a0, a1, ratio);
        QVERIFY2(a1 / a0 < 0.52, qPrintable(QString::number(a1 / a0)));
        QVERIFY2(wall <= 30000, qPrintable(QString::number(wall)));
        QVERIFY2(std::abs(ratio - 1) < 0.05, qPrintable(QString::number(ratio)));
    }

    // A machine that cannot keep the watchable pace says so in the status bar, with the work of a step,
    // and offers the lighter experiment the kind's registration knows; nothing changes until the button
    // is pressed. (Before, the tunnel ran at 35–42 % of the watchable pace on a loaded machine and nothing
    // said why; a dragged body took 25 s to arrive.)
    void aShortPaceIsSaidWithALighterExperiment() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("tunnel-cylinder"));
        auto* controller = window.controller();
        // 20 times the preset's molecules: far below the watchable pace on any machine that runs the tests.
        const double presetFn = std::get<double>(controller->parameterValues().at("fn"));
        QVERIFY(controller->setParameters({{"fn", presetFn / 20}}).isEmpty());
        controller->reset();
        const std::size_t heavy = controller->model()->particleCount();
        QVERIFY(test::showActive(window));
        auto* advice = window.findChild<QWidget*>("paceAdvice");
        QVERIFY(advice && !advice->isVisible());
        controller->play();
        QTRY_VERIFY_WITH_TIMEOUT(advice->isVisible(), 20000);
        auto* text = window.findChild<QLabel*>("paceAdviceText");
        QVERIFY2(text->text().endsWith("% of the watchable pace"), qPrintable(text->text()));
        QVERIFY2(text->toolTip().contains("ms for") && text->toolTip().contains("particles"),
                 qPrintable(text->toolTip())); // the work of a step
        // Nothing changed by itself: the experiment is the one the teacher chose.
        QCOMPARE(std::get<double>(controller->parameterValues().at("fn")), presetFn / 20);
        auto* use = window.findChild<QPushButton*>("paceAdviceUse");
        QVERIFY2(use->isVisible() && use->text().contains("Particle weight F_N = "), qPrintable(use->text()));
        QTest::mouseClick(use, Qt::LeftButton);
        const double lighterFn = std::get<double>(controller->parameterValues().at("fn"));
        qInfo("advised F_N %.3g from %.3g: %zu molecules before, %zu after", lighterFn, presetFn / 20, heavy,
              controller->model()->particleCount());
        QVERIFY(lighterFn > 2 * presetFn / 20);
        QVERIFY(controller->model()->particleCount() < heavy / 2); // restarted lighter
        QVERIFY(controller->isRunning());
        QVERIFY(!advice->isVisible());
        controller->pause();
    }
};

QTEST_MAIN(TestPace)
#include "tst_pace.moc"
