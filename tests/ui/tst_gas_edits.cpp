// The gas's deliberate edits through real keys and clicks, on the CPU and the GL model: an Add-disc click
// onto the disks changes neither their energy nor the Energy dock's drift, and Reset after the piston
// moved gives the box and the Piston position field back as set. Screenshots to look at are saved.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "gas/GasModel.h"
#include "panels/ParameterPanel.h"
#include "viewport/ViewportCore.h"

#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QScrollArea>
#include <QtTest>
#include <algorithm>

using namespace pl;

namespace {

void saveScreenshot(ui::MainWindow& window, const QString& name) {
    QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
    window.windowImage().save(QString(PARTICLELAB_SCREENSHOT_DIR) + "/" + name + ".png");
}

void press(int key, Qt::KeyboardModifiers modifiers = {}) {
    QTest::keyClick(QApplication::focusWidget(), Qt::Key(key), modifiers);
}

// The last row's value of a column of the plots' series.
double lastOf(ui::SimulationController& controller, const char* column) {
    const QVector<double> values = controller.series()->values(controller.series()->column(column));
    return values.isEmpty() ? qQNaN() : values.back();
}

} // namespace

class TestGasEdits : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useCleanTestSettings(); }

    void init() {
        QFETCH(QString, backend);
        window_ = std::make_unique<ui::MainWindow>();
        window_->controller()->setBackend(backend == "gl" ? gl::Backend::Gl : gl::Backend::Cpu);
        QVERIFY(window_->openPreset("gas-classroom"));
        QVERIFY(test::showActive(*window_));
        if (window_->controller()->model()->backend() != backend.toStdString())
            QSKIP("no GL 4.3 context for the gas here");
        window_->controller()->setStepsPerFrame(20);
    }

    void cleanup() {
        window_->controller()->pause();
        window_->document()->setModified(false); // no "save changes?" question on close
        window_.reset();
    }

    // gas-classroom, key 3, one click in the gas: before, E 1250 → 1322 (+5.8 %), kT 0.474 → 0.500 and
    // a drift of 0.058 that stayed, as the disks under the disc were pushed into their neighbours.
    void addDiscClickKeepsTheEnergy_data() { rows(); }
    void addDiscClickKeepsTheEnergy() {
        auto& controller = *window_->controller();
        for (int f = 0; f < 6; ++f) controller.advanceFrame(); // off the lattice
        const double e0 = lastOf(controller, "total"), kT0 = lastOf(controller, "kT");

        press(Qt::Key_3);
        QCOMPARE(window_->viewportCore()->tool(), ui::ViewportTool::AddDisc);
        QWidget* view = window_->viewport();
        const QPoint at = window_->viewportCore()->transform().toWidget(0.013, -0.021).toPoint();
        QTest::mouseMove(view, at);
        QTest::mouseClick(view, Qt::LeftButton, {}, at);
        QCOMPARE(controller.tools()->obstacles().size(), std::size_t(1));
        QCOMPARE(controller.model()->particleCount(), std::size_t(2500));
        QTest::qWait(50);
        saveScreenshot(*window_, "add-disc-placed-" + QString(QTest::currentDataTag()));

        for (int f = 0; f < 15; ++f) controller.advanceFrame(); // 300 steps: a row every 3 frames
        const double e1 = lastOf(controller, "total"), kT1 = lastOf(controller, "kT");
        const double drift = lastOf(controller, "energy_drift");
        qInfo("%s: E %.1f -> %.1f, kT %.4f -> %.4f, drift %.2e", controller.model()->backend().c_str(), e0,
              e1, kT0, kT1, drift);
        QVERIFY2(std::abs(e1 / e0 - 1) < 0.01, qPrintable(QString::number(e1)));
        QVERIFY2(std::abs(kT1 / kT0 - 1) < 0.02, qPrintable(QString::number(kT1)));
        QVERIFY2(drift < 0.002, qPrintable(QString::number(drift)));
        QTest::qWait(50);
        saveScreenshot(*window_, "add-disc-after-" + QString(QTest::currentDataTag()));
    }

    // Tick Piston, Ctrl+Left, Ctrl+Right, Ctrl+R: before, the moving piston wrote its position into the
    // Piston position field, and the reset gas filled only the box left of it.
    void resetAfterTheClassroomPistonGivesTheWholeBox_data() { rows(); }
    void resetAfterTheClassroomPistonGivesTheWholeBox() {
        auto& controller = *window_->controller();
        auto* field = qobject_cast<QDoubleSpinBox*>(window_->parameters()->editor("piston_x"));
        auto* tick = qobject_cast<QCheckBox*>(window_->parameters()->editor("piston_enabled"));
        QVERIFY(field && tick);
        const double set = std::get<double>(controller.parameterValues().at("piston_x"));
        QVERIFY(controller.setParameters({{"piston_speed_factor", 10.0}}).isEmpty()); // a short test
        for (QWidget* w = tick; w; w = w->parentWidget())
            if (auto* scroll = qobject_cast<QScrollArea*>(w)) scroll->ensureWidgetVisible(tick);
        QTest::mouseClick(tick, Qt::LeftButton, {}, QPoint(8, tick->height() / 2));
        QVERIFY(controller.tools()->hasPiston());

        press(Qt::Key_Left, Qt::ControlModifier);
        QCOMPARE(controller.tools()->pistonDirection(), -1);
        for (int f = 0; f < 100 && controller.tools()->pistonX() > 0.5; ++f) controller.advanceFrame();
        QVERIFY2(controller.tools()->pistonX() <= 0.5,
                 qPrintable(QString::number(controller.tools()->pistonX())));
        press(Qt::Key_Right, Qt::ControlModifier);
        QCOMPARE(controller.tools()->pistonDirection(), 1);
        for (int f = 0; f < 3; ++f) controller.advanceFrame();
        QTest::qWait(50);
        saveScreenshot(*window_, "piston-moved-" + QString(QTest::currentDataTag()));
        const double moved = controller.tools()->pistonX();
        QCOMPARE(field->value(), set); // the field shows what was set, not the moving piston
        QCOMPARE(std::get<double>(controller.parameterValues().at("piston_x")), set);

        press(Qt::Key_R, Qt::ControlModifier);
        QCOMPARE(controller.tools()->pistonX(), set);
        QCOMPARE(controller.tools()->pistonDirection(), 0);
        QCOMPARE(field->value(), set);
        const GasState& s = static_cast<GasModel*>(controller.model())->state();
        const double right = *std::max_element(s.x.begin(), s.x.end());
        qInfo("piston at %.4f before Reset; after it at %.4f, the rightmost disk at %.4f", moved,
              controller.tools()->pistonX(), right);
        QVERIFY2(right > 0.9 * set, qPrintable(QString::number(right)));
        QTest::qWait(50);
        saveScreenshot(*window_, "piston-reset-" + QString(QTest::currentDataTag()));
    }

private:
    static void rows() {
        QTest::addColumn<QString>("backend");
        QTest::newRow("cpu") << QStringLiteral("cpu");
        QTest::newRow("gl") << QStringLiteral("gl");
    }

    std::unique_ptr<ui::MainWindow> window_;
};

QTEST_MAIN(TestGasEdits)
#include "tst_gas_edits.moc"
