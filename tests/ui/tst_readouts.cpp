// Readouts tell the truth: a value that waits for Reset stays out of the simulated state (kT, pressure
// and plots keep describing the disks as they move); Reset applies it and gives the preset's count back
// after spawning; after a blow-up Play and Step are off and the viewport says to Reset; the colour scale
// follows a heated gas unless fixed.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "catalog/ModelCatalog.h"
#include "i18n/Translations.h"
#include "panels/ParameterPanel.h"
#include "present/PresentReadouts.h"
#include "viewport/ViewportCore.h"

#include <QAbstractSpinBox>
#include <QAccessible>
#include <QLineEdit>
#include <QScrollArea>
#include <QSlider>
#include <QWheelEvent>
#include <QtTest>

using namespace pl;

namespace {

double lastValue(ui::MainWindow& window, const char* column) {
    const int c = window.controller()->series()->column(column);
    const QVector<double> values = window.controller()->series()->values(c);
    return c < 0 || values.isEmpty() ? qQNaN() : values.back();
}

void runFrames(ui::MainWindow& window, int frames) {
    for (int f = 0; f < frames; ++f) window.controller()->advanceFrame();
    QTest::qWait(20);
}

// Pixels of the notice's orange frame (ScenePainter's paintNotice).
int noticePixels(const QImage& image) {
    int count = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2) {
            const QColor c = image.pixelColor(x, y);
            count += c.red() > 200 && c.green() > 90 && c.green() < 150 && c.blue() < 90;
        }
    return count;
}

} // namespace

