// Present mode and the viewport's room under a real X server: F5 and Escape enter and leave it and bring
// back the exact layout; the viewport keeps at least half the window in present mode and never shrinks
// in projector mode, at 1024×700, 1280×800 and 1920×1080; every board keeps its controls in reach and its
// plot readable, in projector mode and German too; the readouts follow the series store; the lesson's
// controls act on the model through real clicks; screenshots of each scene are saved.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "catalog/ModelCatalog.h"
#include "contract/BallisticKind.h"
#include "gl/Backends.h"
#include "i18n/Translations.h"
#include "plots/DistributionPlot.h"
#include "plots/SeriesPlot.h"
#include "present/LessonControls.h"
#include "present/PresentMode.h"
#include "present/PresentPanel.h"
#include "present/PresentReadouts.h"
#include "viewport/ViewportCore.h"

#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>
#include <numeric>

using namespace pl;
using test::cutOffWidgets;
using test::shownPart;

namespace {

void runFrames(ui::MainWindow& window, int frames) {
    for (int f = 0; f < frames; ++f) window.controller()->advanceFrame();
    QTest::qWait(60); // queued replots, layout and repaints run, as the event loop does for a user
}

double viewportShare(const ui::MainWindow& window) {
    const QSize v = window.viewport()->size(), w = window.size();
    return double(v.width()) * v.height() / (double(w.width()) * w.height());
}

// The drawn scene's width in pixels (the gas box, the tank) after the viewport has painted.
double sceneWidthPx(ui::MainWindow& window) {
    window.viewport()->repaint();
    QTest::qWait(30);
    const SceneView& scene = window.viewportCore()->scene();
    return window.viewportCore()->transform().scale() * (scene.right - scene.left);
}

// What "the layout" is: visible docks and their sizes, tool bars, menu and status bar, window state.
QStringList layoutOf(ui::MainWindow& window) {
    QStringList out;
    for (QDockWidget* dock : window.findChildren<QDockWidget*>())
        if (dock->isVisible())
            out << QString("%1 %2x%3").arg(dock->objectName()).arg(dock->width()).arg(dock->height());
    for (QToolBar* bar : window.findChildren<QToolBar*>())
        out << bar->objectName() + (bar->isVisible() ? " on" : " off");
    out << QString("menu %1 status %2")
               .arg(window.menuBar()->isVisible())
               .arg(window.statusBar()->isVisible());
    out << QString("window %1x%2 state %3")
               .arg(window.width())
               .arg(window.height())
               .arg(int(window.windowState()));
    out.sort();
    return out;
}

void showAt(ui::MainWindow& window, QSize size) {
    window.resize(size);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTest::qWait(50);
}

template <typename T> T* presentChild(ui::MainWindow& window, const QString& name) {
    return window.presentMode()->panel()->findChild<T*>(name);
}

} // namespace

