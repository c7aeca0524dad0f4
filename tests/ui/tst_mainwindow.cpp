// The desktop window under a real X server: every built-in preset loads and feeds its docks, time runs
// backwards, bad presets and bad values leave the experiment running, presets round-trip through the
// document, the mouse tools change the scene, docks persist, and a screenshot per scene is saved.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "ViewChooser.h"
#include "fluid/FluidModel.h"
#include "gas/GasModel.h"
#include "panels/ParameterPanel.h"
#include "plots/DistributionPlot.h"
#include "plots/SeriesPlot.h"
#include "viewport/GLViewport.h"
#include "viewport/SoftwareViewport.h"
#include "viewport/ViewportCore.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QDockWidget>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>
#include <qcustomplot.h>

using namespace pl;

namespace {

void runFrames(ui::MainWindow& window, int frames) {
    for (int f = 0; f < frames; ++f) window.controller()->advanceFrame();
    QTest::qWait(50); // queued replots and repaints run, as the event loop does for a user
}

int distinctColours(const QImage& image) {
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
    return static_cast<int>(colours.size());
}

void raiseDockOf(ui::MainWindow& window, ui::SeriesPlot* plot) {
    window.findChild<QDockWidget*>(plot->spec().objectName + "Dock")->raise();
    QTest::qWait(20);
}

QPoint widgetPoint(ui::MainWindow& window, double x, double y) {
    return window.viewportCore()->transform().toWidget(x, y).toPoint();
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // settings and user presets in a scratch location
        QSettings().clear();
        QDir(ui::ExperimentDocument::userPresetDirectory()).removeRecursively();
    }

    void viewportMatchesThePlatform() {
        ui::MainWindow window;
        // The offscreen platform shows no OpenGL windows (Qt 6.4 crashes making GL widgets there).
        if (QGuiApplication::platformName() == "offscreen")
            QVERIFY(qobject_cast<ui::SoftwareViewport*>(window.viewport()));
        else
            QVERIFY(qobject_cast<ui::GLViewport*>(window.viewport()));
    }

    // The main window stays a raster window on every platform: the GL viewport draws in a native window
    // of its own that takes no input (a GL widget would make Qt compose the whole window through OpenGL
    // every frame); the QPainter one (offscreen) has no window at all. Clicks reach the tools either way.
    void theViewportDrawsInItsOwnWindow() {
        const bool drawsWithGl = QGuiApplication::platformName() != "offscreen";
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QCOMPARE(window.windowHandle()->surfaceType(), QSurface::RasterSurface);
        const auto glWindows = window.windowHandle()->findChildren<QWindow*>();
        QCOMPARE(glWindows.size(), drawsWithGl ? 1 : 0);
        if (drawsWithGl) {
            QCOMPARE(glWindows.front()->surfaceType(), QSurface::OpenGLSurface);
            QVERIFY(glWindows.front()->flags().testFlag(Qt::WindowTransparentForInput));
            QVERIFY(QTest::qWaitForWindowExposed(glWindows.front()));
            QCOMPARE(glWindows.front()->size(), window.viewport()->size());
        }

        window.viewportCore()->setTool(ui::ViewportTool::AddDisc);
        const std::size_t before = window.controller()->tools()->obstacles().size();
        QTest::mouseClick(window.viewport(), Qt::LeftButton, {}, window.viewport()->rect().center());
        QCOMPARE(window.controller()->tools()->obstacles().size(), before + 1);
        QVERIFY(!window.viewportImage().isNull());
        QCOMPARE(window.viewportImage().size(), window.viewport()->size() * window.devicePixelRatio());
    }

