// The wind tunnel in the window, through real mouse and key events: the colour map of a field (hand-made
// and the model's), the field chooser and present mode's buttons setting the `view` parameter, the click
// probe reading the clicked cell, the Profile line tool filling the Profile dock with the field along the
// line, and the tunnel's drag and particle-count docks; screenshots of the particles, the Mach field, the
// probe and the profile are saved to look at.
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "ViewChooser.h"
#include "plots/PlotExport.h"
#include "plots/ProfilePlot.h"
#include "plots/SeriesPlot.h"
#include "present/PresentMode.h"
#include "viewport/FieldOverlay.h"
#include "viewport/Palette.h"
#include "viewport/ViewportCore.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <qcustomplot.h>

using namespace pl;

namespace {

constexpr const char* kPreset = "tunnel-cylinder";
// The preset opens its fields window after 800 steps, once the flow has crossed the domain twice; the
// tests read the fields much earlier (the domain upstream still holds the free stream it started with),
// so that each takes seconds, not minutes.
constexpr double kSampleStart = 30;

// The preset, its fields window opening after kSampleStart steps.
bool openTunnel(ui::MainWindow& window) {
    for (const BuiltinPreset& builtin : builtinPresets())
        if (builtin.name == kPreset) {
            Preset preset = builtin.preset;
            preset.params["sample_start"] = kSampleStart;
            return window.controller()->load(preset).isEmpty();
        }
    return false;
}

QPoint widgetPoint(ui::MainWindow& window, double x, double y) {
    return window.viewportCore()->transform().toWidget(x, y).toPoint();
}

QPointF worldOf(ui::MainWindow& window, QPoint pixel) {
    return window.viewportCore()->transform().toWorld(QPointF(pixel));
}

void saveScreenshot(ui::MainWindow& window, const QString& name) {
    QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
    window.windowImage().save(QString(PARTICLELAB_SCREENSHOT_DIR) + "/tunnel-" + name + ".png");
}

const SampledFields& fieldsOf(ui::MainWindow& window) {
    return *window.controller()->model()->sampledFields();
}

// Runs the model, 20 steps a frame, until the fields window holds `steps` steps.
void sampleFor(ui::MainWindow& window, std::int64_t steps) {
    ui::SimulationController* controller = window.controller();
    controller->setStepsPerFrame(20);
    for (int f = 0; f < 200 && fieldsOf(window).sampledSteps() < steps; ++f) controller->advanceFrame();
    QTest::qWait(50); // queued replots and repaints run, as the event loop does for a user
}

// Picks `text` in a combo box as a user does: click it open, click the entry in its list.
bool pickInCombo(QComboBox* combo, const QString& text) {
    const int row = combo->findText(text);
    if (row < 0) return false;
    QTest::mouseClick(combo, Qt::LeftButton);
    QAbstractItemView* list = combo->view();
    if (!QTest::qWaitFor([list] { return list->isVisible(); })) return false;
    QTest::qWait(QApplication::doubleClickInterval() + 20); // the list ignores a release that follows at once
    const QRect entry = list->visualRect(list->model()->index(row, 0));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, entry.center());
    return QTest::qWaitFor(
        [combo, row] { return combo->currentIndex() == row && !combo->view()->isVisible(); });
}

bool sameValue(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || a == b;
}

} // namespace