class TestReadouts : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        test::useCleanTestSettings();
        QVERIFY(ui::installLanguage("en")); // as the app starts: English with its plural forms
    }

    // The case: Mass (A) = 25 typed in while the gas runs. Before, kT jumped 0.47 → 11.2 with the
    // histogram unchanged; the mass now waits in the panel until Reset.
    void aValueThatWaitsForResetLeavesTheReadoutsAlone() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(test::showActive(window));
        runFrames(window, 9);
        const double kT = lastValue(window, "kT");
        const double mass = std::get<double>(window.controller()->model()->params().at("mass_a"));
        QVERIFY(kT > 0);

        test::typeInto(window.parameters()->editor("mass_a"), "25");
        QCOMPARE(std::get<double>(window.controller()->model()->params().at("mass_a")), mass);
        QCOMPARE(std::get<double>(window.controller()->parameterValues().at("mass_a")), 25.0);
        QCOMPARE(window.controller()->pendingUntilReset().size(), std::size_t(1));
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(window.parameters()->editor("mass_a"))->text(),
                 QString("25"));
        runFrames(window, 9);
        QVERIFY2(std::abs(lastValue(window, "kT") / kT - 1) < 0.2,
                 qPrintable(QString("kT %1 → %2").arg(kT).arg(lastValue(window, "kT"))));

        window.controller()->reset(); // now the disks have it
        QCOMPARE(std::get<double>(window.controller()->model()->params().at("mass_a")), 25.0);
        QVERIFY(window.controller()->pendingUntilReset().empty());
        window.document()->setModified(false);
    }

    // A saved preset keeps what was typed, also while it waits.
    void aWaitingValueIsSavedWithThePreset() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(window.controller()->setParameters({{"mass_a", 3.0}}).isEmpty());
        QCOMPARE(std::get<double>(window.controller()->experimentPreset().params.at("mass_a")), 3.0);
        window.document()->setModified(false);
    }

    // Spawned disks are a lesson's moment, not the experiment: Reset gives the preset's count back.
    void resetGivesThePresetsCountBack() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        const std::size_t preset = window.controller()->model()->particleCount();
        QVERIFY(window.controller()->model()->tools()->spawnInRectangle(-5, -5, 5, 5).starts_with("added"));
        QVERIFY(window.controller()->model()->particleCount() > preset);
        window.controller()->reset();
        QCOMPARE(window.controller()->model()->particleCount(), preset);
        // A count typed in is what Reset builds.
        QVERIFY(window.controller()->setParameters({{"count_a", 1200.0}}).isEmpty());
        window.controller()->reset();
        QCOMPARE(window.controller()->model()->particleCount(), std::size_t(1200));
        window.document()->setModified(false);
    }

    // A blow-up: Play, Space and Step do nothing until Reset, so they are off, and the viewport says why.
    void afterABlowUpPlayIsOffAndTheViewportSaysReset() {
        test::MessageBoxAnswerer dialogs;
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(test::showActive(window));
        auto* play = window.findChild<QAction*>("playAction");
        QVERIFY(play && play->isEnabled());
        QCOMPARE(noticePixels(window.viewportImage()), 0);
        // dt·ω = 2.5 > 2: the panel refuses it (tst_parameterpanel), so the model is given it directly, as a
        // preset run with --allow-unstable would have it.
        window.controller()->model()->setParams({{"dt", 0.0056}});
        window.controller()->setStepsPerFrame(100);
        for (int f = 0; f < 200 && !window.controller()->model()->failure(); ++f)
            window.controller()->advanceFrame();
        QVERIFY(window.controller()->model()->failure());
        QTRY_VERIFY(!dialogs.texts.isEmpty()); // the dialog that names the cause
        QVERIFY(!play->isEnabled());
        QTest::keyClick(window.viewport(), Qt::Key_Space);
        QVERIFY(!window.controller()->isRunning());
        QVERIFY(noticePixels(window.viewportImage()) > 100);

        QVERIFY(window.controller()->setParameters({{"dt", 0.002}}).isEmpty());
        window.controller()->reset();
        QVERIFY(!window.controller()->model()->failure());
        QVERIFY(play->isEnabled());
        QCOMPARE(noticePixels(window.viewportImage()), 0);
        window.document()->setModified(false);
    }

    // Heat acts while it is held: a press on the groove (which steps the handle on) and its release leave
    // no heater running, nor does the wheel turn one on.
    void heatSpringsBackHoweverItWasMoved() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(test::showActive(window));
        auto* heat = window.findChild<QSlider*>("heatSlider");
        QVERIFY(heat && heat->isVisible());
        const QPoint rightOfHandle(heat->width() - 4, heat->height() / 2);
        QTest::mousePress(heat, Qt::LeftButton, {}, rightOfHandle);
        QVERIFY(heat->value() > 0);
        QTest::mouseRelease(heat, Qt::LeftButton, {}, rightOfHandle, 300);
        QCOMPARE(heat->value(), 0);
        QWheelEvent wheel(QPointF(rightOfHandle), heat->mapToGlobal(QPointF(rightOfHandle)), {},
                          QPoint(0, 120), Qt::NoButton, {}, Qt::NoScrollPhase, false);
        QApplication::sendEvent(heat, &wheel);
        QCOMPARE(heat->value(), 0);
        window.document()->setModified(false);
    }

    // Heated to about four times its temperature, the gas keeps a gradient of colours on the automatic
    // scale; the fixed scale shows it red hot.
    void theColourScaleFollowsAHeatedGas() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        QVERIFY(test::showActive(window));
        ui::ViewportCore* core = window.viewportCore();
        auto colourTop = [&] {
            (void)window.viewportImage(); // a paint applies the scale
            return core->scene().colourMax;
        };
        const double start = colourTop();
        window.controller()->model()->tools()->scaleKineticEnergy(4.0);
        for (int frame = 0; frame < 40; ++frame) colourTop(); // the scale settles over frames
        QVERIFY2(colourTop() > 1.7 * start, qPrintable(QString("%1 → %2").arg(start).arg(colourTop())));
        auto* automatic = window.findChild<QAction*>("automaticColourScaleAction");
        QVERIFY(automatic && automatic->isChecked());
        automatic->trigger();
        QCOMPARE(colourTop(), start);
        automatic->trigger();
        window.document()->setModified(false);

        // The fluid's and the tunnel's scales are designed fixed ones: a dam break in motion keeps its top.
        QVERIFY(window.openPreset("fluid-dam-break"));
        const double fluidTop = colourTop();
        for (int frame = 0; frame < 20; ++frame) window.controller()->advanceFrame();
        QCOMPARE(colourTop(), fluidTop);
        window.document()->setModified(false);
    }
    // The viewport in words for a screen reader, from each kind's registration alone: its title as the
    // accessible name, and as the description the particle count, what the colour shows and present mode's
    // readouts with their latest values, kept current while the run goes (it was an empty node before).
    void theViewportDescribesItsScene_data() {
        QTest::addColumn<QString>("preset");
        for (const ModelDescriptor& kind : modelCatalog())
            if (!kind.contractPreset.empty())
                QTest::newRow(kind.kind.c_str()) << QString::fromStdString(kind.contractPreset);
    }
    void theViewportDescribesItsScene() {
        QFETCH(QString, preset);
        ui::MainWindow window;
        QVERIFY(window.openPreset(preset));
        QVERIFY(test::showActive(window));
        runFrames(window, 5);
        window.viewportCore()->describe(); // at once, not at the next second's frame
        const Model& model = *window.controller()->model();
        QAccessibleInterface* node = QAccessible::queryAccessibleInterface(window.viewport());
        QVERIFY(node);
        QCOMPARE(node->text(QAccessible::Name), "Scene: " + ui::coreText(findModel(model.kind())->title));
        const QString description = node->text(QAccessible::Description);
        QVERIFY2(description.contains(QString("%1 particles.").arg(model.particleCount())),
                 qPrintable(description));
        int readouts = 0;
        for (const ui::ReadoutSpec& spec : ui::readoutSpecsFor(model))
            if (window.controller()->series()->column(spec.column) >= 0 && !spec.needsBodies) {
                QVERIFY2(description.contains(spec.name + " = "), qPrintable(spec.name + ": " + description));
                ++readouts;
            }
        QVERIFY(readouts >= 2);
        QVERIFY2(!description.contains("nan") && !description.contains("E+"), qPrintable(description));

        // A second later the numbers are the run's new ones (each kind's time or state moves on).
        QTest::qWait(1100);
        runFrames(window, 20);
        (void)window.viewportImage(); // a frame describes the scene once a second
        QVERIFY2(node->text(QAccessible::Description) != description,
                 qPrintable(description + " | " + node->text(QAccessible::Description)));
        window.document()->setModified(false);
    }

    // In German, as the rest of the window: the name and the sentences come through the catalogue.
    void theSceneIsDescribedInTheUiLanguage() {
        QVERIFY(ui::installLanguage("de"));
        {
            ui::MainWindow window;
            QVERIFY(window.openPreset("gas-classroom"));
            QVERIFY(test::showActive(window));
            runFrames(window, 5);
            window.viewportCore()->describe();
            const QString name = window.viewport()->accessibleName(),
                          description = window.viewport()->accessibleDescription();
            QVERIFY2(name.startsWith("Szene: "), qPrintable(name));
            QVERIFY2(description.contains("Teilchen.") && description.contains("Farbe"),
                     qPrintable(description));
            window.document()->setModified(false);
        }
        QVERIFY(ui::installLanguage("en"));
    }
};

QTEST_MAIN(TestReadouts)
#include "tst_readouts.moc"