    void everyBuiltinPresetFeedsItsDocks() {
        for (const auto& builtin : builtinPresets()) {
            ui::MainWindow window;
            const QString name = QString::fromStdString(builtin.name);
            QVERIFY2(window.openPreset(name), qPrintable(name));
            window.resize(1280, 800);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            Model* model = window.controller()->model();
            if (model->particleCount() == 0) // the fluid write-up's empty tank: pour a block as a user would
                QVERIFY(model->tools()->spawnInRectangle(10, 2, 40, 12).starts_with("added"));
            runFrames(window, 30);
            QVERIFY(window.controller()->model()->stepCount() > 0);
            const auto* series = window.controller()->series();
            if (model->plannedSteps() > 0 && model->stepCount() >= model->plannedSteps()) {
                // A short run (the dam break's 300 steps) ends within the frames, sampled on the way.
                QVERIFY2(series->rows() >= 5, qPrintable(name));
            } else {
                QVERIFY2(series->rows() >= 10, qPrintable(name)); // 1 sample per 3 frames
            }
            QVERIFY(window.parameters()->editor("dt") != nullptr);
            if (!model->histograms().empty())
                QVERIFY(window.histogram()->plot()->plottableCount() >= 2); // bars and the theory curve
            for (ui::SeriesPlot* plot : window.seriesPlots()) {
                if (!plot->spec().kinds.contains(QString::fromStdString(builtin.preset.model))) continue;
                // The forces of a scene without a body (the shock tube) have no dock to show them.
                const auto* dock = window.findChild<QDockWidget*>(plot->spec().objectName + "Dock");
                QCOMPARE(dock->toggleViewAction()->isEnabled(),
                         !plot->spec().needsBodies || !builtin.preset.obstacles.empty());
                if (!dock->toggleViewAction()->isEnabled()) continue;
                raiseDockOf(window, plot); // tabbed-away plots refresh when they are shown
                QVERIFY(plot->plot()->graphCount() >= 2);
                // The write-up's tank has no dam-break column, so its front plot has nothing to show.
                if (name == "fluid-write-up" && plot->spec().objectName == "frontPlot") continue;
                int filled = 0; // graphs with 10 samples, or a profile of all 5 iterations and the result
                for (int g = 0; g < plot->plot()->graphCount(); ++g)
                    filled += plot->plot()->graph(g)->visible() && plot->plot()->graph(g)->dataCount() >= 6;
                QVERIFY2(filled >= 2, qPrintable(name + ": " + plot->spec().title));
            }
            const QImage shot = window.windowImage();
            QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
            QVERIFY(shot.save(QString(PARTICLELAB_SCREENSHOT_DIR) + "/mainwindow-" + name + ".png"));
            QVERIFY(distinctColours(window.viewportImage()) > 20); // particles in palette colours, not blank
        }
    }

    void gravityToggleFollowsTheScene() {
        ui::MainWindow window;
        auto* gravity = window.findChild<QAction*>("gravityAction");
        QVERIFY(gravity);
        QVERIFY(window.openPreset("gas-write-up"));
        QVERIFY(gravity->isVisible());                           // every scene with gravity has the switch
        QVERIFY(!gravity->isChecked() && !gravity->isEnabled()); // off where g = 0
        QVERIFY(window.openPreset("dsmc-write-up"));
        QVERIFY(!gravity->isVisible()); // a DSMC cell has no gravity
        QVERIFY(window.openPreset("fluid-dam-break"));
        QVERIFY(gravity->isVisible() && gravity->isChecked());
        gravity->trigger();
        QCOMPARE(std::get<bool>(window.controller()->model()->params().at("gravity_on")), false);
        QVERIFY(window.isWindowModified());
        // Without gravity the column does not fall: its mean vertical velocity stays ≥ 0 (it only relaxes
        // at its free surface), where with gravity it is −1.7 L/s after these 20 steps.
        for (int s = 0; s < 20; ++s) window.controller()->model()->step();
        const auto* fluid = static_cast<const FluidModel*>(window.controller()->model());
        double vy = 0;
        for (double v : fluid->state().vy) vy += v / static_cast<double>(fluid->particleCount());
        QVERIFY2(vy > -0.01, qPrintable(QString::number(vy)));
        window.controller()->setParameters({{"gravity_on", true}});
        QVERIFY(gravity->isChecked());
    }