class TestTunnelUi : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        test::useCleanTestSettings();
        QApplication::setEffectEnabled(Qt::UI_AnimateCombo, false);
        QApplication::setDoubleClickInterval(100); // how long an opened combo list ignores a release
    }

    void fieldImageIsTheColourMapWithNaNTransparent() {
        // A hand-made 3 × 2 field: each pixel is the palette colour of its cell, row 0 of the image is the
        // top row of cells (the largest y), and the cell without samples lets the background through.
        SceneFieldImage field;
        field.nx = 3;
        field.ny = 2;
        field.value = {0.0f, 0.5f, 1.0f, 0.25f, std::nanf(""), 0.75f};
        field.colours = ColourMap::Thermal;
        const QImage image = ui::fieldImage(field);
        QCOMPARE(image.size(), QSize(3, 2));
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 3; ++i) {
                const float v = field.value[static_cast<std::size_t>(j * 3 + i)];
                const QColor pixel = image.pixelColor(i, 1 - j);
                if (std::isnan(v)) {
                    QCOMPARE(pixel.alpha(), 0);
                    continue;
                }
                QCOMPARE(pixel.alpha(), 255);
                QCOMPARE(pixel.rgb(), ui::paletteColour(ColourMap::Thermal, v).rgb());
            }
        field.value.pop_back(); // a field whose values do not fill its grid draws nothing
        QVERIFY(ui::fieldImage(field).isNull());
        // The probe's numbers: four significant digits, powers of ten for the very large, a dash for NaN.
        QCOMPARE(ui::formatFieldValue(2634.0), QStringLiteral("2634"));
        QCOMPARE(ui::formatFieldValue(1.0e21), QStringLiteral("1.00 × 10²¹"));
        QCOMPARE(ui::formatFieldValue(9.999e20), QStringLiteral("1.00 × 10²¹"));
        QCOMPARE(ui::formatFieldValue(-2.5e-7), QStringLiteral("-2.50 × 10⁻⁷"));
        QCOMPARE(ui::formatFieldValue(std::nan("")), QStringLiteral("—"));
        // In the UI's language: the German decimal comma.
        const QLocale before;
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        QCOMPARE(ui::formatFieldValue(1.0e21), QStringLiteral("1,00 × 10²¹"));
        QCOMPARE(ui::formatFieldValue(2.5), QStringLiteral("2,5"));
        QLocale::setDefault(before);
    }

    void choosingMachShowsTheMachField() {
        ui::MainWindow window;
        QVERIFY(openTunnel(window));
        QVERIFY(test::showActive(window));
        sampleFor(window, 20);
        saveScreenshot(window, "particles");
        QComboBox* chooser = window.viewChooser()->combo();
        QVERIFY(chooser->isVisible());
        QVERIFY(pickInCombo(chooser, ui::viewChoiceText("mach")));
        QCOMPARE(std::get<std::string>(window.controller()->model()->params().at("view")),
                 std::string("mach"));
        QVERIFY(!window.isWindowModified());        // Show is a view of the experiment, not an edit of it
        const QImage shot = window.viewportImage(); // paints the frame: the core's snapshot is this one
        const SceneView& scene = window.viewportCore()->scene();
        QVERIFY(scene.field.has_value());
        QVERIFY(!scene.drawParticles);
        QVERIFY(scene.field->maximum > scene.field->minimum);
        // Upstream of the bow shock the flow is uniform: there the viewport shows the palette colour of
        // the field's value (cells near each other differ by sampling noise only, hence the tolerance).
        const SceneFieldImage& field = *scene.field;
        const int i = field.nx / 10, j = field.ny - 1 - field.ny / 10;
        const double x = field.left + (i + 0.5) * (field.right - field.left) / field.nx;
        const double y = field.bottom + (j + 0.5) * (field.top - field.bottom) / field.ny;
        const float value = field.value[static_cast<std::size_t>(j) * field.nx + i];
        QVERIFY(std::isfinite(value));
        const QColor expected = ui::paletteColour(field.colours, value);
        const QColor shown = shot.pixelColor(widgetPoint(window, x, y) * shot.devicePixelRatio());
        const int difference = std::abs(shown.red() - expected.red()) +
                               std::abs(shown.green() - expected.green()) +
                               std::abs(shown.blue() - expected.blue());
        QVERIFY2(difference < 60, qPrintable(QString("%1 vs %2").arg(shown.name(), expected.name())));
        // The View menu's entries follow the choice, whichever control made it.
        bool checked = false;
        for (QAction* action : window.viewChooser()->menu()->actions())
            if (action->data().toString() == "mach") checked = action->isChecked();
        QVERIFY(checked);
        saveScreenshot(window, "mach");

        // Presenting, the lesson's buttons choose the field: a click on "Number density" shows it.
        QTest::keyClick(window.viewport(), Qt::Key_F5);
        QVERIFY(window.presentMode()->isActive());
        auto* density = window.findChild<QPushButton*>("lessonView-density");
        QVERIFY(density && QTest::qWaitFor([density] { return density->isVisible(); }));
        QVERIFY(window.findChild<QPushButton*>("lessonView-mach")->isChecked());
        QTest::mouseClick(density, Qt::LeftButton);
        QCOMPARE(std::get<std::string>(window.controller()->model()->params().at("view")),
                 std::string("density"));
        QVERIFY(density->isChecked());
        QCOMPARE(chooser->currentData().toString(), QStringLiteral("density"));
        QTest::keyClick(window.viewport(), Qt::Key_Escape);
        QVERIFY(QTest::qWaitFor([&window] { return !window.presentMode()->isActive(); }));
    }

    void probeShowsTheValuesOfTheClickedCell() {
        ui::MainWindow window;
        QVERIFY(openTunnel(window));
        QVERIFY(test::showActive(window));
        sampleFor(window, 20);
        ui::ViewportCore* core = window.viewportCore();
        QWidget* view = window.viewport();
        const FieldGrid density = fieldsOf(window).field("n");
        QCOMPARE(core->tool(), ui::ViewportTool::Drag);

        // Press at the centre of a cell upstream, then move to another one while the button is held.
        const auto cellCentre = [&](int i, int j) {
            return widgetPoint(window, density.left + (i + 0.5) * density.dx(),
                               density.bottom + (j + 0.5) * density.dy());
        };
        const auto expectValuesOfCell = [&](QPoint pixel) {
            const QPointF world = worldOf(window, pixel);
            const int i = static_cast<int>(std::floor((world.x() - density.left) / density.dx()));
            const int j = static_cast<int>(std::floor((world.y() - density.bottom) / density.dy()));
            const QStringList text = core->probeText();
            QVERIFY(core->probePoint().has_value());
            QVERIFY(std::abs(core->probePoint()->x() - world.x()) < 1e-12);
            // Every field the model samples, each read from its grid at the clicked cell.
            for (const FieldChoice& choice : fieldsOf(window).fieldChoices()) {
                const FieldGrid grid = fieldsOf(window).field(choice.name);
                const double v = grid.values[static_cast<std::size_t>(j) * grid.nx + i];
                const QString line = QString::fromStdString(choice.label) + ": " + ui::formatFieldValue(v);
                QVERIFY2(text.filter(line).size() == 1, qPrintable(line + " in " + text.join(" | ")));
            }
        };
        QTest::mousePress(view, Qt::LeftButton, {}, cellCentre(3, density.ny / 2));
        expectValuesOfCell(cellCentre(3, density.ny / 2));
        QTest::mouseMove(view, cellCentre(6, density.ny / 4));
        expectValuesOfCell(cellCentre(6, density.ny / 4));
        QTest::mouseRelease(view, Qt::LeftButton, {}, cellCentre(6, density.ny / 4));
        QVERIFY(core->probePoint().has_value()); // it stays to be read
        QTest::qWait(50);
        saveScreenshot(window, "probe");

        // A right click closes it; a press on the body drags the body and opens no probe.
        QTest::mouseClick(view, Qt::RightButton, {}, cellCentre(6, density.ny / 4));
        QVERIFY(!core->probePoint());
        const Obstacle body = window.controller()->tools()->obstacles().at(0);
        const double grabY = body.y + 0.5 * body.radius; // the body's upper half: the lower is outside
        QTest::mousePress(view, Qt::LeftButton, {}, widgetPoint(window, body.x, grabY));
        QTest::mouseMove(view, widgetPoint(window, body.x, grabY + 0.25 * body.radius));
        QTest::mouseRelease(view, Qt::LeftButton, {},
                            widgetPoint(window, body.x, grabY + 0.25 * body.radius));
        QVERIFY(!core->probePoint());
        QVERIFY(window.controller()->tools()->obstacles().at(0).y > body.y);
    }

    void profileLineFillsTheProfileDock() {
        ui::MainWindow window;
        QVERIFY(openTunnel(window));
        QVERIFY(test::showActive(window));
        auto* dock = window.findChild<QDockWidget*>("profileDock");
        QVERIFY(dock && dock->toggleViewAction()->isEnabled());
        sampleFor(window, 20);
        ui::ProfilePlot* profile = window.profilePlot();
        QVERIFY(profile->visibleRegion().isEmpty()); // tabbed behind the scene's first plot

        // The Profile line tool from its key, then the stagnation line: from upstream to the body's nose.
        QWidget* view = window.viewport();
        QTest::keyClick(view, Qt::Key_7);
        QCOMPARE(window.viewportCore()->tool(), ui::ViewportTool::ProfileLine);
        const Obstacle body = window.controller()->tools()->obstacles().at(0);
        const FieldGrid before = fieldsOf(window).field("n");
        // The body sits on the symmetry plane (the bottom side): the line runs along the first row of cells.
        const double y = body.y + 0.5 * before.dy();
        const QPoint start = widgetPoint(window, before.left + 0.5 * before.dx(), y);
        const QPoint end = widgetPoint(window, body.x - 1.05 * body.radius, y);
        QTest::mousePress(view, Qt::LeftButton, {}, start);
        QTest::mouseMove(view, (start + end) / 2);
        QTest::mouseMove(view, end);
        QTest::mouseRelease(view, Qt::LeftButton, {}, end);
        QVERIFY(window.viewportCore()->profileLine().has_value());
        QTest::qWait(20);
        QVERIFY(!profile->visibleRegion().isEmpty()); // a line just drawn brings its dock to the front
        QVERIFY(pickInCombo(profile->fieldChooser(), "Number density"));
        QTest::qWait(50);

        // The dock holds the density along the line as profileAlong() reads it from the grid.
        const QLineF line(worldOf(window, start), worldOf(window, end));
        const FieldGrid grid = fieldsOf(window).field("n");
        const int samples = ui::ProfilePlot::samplesAlong(line.length(), grid.dx(), grid.dy());
        QVERIFY(samples >= 2 * static_cast<int>(line.length() / grid.dx()));
        const FieldProfile expected = profileAlong(grid, line.x1(), line.y1(), line.x2(), line.y2(), samples);
        QCPGraph* graph = profile->plot()->graph(0);
        QCOMPARE(graph->dataCount(), samples);
        for (int k = 0; k < samples; ++k) {
            const auto point = graph->data()->at(k);
            QVERIFY(std::abs(point->key - expected.distance[static_cast<std::size_t>(k)]) < 1e-12);
            QVERIFY2(sameValue(point->value, expected.values[static_cast<std::size_t>(k)]),
                     qPrintable(QString::number(k)));
        }
        // Upstream the line reads the free stream. Over the first quarter of the line (8 cells) the mean
        // density has a sampling noise of about 6 %: 8 molecules a cell, a molecule crossing a cell in
        // about 4 steps, so 20 steps give 5 independent looks at each cell, 8 · 5 · 8 = 320 counts in all
        // (Poisson: 1/√320); 20 % is more than three of those.
        const double stream = std::get<double>(window.controller()->model()->params().at("stream_density"));
        double upstream = 0;
        const int quarter = samples / 4;
        for (int k = 0; k < quarter; ++k) upstream += expected.values[static_cast<std::size_t>(k)] / quarter;
        QVERIFY2(std::abs(upstream / stream - 1) < 0.2, qPrintable(QString::number(upstream)));

        // The CSV export writes one row per point under a header.
        QTemporaryDir dir;
        const QString csv = dir.filePath("profile.csv");
        QVERIFY(ui::savePlotCsv(profile->plot(), csv).isEmpty());
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(file.readAll()).trimmed().split('\n').size(), samples + 1);
        saveScreenshot(window, "profile");
    }

    void dragAndParticleDocksFollowTheTunnel() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-write-up"));
        QVERIFY(test::showActive(window));
        auto* profileDock = window.findChild<QDockWidget*>("profileDock");
        QVERIFY(!profileDock->toggleViewAction()->isEnabled()); // no sampled fields in the gas
        QVERIFY(!window.viewChooser()->combo()->isVisible());
        QVERIFY(openTunnel(window));
        QVERIFY(profileDock->toggleViewAction()->isEnabled());
        QVERIFY(window.viewChooser()->combo()->isVisible());
        // One step a frame, a row every third frame: 10 rows, as the docks get them while time runs.
        ui::SimulationController* controller = window.controller();
        controller->setStepsPerFrame(1);
        for (int f = 0; f < 30; ++f) controller->advanceFrame();
        const auto graphNamed = [&window](const QString& plotName, const QString& curve) -> QCPGraph* {
            for (ui::SeriesPlot* plot : window.seriesPlots())
                if (plot->spec().objectName == plotName) {
                    auto* dock = window.findChild<QDockWidget*>(plotName + "Dock");
                    if (!dock || !dock->toggleViewAction()->isEnabled()) return nullptr;
                    dock->raise(); // a tabbed-away plot catches up when it is shown
                    QTest::qWait(50);
                    for (int g = 0; g < plot->plot()->graphCount(); ++g) { // named "drag  6.006"
                        const QString name = plot->plot()->graph(g)->name();
                        if (name == curve || name.startsWith(curve + "  ")) return plot->plot()->graph(g);
                    }
                }
            return nullptr;
        };
        QCPGraph* drag = graphNamed("forcesPlot", "drag");
        QVERIFY(drag);
        QVERIFY2(drag->dataCount() >= 10, qPrintable(QString::number(drag->dataCount())));
        // Argon at Mach 10 hits the cylinder from the left: the drag points downstream from the first step.
        QVERIFY2((drag->data()->end() - 1)->value > 0,
                 qPrintable(QString::number((drag->data()->end() - 1)->value)));
        QCPGraph* molecules = graphNamed("particlesPlot", "molecules");
        QVERIFY(molecules);
        QCOMPARE(molecules->dataCount(), drag->dataCount());
        // The last row was sampled after the last step: it counts the molecules there are now.
        QCOMPARE((molecules->data()->end() - 1)->value, double(controller->model()->particleCount()));
    }
};

QTEST_MAIN(TestTunnelUi)
#include "tst_tunnel_ui.moc"