class TestPresent : public QObject {
    Q_OBJECT
    QFont baseFont_;
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // settings in a scratch location
        QSettings().clear();
        baseFont_ = QApplication::font();
        // A kind made by docs/architecture.md's checklist alone, with no presets and no word of its own in
        // ui/: present mode must still give it a board.
        registerModel(test::ballisticRegistration());
    }
    void init() { QSettings().clear(); } // every test starts from the default layout
    void cleanup() { // a failed projector or German row leaves no large font and no German
        QApplication::setFont(baseFont_);
        ui::installLanguage("en");
    }

    void keysEnterAndLeaveRestoringTheLayout() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        showAt(window, {1280, 800});
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));       // keys reach the active window only
        window.findChild<QToolBar*>("toolsToolBar")->hide(); // a layout of the user's own
        QTest::qWait(30);
        const QStringList before = layoutOf(window);
        QTest::keyClick(window.viewport(), Qt::Key_F5);
        QTest::qWait(80);
        QVERIFY(window.presentMode()->isActive());
        QVERIFY(window.windowState() & Qt::WindowFullScreen);
        QVERIFY(!window.menuBar()->isVisible());
        for (QToolBar* bar : window.findChildren<QToolBar*>()) QVERIFY(!bar->isVisible());
        for (QDockWidget* dock : window.findChildren<QDockWidget*>())
            QCOMPARE(dock->isVisible(), dock->objectName() == "presentDock");
        // The menu's keys still act without the menu bar: Space runs, Space pauses.
        QTest::keyClick(window.viewport(), Qt::Key_Space);
        QVERIFY(window.controller()->isRunning());
        QTest::keyClick(window.viewport(), Qt::Key_Space);
        QVERIFY(!window.controller()->isRunning());
        QTest::keyClick(window.viewport(), Qt::Key_Escape);
        QTest::qWait(80);
        QVERIFY(!window.presentMode()->isActive());
        QCOMPARE(layoutOf(window), before);
        QVERIFY(!window.findChild<QAction*>("presentAction")->isChecked());
        // And F5 a second time leaves too.
        window.findChild<QAction*>("presentAction")->trigger();
        QTest::qWait(50);
        QVERIFY(window.presentMode()->isActive());
        QTest::keyClick(window.viewport(), Qt::Key_F5);
        QTest::qWait(80);
        QCOMPARE(layoutOf(window), before);
        window.document()->setModified(false);
    }

    void viewportKeepsItsRoom_data() {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QSize>("size");
        for (const QString preset : {"gas-classroom", "dsmc-write-up", "fluid-obstacle"})
            for (QSize size : {QSize(1024, 700), QSize(1280, 800), QSize(1920, 1080)})
                QTest::newRow(
                    qPrintable(QString("%1 %2x%3").arg(preset).arg(size.width()).arg(size.height())))
                    << preset << size;
    }

    void viewportKeepsItsRoom() {
        QFETCH(QString, preset);
        QFETCH(QSize, size);
        ui::MainWindow window;
        QVERIFY(window.openPreset(preset));
        showAt(window, size);
        runFrames(window, 4);
        const QSize normal = window.viewport()->size();
        const double normalScene = sceneWidthPx(window);
        // Projector mode: larger text, and the docks give back the width it would take from the view.
        window.setProjectorMode(true);
        QTest::qWait(80);
        const QSize projector = window.viewport()->size();
        const double projectorScene = sceneWidthPx(window);
        qInfo("%s normal viewport %dx%d (scene %.0f px, share %.2f), projector %dx%d (scene %.0f px)",
              qPrintable(preset), normal.width(), normal.height(), normalScene,
              double(normal.width()) * normal.height() / (size.width() * size.height()), projector.width(),
              projector.height(), projectorScene);
        QVERIFY2(projector.width() >= normal.width(), "the docks took width from the viewport");
        // The taller menu, tool and status bars take a few rows; the scene may lose no more than that.
        QVERIFY2(projectorScene >= 0.93 * normalScene, "projector mode shrank the scene");
        window.setProjectorMode(false);
        QTest::qWait(50);

        window.presentMode()->setActive(true);
        QTest::qWait(50);
        window.resize(size); // Xvfb has no window manager: "full screen" is the size the test gives
        runFrames(window, 12);
        QTest::qWait(100);
        const double share = viewportShare(window);
        qInfo("present %dx%d: viewport %dx%d, share %.2f, scene %.0f px", window.width(), window.height(),
              window.viewport()->width(), window.viewport()->height(), share, sceneWidthPx(window));
        QCOMPARE(window.size(), size);
        QVERIFY2(share >= 0.5, qPrintable(QString::number(share)));
        QVERIFY(sceneWidthPx(window) >= normalScene); // the scene grows when presented
        // The panel shows its width whole: nothing of it lies beyond the window's right edge.
        QWidget* panel = window.presentMode()->panel();
        QVERIFY2(panel->mapTo(&window, QPoint(panel->width(), 0)).x() <= window.width(),
                 qPrintable(QString("panel %1 wide").arg(panel->width())));
        QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
        QVERIFY(window.windowImage().save(QString("%1/present-%2-%3x%4.png")
                                              .arg(PARTICLELAB_SCREENSHOT_DIR, preset)
                                              .arg(size.width())
                                              .arg(size.height())));
        window.presentMode()->setActive(false);
        window.document()->setModified(false);
    }
    // Every registered kind (the catalog, with the test tree's kind) and every built-in preset, at the
    // three sizes: the panel lies inside the window with nothing cut off, shows at least three readouts,
    // and keeps Leave and Record in reach. Each kind's first scene also in projector mode at 1024×700 and
    // 1280×800 and in German: every control of its board in reach without scrolling, its plot at least
    // 150 px high (the 30 px plot and the piston's buttons below the screen's edge) and
    // the area inside its axes at least test::kReadableDataHeight (it was 40–60 px in projector mode).
    void everySceneFitsPresentMode_data() {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("preset"); // empty: the kind's default experiment
        QTest::addColumn<QSize>("size");
        QTest::addColumn<bool>("projector");
        QTest::addColumn<QString>("language");
        const auto row = [](const QString& kind, const QString& preset, QSize size, bool projector,
                            const QString& language) {
            QTest::newRow(qPrintable(QString("%1 %2x%3%4%5")
                                         .arg(preset.isEmpty() ? kind : preset)
                                         .arg(size.width())
                                         .arg(size.height())
                                         .arg(projector ? " projector" : "")
                                         .arg(language == "en" ? QString() : " " + language)))
                << kind << preset << size << projector << language;
        };
        for (const ModelDescriptor& descriptor : modelCatalog()) {
            const QString kind = QString::fromStdString(descriptor.kind);
            QStringList presets;
            for (const BuiltinPreset* builtin : builtinPresetsOf(descriptor.kind))
                presets << QString::fromStdString(builtin->name);
            if (presets.isEmpty()) presets << QString();
            for (const QString& preset : presets) {
                for (QSize size : {QSize(1024, 700), QSize(1280, 800), QSize(1920, 1080)})
                    row(kind, preset, size, false, "en");
                // Every scene's board in projector mode on the smallest screen (fluid-obstacle's gravity
                // controls, pour and spawn tool ran past its bottom edge)
                if (preset != presets.front()) row(kind, preset, QSize(1024, 700), true, "en");
            }
            for (const QString language : {"en", "de"}) {
                for (QSize size : {QSize(1024, 700), QSize(1280, 800)})
                    row(kind, presets.front(), size, true, language);
                if (language == QLatin1String("de"))
                    row(kind, presets.front(), QSize(1024, 700), false, language);
            }
        }
    }
    void everySceneFitsPresentMode() {
        QFETCH(QString, kind);
        QFETCH(QString, preset);
        QFETCH(QSize, size);
        QFETCH(bool, projector);
        QFETCH(QString, language);
        QVERIFY(ui::installLanguage(language)); // before the window: its texts are translated once
        ui::MainWindow window;
        window.controller()->setBackend(gl::Backend::Cpu); // the layout is the same on either backend
        if (preset.isEmpty())
            QVERIFY(window.controller()->load(defaultPreset(*findModel(kind.toStdString()))).isEmpty());
        else
            QVERIFY(window.openPreset(preset));
        showAt(window, size);
        if (projector) { // as the teacher does it: Ctrl+Shift+P, then F5
            window.activateWindow();
            QVERIFY(QTest::qWaitForWindowActive(&window));
            QTest::keyClick(window.viewport(), Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
            QVERIFY(window.findChild<QAction*>("projectorAction")->isChecked());
            QTest::keyClick(window.viewport(), Qt::Key_F5);
            QVERIFY(window.presentMode()->isActive());
        } else {
            window.presentMode()->setActive(true);
        }
        QTest::qWait(50);
        window.resize(size); // Xvfb has no window manager: "full screen" is the size the test gives
        runFrames(window, 6);
        QTest::qWait(120);
        QCOMPARE(window.size(), size);
        ui::PresentPanel* panel = window.presentMode()->panel();
        const QStringList cut = cutOffWidgets(panel, &window);
        const test::BoardReach reach = test::boardReach(panel, &window);
        qInfo("board: %d of %d controls in reach, plot %s px high; panel %d px wide", reach.inReach,
              reach.controls,
              qPrintable(std::accumulate(reach.plotHeights.begin(), reach.plotHeights.end(), QString(),
                                         [](QString a, int h) { return a + QString::number(h) + " "; })),
              panel->width());
        QVERIFY2(cut.isEmpty(), qPrintable("cut off: " + cut.join(", ")));
        QVERIFY2(reach.inReach == reach.controls, qPrintable("out of reach: " + reach.outOfReach.join(", ")));
        QVERIFY(!reach.plotHeights.isEmpty());
        for (int height : reach.plotHeights)
            QVERIFY2(height >= test::kReadableDataHeight, qPrintable(QString::number(height)));
        const QStringList readouts = panel->readouts()->texts();
        QVERIFY2(readouts.size() >= 3, qPrintable(kind + " readouts: " + readouts.join("; ")));
        // Each number is read whole, its unit too: a value cut at its label's edge read "5.33 N" for
        // 5.33 N/m and "299 K" with half a K (German DSMC at 1024 × 700).
        for (const QLabel* value : panel->readouts()->findChildren<QLabel*>(QRegularExpression("^readout_")))
            QVERIFY2(value->width() >= value->sizeHint().width(),
                     qPrintable(QString("%1 '%2' is %3 px wide, needs %4")
                                    .arg(value->objectName(), value->text())
                                    .arg(value->width())
                                    .arg(value->sizeHint().width())));
        // The forces on a body are read where the scene has one (not 0 N/m in the shock tube).
        const SceneTools* tools = window.controller()->tools();
        const bool hasBodies = tools && !tools->obstacles().empty();
        for (const ui::ReadoutSpec& spec : ui::readoutSpecsFor(*window.controller()->model()))
            if (spec.needsBodies)
                QCOMPARE(
                    readouts.filter(QRegularExpression("^" + QRegularExpression::escape(spec.name) + " = "))
                        .size(),
                    hasBodies ? 1 : 0);
        auto* leave = presentChild<QPushButton>(window, "presentLeave");
        QVERIFY(leave && leave->isVisibleTo(&window));
        QCOMPARE(shownPart(leave, &window), leave->rect());
        auto* record = presentChild<QToolButton>(window, "presentRecord");
        QVERIFY2(record && record->isVisibleTo(&window), "no Record button");
        QCOMPARE(record->defaultAction(), window.findChild<QAction*>("recordAction"));
        QVERIFY(panel->currentPlot() && panel->currentPlot()->height() >= 150);
        QVERIFY(viewportShare(window) >= 0.5);
        QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
        QVERIFY(
            window.windowImage().save(QString("%1/present-board-%2-%3x%4%5%6.png")
                                          .arg(PARTICLELAB_SCREENSHOT_DIR, preset.isEmpty() ? kind : preset)
                                          .arg(size.width())
                                          .arg(size.height())
                                          .arg(projector ? "-projector" : "")
                                          .arg(language == "en" ? QString() : "-" + language)));
        window.presentMode()->setActive(false);
        window.setProjectorMode(false);
        window.document()->setModified(false);
        ui::installLanguage("en");
    }
    void gasLessonControlsActOnTheModel() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        auto* controller = window.controller();
        QVERIFY(controller->setParameters({{"count_a", 400.0}}).isEmpty()); // a small, fast scene
        controller->reset();
        showAt(window, {1280, 800});
        window.presentMode()->setActive(true);
        QTest::qWait(50);
        Model* model = controller->model();
        auto* compress = presentChild<QPushButton>(window, "lessonCompress");
        QVERIFY(compress && !compress->isEnabled()); // no piston yet
        QTest::mouseClick(presentChild<QPushButton>(window, "lessonPistonSwitch"), Qt::LeftButton);
        QVERIFY(model->tools()->hasPiston());
        QVERIFY(compress->isEnabled());
        const double start = model->tools()->pistonX();
        QTest::mouseClick(compress, Qt::LeftButton);
        QCOMPARE(model->tools()->pistonDirection(), -1);
        QVERIFY(compress->isChecked());
        runFrames(window, 20);
        QVERIFY2(model->tools()->pistonX() < start, qPrintable(QString::number(model->tools()->pistonX())));
        QTest::mouseClick(presentChild<QPushButton>(window, "lessonStop"), Qt::LeftButton);
        QCOMPARE(model->tools()->pistonDirection(), 0);

        // Temperature: held to the right, it heats while frames run; released, it springs back.
        auto* heat = presentChild<QSlider>(window, "lessonHeat");
        const int kTColumn = controller->series()->column("kT");
        const auto latestKT = [&] {
            runFrames(window, 3); // one more sample
            return controller->series()->table().row(controller->series()->rows() - 1)[std::size_t(kTColumn)];
        };
        const double kT0 = latestKT();
        QTest::mousePress(heat, Qt::LeftButton, {}, heat->rect().center());
        QTest::mouseMove(heat, QPoint(heat->width() - 5, heat->height() / 2));
        QVERIFY(heat->value() > 50);
        // Heating is a rate per simulated time (kT × 2 in 10 T at full): held until it shows.
        for (int round = 0; round < 100 && latestKT() <= 1.25 * kT0; ++round) runFrames(window, 10);
        QTest::mouseRelease(heat, Qt::LeftButton, {}, QPoint(heat->width() - 5, heat->height() / 2));
        QCOMPARE(heat->value(), 0);
        const double kT1 = latestKT();
        QVERIFY2(kT1 > 1.2 * kT0, qPrintable(QString("%1 -> %2").arg(kT0).arg(kT1)));

        // Particle number: a click on the groove steps it; the scene restarts with that many disks.
        auto* count = presentChild<QSlider>(window, "lessonCount");
        QCOMPARE(count->value(), 400);
        const double kTReached = latestKT();
        QTest::mouseClick(count, Qt::LeftButton, {}, QPoint(count->width() - 5, count->height() / 2));
        QTest::qWait(30);
        QVERIFY(count->value() > 400);
        model = controller->model();
        QCOMPARE(int(model->particleCount()), count->value());
        // … at the temperature it had reached, as the gas's registration says (init_kT).
        const double restartKT = std::get<double>(model->params().at("init_kT"));
        QVERIFY2(std::abs(restartKT / kTReached - 1) < 0.1,
                 qPrintable(QString("%1 vs %2").arg(restartKT).arg(kTReached)));
        QVERIFY(model->tools()->hasPiston()); // the restart keeps the experiment's piston

        // Gravity: a click on the groove sets a downward field.
        auto* gravity = presentChild<QSlider>(window, "lessonGravity");
        QTest::mouseClick(gravity, Qt::LeftButton, {}, QPoint(gravity->width() - 5, gravity->height() / 2));
        QVERIFY(std::get<double>(model->params().at("gravity")) > 0);

        // The readouts are the store's latest row.
        runFrames(window, 6);
        const QStringList texts = window.presentMode()->panel()->readouts()->texts();
        QVERIFY2(texts.contains(QString("N = %1").arg(model->particleCount())), qPrintable(texts.join("; ")));
        window.presentMode()->setActive(false);
        window.document()->setModified(false);
    }

    void fluidPoursAndChoosesTheSpawnTool() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("fluid-write-up")); // an empty tank
        showAt(window, {1280, 800});
        window.presentMode()->setActive(true);
        QTest::qWait(50);
        auto* pour = presentChild<QPushButton>(window, "lessonPour");
        QTest::mousePress(pour, Qt::LeftButton);
        QTest::qWait(400); // held: a block every 150 ms
        QTest::mouseRelease(pour, Qt::LeftButton);
        const std::size_t poured = window.controller()->model()->particleCount();
        QVERIFY2(poured > 0, "holding Pour added no fluid");
        QTest::qWait(300);
        QCOMPARE(window.controller()->model()->particleCount(), poured); // released: it stops
        QTest::mouseClick(presentChild<QPushButton>(window, "lessonSpawnTool"), Qt::LeftButton);
        QCOMPARE(window.viewportCore()->tool(), ui::ViewportTool::Spawn);
        auto* gravity = presentChild<QPushButton>(window, "lessonGravitySwitch");
        QTest::mouseClick(gravity, Qt::LeftButton);
        QCOMPARE(std::get<bool>(window.controller()->model()->params().at("gravity_on")),
                 gravity->isChecked());
        window.presentMode()->setActive(false);
        window.document()->setModified(false);
    }

    void dsmcRunsAndResets() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("dsmc-write-up"));
        showAt(window, {1280, 800});
        window.presentMode()->setActive(true);
        QTest::qWait(50);
        auto* run = presentChild<QPushButton>(window, "lessonRun");
        QTest::mouseClick(run, Qt::LeftButton);
        QVERIFY(window.controller()->isRunning());
        QCOMPARE(run->text(), QString("Pause"));
        QTest::qWait(200);
        QTest::mouseClick(run, Qt::LeftButton);
        QVERIFY(!window.controller()->isRunning());
        QVERIFY(window.controller()->model()->stepCount() > 0);
        QTest::mouseClick(presentChild<QPushButton>(window, "lessonReset"), Qt::LeftButton);
        QCOMPARE(window.controller()->model()->stepCount(), 0);
        window.presentMode()->setActive(false);
    }

    void plotChoiceIsKeptPerScene() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        showAt(window, {1280, 800});
        window.presentMode()->setActive(true);
        QTest::qWait(50);
        auto* chooser = window.presentMode()->panel()->plotChooser();
        QVERIFY(qobject_cast<ui::DistributionPlot*>(window.presentMode()->panel()->currentPlot()));
        const int energy = chooser->findData("energyPlot");
        QVERIFY(energy > 0);
        while (chooser->currentIndex() < energy) QTest::keyClick(chooser, Qt::Key_Down);
        auto* plot = qobject_cast<ui::SeriesPlot*>(window.presentMode()->panel()->currentPlot());
        QVERIFY(plot && plot->spec().objectName == "present_energyPlot");
        window.presentMode()->setActive(false);
        window.presentMode()->setActive(true);
        plot = qobject_cast<ui::SeriesPlot*>(window.presentMode()->panel()->currentPlot());
        QVERIFY(plot && plot->spec().objectName == "present_energyPlot");
        window.presentMode()->setActive(false);
    }
    void restoredLayoutLeavesTheViewportItsRoom() {
        {
            ui::MainWindow wide;
            QVERIFY(wide.openPreset("gas-classroom"));
            showAt(wide, {1280, 800});
            QList<QDockWidget*> plots;
            for (QDockWidget* dock : wide.findChildren<QDockWidget*>())
                if (dock->isVisible() && wide.dockWidgetArea(dock) == Qt::RightDockWidgetArea) plots << dock;
            wide.resizeDocks(plots, QList<int>(plots.size(), 740), Qt::Horizontal); // the user's own layout
            QTest::qWait(50);
            QVERIFY(wide.viewport()->width() < 400);
            QVERIFY(wide.close()); // saves the layout
        }
        ui::MainWindow restored;
        QVERIFY(restored.openPreset("gas-classroom"));
        restored.show();
        QVERIFY(QTest::qWaitForWindowExposed(&restored));
        QTest::qWait(80);
        QCOMPARE(restored.size(), QSize(1280, 800));
        QVERIFY2(restored.viewport()->width() >= 0.5 * restored.width(),
                 qPrintable(QString::number(restored.viewport()->width())));
        QSettings().clear();
    }
};

QTEST_MAIN(TestPresent)
#include "tst_present.moc"