    // A preset's old name opens the preset it is now (the write-up's scenes were named "-seed").
    void oldPresetNamesOpenTheRenamedPreset() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("dsmc-seed"));
        QCOMPARE(window.document()->title(), QString("dsmc-write-up"));
        QCOMPARE(window.controller()->model()->kind(), std::string("dsmc"));
    }

    void negativeSpeedRunsTimeBackwards() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-write-up"));
        auto* controller = window.controller();
        const GasState start = static_cast<const GasModel*>(controller->model())->state();
        controller->setStepsPerFrame(5);
        for (int frame = 0; frame < 20; ++frame) controller->advanceFrame();
        controller->setStepsPerFrame(-5);
        for (int frame = 0; frame < 20; ++frame) controller->advanceFrame();
        const GasState& back = static_cast<const GasModel*>(controller->model())->state();
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
        const auto steps = before->stepCount();
        QVERIFY(steps > 0);
        test::MessageBoxAnswerer answerer;
        QVERIFY(!window.openPreset("/nonexistent/preset.json"));
        QCOMPARE(window.controller()->model(), before);
        QCOMPARE(window.controller()->model()->stepCount(), steps);

        QTemporaryDir dir;
        const QString broken = dir.filePath("broken.json");
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"schema": 1, "model": "gas", "name": "x", "params": {"dt": "fast"}})");
        file.close();
        QVERIFY(!window.openPreset(broken));
        QCOMPARE(window.controller()->model(), before);
        QVERIFY2(answerer.texts.last().contains("params.dt") || answerer.texts.last().contains("dt"),
                 qPrintable(answerer.texts.last()));
    }

    void invalidParameterNamesTheFieldAndChangesNothing() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        const ParamValues before = window.controller()->model()->params();
        test::MessageBoxAnswerer answerer;
        // 10⁷ disks do not fit in the box: a cross-field error no single field's range can prevent.
        const QString error = window.parameters()->apply("count_a", 1e7);
        QVERIFY(!error.isEmpty());
        QVERIFY2(error.contains("Disks (A)") || error.contains("box"), qPrintable(error));
        QCOMPARE(window.parameters()->problem("count_a"), error); // said under the field, not in a dialog
        QVERIFY(answerer.texts.isEmpty());
        QVERIFY(window.controller()->model()->params() == before);
        QVERIFY(!window.document()->isModified());
    }

    void liveAndResetParametersAreTold() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(window.parameters()->apply("gravity", 0.5).isEmpty()); // live
        QVERIFY(window.controller()->pendingUntilReset().empty());
        QVERIFY(window.parameters()->apply("count_a", 900.0).isEmpty()); // waits for Reset
        QCOMPARE(window.controller()->pendingUntilReset().size(), std::size_t(1));
        QCOMPARE(window.controller()->model()->particleCount(), std::size_t(2500));
        window.controller()->reset();
        QVERIFY(window.controller()->pendingUntilReset().empty());
        QCOMPARE(window.controller()->model()->particleCount(), std::size_t(900));
        QVERIFY(window.document()->isModified());
        QVERIFY(window.isWindowModified());
    }

    void aValueSetBackWaitsForNothing() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(window.parameters()->apply("count_a", 900.0).isEmpty());
        QCOMPARE(window.controller()->pendingUntilReset().size(), std::size_t(1));
        QVERIFY(
            window.parameters()->apply("count_a", 2500.0).isEmpty()); // the value the disks were made with
        QVERIFY(window.controller()->pendingUntilReset().empty());
        window.document()->setModified(false);
    }

    void showIsAViewNotAnEdit() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("tunnel-cylinder"));
        QVERIFY(!window.document()->isModified());
        QComboBox* chooser = window.viewChooser()->combo();
        QVERIFY(chooser && chooser->count() > 1);
        chooser->setCurrentIndex((chooser->currentIndex() + 1) % chooser->count());
        emit chooser->activated(chooser->currentIndex());
        QVERIFY(!window.document()->isModified());
        QVERIFY(!window.isWindowModified());
    }

    void theGravitySwitchShowsG() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom")); // g = 0: off, and nothing to switch
        auto* gravity = window.findChild<QAction*>("gravityAction");
        QVERIFY(gravity && gravity->isVisible());
        QVERIFY(!gravity->isChecked());
        QVERIFY(!gravity->isEnabled());
        QVERIFY(window.parameters()->apply("gravity", 2.5).isEmpty());
        QVERIFY(gravity->isEnabled());
        QVERIFY(gravity->isChecked());
        QVERIFY2(gravity->text().contains("2.5"), qPrintable(gravity->text()));
        window.document()->setModified(false); // no "save changes?" question
        QVERIFY(window.openPreset("fluid-dam-break"));
        QVERIFY(gravity->isChecked());
        QVERIFY2(gravity->text().contains("9.8"), qPrintable(gravity->text()));
        window.document()->setModified(false);
    }

    void presetsRoundTripThroughTheDocument() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(window.parameters()->apply("stiffness", 5e4).isEmpty());
        Obstacle disc;
        disc.x = 0.3;
        disc.radius = 0.15;
        window.controller()->model()->tools()->addObstacle(disc);
        window.controller()->noteEdited();
        QTemporaryDir dir;
        const QString path = dir.filePath("my-gas.json");
        QVERIFY(window.document()->saveTo(path));
        QVERIFY(!window.document()->isModified());
        QCOMPARE(window.document()->recentFiles().value(0), QFileInfo(path).absoluteFilePath());

        ui::MainWindow second;
        QVERIFY(second.openPreset(path));
        const Model* loaded = second.controller()->model();
        QCOMPARE(std::get<double>(loaded->params().at("stiffness")), 5e4);
        QVERIFY(loaded->params() == window.controller()->model()->params());
        const auto& obstacles = static_cast<const GasModel*>(loaded)->obstacles();
        QCOMPARE(obstacles.size(), std::size_t(1));
        QCOMPARE(obstacles[0].radius, 0.15);
        QCOMPARE(second.document()->title(), QString("my-gas"));
    }

    void mouseToolsDragSpawnAndEditObstacles() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QWidget* view = window.viewport();
        ui::ViewportCore* core = window.viewportCore();
        QTest::qWait(50);

        core->setTool(ui::ViewportTool::AddDisc);
        QTest::mouseClick(view, Qt::LeftButton, {}, widgetPoint(window, -0.5, 0.0));
        auto* md = static_cast<GasModel*>(window.controller()->model());
        QCOMPARE(md->obstacles().size(), std::size_t(1));
        QVERIFY(std::abs(md->obstacles()[0].x + 0.5) < 0.01);
        QVERIFY(window.document()->isModified());

        core->setTool(ui::ViewportTool::Drag); // drag the disc to the right while paused
        QTest::mousePress(view, Qt::LeftButton, {}, widgetPoint(window, -0.5, 0.0));
        QTest::mouseMove(view, widgetPoint(window, -0.2, 0.1));
        QTest::mouseRelease(view, Qt::LeftButton, {}, widgetPoint(window, 0.0, 0.2));
        QVERIFY(std::abs(md->obstacles()[0].x - 0.0) < 0.01);
        QVERIFY(std::abs(md->obstacles()[0].y - 0.2) < 0.01);
        QCOMPARE(md->obstacles()[0].vx, 0.0); // let go: at rest

        core->setTool(ui::ViewportTool::Remove);
        QTest::mouseClick(view, Qt::LeftButton, {}, widgetPoint(window, 0.0, 0.2));
        QVERIFY(md->obstacles().empty());

        // Spawning is refused at the particle cap, with the reason in the status bar.
        QVERIFY(window.parameters()->apply("max_particles", 2500.0).isEmpty());
        core->setTool(ui::ViewportTool::Spawn);
        QSignalSpy messages(core, &ui::ViewportCore::statusMessage);
        QTest::mousePress(view, Qt::LeftButton, {}, widgetPoint(window, -0.9, -0.9));
        QTest::mouseMove(view, widgetPoint(window, -0.5, -0.5));
        QTest::mouseRelease(view, Qt::LeftButton, {}, widgetPoint(window, -0.5, -0.5));
        QCOMPARE(md->particleCount(), std::size_t(2500));
        QCOMPARE(messages.count(), 1);
        QVERIFY2(messages.first().first().toString().contains("Particle cap"),
                 qPrintable(messages.first().first().toString()));

        // Below the cap a dragged rectangle fills with disks.
        QVERIFY(window.parameters()->apply("max_particles", 10000.0).isEmpty());
        QTest::mousePress(view, Qt::LeftButton, {}, widgetPoint(window, -0.9, -0.9));
        QTest::mouseMove(view, widgetPoint(window, -0.5, -0.5));
        QTest::mouseRelease(view, Qt::LeftButton, {}, widgetPoint(window, -0.5, -0.5));
        QVERIFY2(md->particleCount() > 2500, qPrintable(messages.last().first().toString()));
    }

    void draggedObstaclePushesTheGas() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* md = static_cast<GasModel*>(window.controller()->model());
        Obstacle paddle;
        paddle.shape = Obstacle::Shape::Box;
        paddle.x = -0.8;
        paddle.halfWidth = 0.05;
        paddle.halfHeight = 0.6;
        md->addObstacle(paddle);
        QTest::qWait(50);
        const double pxBefore = md->observe().px;
        window.controller()->play(); // while running, the paddle heads for the mouse at the tool speed
        QWidget* view = window.viewport();
        QTest::mousePress(view, Qt::LeftButton, {}, widgetPoint(window, -0.8, 0.0));
        for (int i = 1; i <= 20; ++i) {
            QTest::mouseMove(view, widgetPoint(window, -0.8 + 0.03 * i, 0.0));
            window.controller()->advanceFrame();
        }
        QTest::mouseRelease(view, Qt::LeftButton, {}, widgetPoint(window, -0.2, 0.0));
        window.controller()->pause();
        // It follows the hand at the tool speed: after the frames above it is still on its way, pushing
        // the gas ahead of it (until the push comes back off the far wall).
        double pushed = -INFINITY;
        window.controller()->setStepsPerFrame(20);
        for (int f = 0; f < 1000 && md->bodiesMoving(); ++f) {
            window.controller()->advanceFrame();
            pushed = std::max(pushed, md->observe().px);
        }
        QVERIFY(std::abs(md->obstacles()[0].x + 0.2) < 0.01); // where it was let go, to a pixel
        QVERIFY2(pushed > pxBefore + 1.0, qPrintable(QString("px %1 -> %2").arg(pxBefore).arg(pushed)));
    }

    void heatAndCoolChangeTheTemperature() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        auto* controller = window.controller();
        auto* gas = static_cast<GasModel*>(controller->model());
        // The total energy: the lattice start turns kinetic into pair energy meanwhile.
        const double before = gas->observe().total;
        controller->setStepsPerFrame(20);
        controller->setHeatRate(1.0);
        for (int f = 0; f < 10; ++f) controller->advanceFrame();
        const double heated = gas->observe().total;
        QVERIFY2(heated > before, qPrintable(QString("%1 → %2").arg(before).arg(heated)));
        controller->setHeatRate(-1.0);
        for (int f = 0; f < 20; ++f) controller->advanceFrame();
        controller->setHeatRate(0.0);
        QVERIFY2(gas->observe().total < heated, "Cool lowers it again");
    }

    void dsmcSceneRunsItsCourseForwardOnly() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("dsmc-bkw"));
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        // Only the docks with data for this scene show; the gas's energy dock is hidden, not lost.
        QVERIFY(!window.findChild<QDockWidget*>("momentsPlotDock")->isHidden());
        QVERIFY(window.findChild<QDockWidget*>("energyPlotDock")->isHidden());
        QVERIFY(!window.findChild<QDockWidget*>("energyPlotDock")->toggleViewAction()->isEnabled());
        auto* controller = window.controller();
        QSignalSpy notices(controller, &ui::SimulationController::notice);
        controller->setStepsPerFrame(-5); // stochastic collisions: no way back
        QCOMPARE(controller->stepsPerFrame(), 0);
        QCOMPARE(notices.count(), 1);
        controller->setStepsPerFrame(10);
        controller->play();
        for (int f = 0; f < 100; ++f) controller->advanceFrame(); // 1000 steps asked, 800 planned
        QCOMPARE(controller->model()->stepCount(), 800LL);
        QVERIFY(!controller->isRunning());
        // The moments dock drew the measured and the exact BKW curves.
        ui::SeriesPlot* moments = nullptr;
        for (ui::SeriesPlot* plot : window.seriesPlots())
            if (plot->spec().objectName == "momentsPlot") moments = plot;
        QVERIFY(moments);
        raiseDockOf(window, moments);
        int visible = 0;
        for (int g = 0; g < moments->plot()->graphCount(); ++g)
            visible += moments->plot()->graph(g)->visible();
        QCOMPARE(visible, 7); // M4, M6, M8, their exact curves, and the KL divergence

        QVERIFY(window.openPreset("gas-write-up")); // back to the gas: its docks return
        QVERIFY(!window.findChild<QDockWidget*>("energyPlotDock")->isHidden());
        QVERIFY(window.findChild<QDockWidget*>("momentsPlotDock")->isHidden());
    }

    // Issue 45: on a 700 px screen the preset list opened over its box with the presets before the current
    // one above it, past the screen's top, and the wheel did not scroll it. Opened with a click, it lies
    // on the screen and the wheel scrolls it.
    void thePresetListStaysOnTheScreenAndScrolls() {
        ui::MainWindow window;
        QVERIFY(window.openPreset(QString::fromStdString(builtinPresets().back().name))); // the last item
        const QRect screen = window.screen()->geometry();
        window.setGeometry(QRect(screen.topLeft(), QSize(1024, 700)).intersected(screen));
        QVERIFY(test::showActive(window));
        auto* picker = window.findChild<QComboBox*>("presetPicker");
        QVERIFY(picker);
        QTest::mouseClick(picker, Qt::LeftButton, {}, picker->rect().center());
        QTRY_VERIFY(picker->view()->isVisible());
        const QRect list = picker->view()->window()->geometry();
        QVERIFY2(screen.contains(list), qPrintable(QString("list at %1,%2 %3x%4")
                                                       .arg(list.x())
                                                       .arg(list.y())
                                                       .arg(list.width())
                                                       .arg(list.height())));
        QScrollBar* bar = picker->view()->verticalScrollBar();
        QVERIFY2(bar->maximum() > 0, "the list shows every preset at once: nothing to scroll");
        const int before = bar->value();
        QWidget* rows = picker->view()->viewport();
        const QPointF at = rows->rect().center();
        QWheelEvent up(at, rows->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                       Qt::NoScrollPhase, false);
        QApplication::sendEvent(rows, &up);
        QVERIFY(bar->value() < before);
        picker->hidePopup();
        window.document()->setModified(false);
    }

    void dockLayoutPersists() {
        {
            ui::MainWindow window;
            QVERIFY(window.openPreset("gas-write-up"));
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            window.findChild<QDockWidget*>("speedHistogramDock")->hide();
            window.close();
        }
        ui::MainWindow reopened;
        QVERIFY(reopened.openPreset("gas-write-up"));
        reopened.show();
        QVERIFY(QTest::qWaitForWindowExposed(&reopened));
        QVERIFY(!reopened.findChild<QDockWidget*>("speedHistogramDock")->isVisible());
        QVERIFY(reopened.findChild<QDockWidget*>("parametersDock")->isVisible());
        reopened.findChild<QDockWidget*>("speedHistogramDock")->show();
        reopened.close();
    }

    void projectorModeEnlargesText() {
        ui::MainWindow window;
        const double normal = QApplication::font().pointSizeF();
        window.setProjectorMode(true);
        QVERIFY(QApplication::font().pointSizeF() > 1.5 * normal);
        window.setProjectorMode(false);
        QCOMPARE(QApplication::font().pointSizeF(), normal);
    }

    void viewportImageIsSaved() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        window.resize(1000, 700);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTemporaryDir dir;
        const QString path = dir.filePath("view.png");
        QVERIFY(window.saveViewportImage(path).isEmpty());
        QImage image(path);
        QVERIFY(!image.isNull());
        QVERIFY(distinctColours(image) > 20);
        QVERIFY(!window.saveViewportImage("/nonexistent/dir/view.png").isEmpty());
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
