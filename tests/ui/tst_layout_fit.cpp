// Layouts that fit a small screen, run on a 1024×700 X screen (CMake starts it): the first window lies
// inside the screen's available area, every shown plot keeps a readable height per panel in normal and
// projector mode (the docks become tabs rather than strips), no tool-bar item falls into the overflow menu,
// present mode's board fits the screen in projector mode, and the window's size comes back on the next
// start, small or large; --measure-fps tells a preset that stopped. The start itself is the real program
// (particlelab --screenshot), so what is checked is what a user's first window gets.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "UiTestSupport.h"
#include "catalog/ModelCatalog.h"
#include "i18n/Translations.h"
#include "present/PresentMode.h"
#include "present/PresentPanel.h"

#include <QAction>
#include <QDockWidget>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QProcess>
#include <QPushButton>
#include <QScreen>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>
#include <numeric>
#include <qcustomplot.h>

using namespace pl;

namespace {

constexpr QSize kScreen(1024, 700);
constexpr int kReadablePlotHeight = 150;

// The window the program opens with the settings in XDG_CONFIG_HOME, as its screenshot shows it.
QSize programWindowSize(const QString& scratch) {
    const QString image = scratch + "/first.png";
    QProcess app;
    app.start(PARTICLELAB_GUI, {"gas-classroom", "--frames", "2", "--screenshot", image});
    if (!app.waitForFinished(60000) || app.exitCode() != 0) {
        qWarning("particlelab: %s", app.readAllStandardError().constData());
        return {};
    }
    return QImage(image).size();
}

// The first built-in preset of every registered kind.
QStringList onePresetPerKind() {
    QStringList names;
    for (const ModelDescriptor& kind : modelCatalog())
        if (!builtinPresetsOf(kind.kind).empty())
            names << QString::fromStdString(builtinPresetsOf(kind.kind).front()->name);
    return names;
}

void showInScreen(ui::MainWindow& window) {
    window.setGeometry(QGuiApplication::primaryScreen()->availableGeometry());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTest::qWait(120); // the docks settle after the first layout
}

} // namespace

class TestLayoutFit : public QObject {
    Q_OBJECT
    QFont baseFont_;
private slots:
    void initTestCase() {
        baseFont_ = QApplication::font();
        const QRect available = QGuiApplication::primaryScreen()->availableGeometry();
        QVERIFY2(available.size() == kScreen,
                 qPrintable(QString("runs on a 1024×700 screen (tests/CMakeLists.txt), not %1×%2")
                                .arg(available.width())
                                .arg(available.height())));
    }
    void init() { QSettings().clear(); }
    void cleanup() {
        QApplication::setFont(baseFont_);
        QSettings().clear();
    }

    void firstWindowFitsTheScreen() {
        const QSize size = programWindowSize(qEnvironmentVariable("XDG_CONFIG_HOME"));
        qInfo("first window %dx%d on a %dx%d screen", size.width(), size.height(), kScreen.width(),
              kScreen.height());
        QVERIFY(!size.isEmpty());
        QVERIFY2(size.width() <= kScreen.width() && size.height() <= kScreen.height(),
                 "the first window is larger than the screen");
        QVERIFY2(size.width() >= 0.9 * kScreen.width(),
                 "the first window leaves most of a small screen unused");
    }

    void sizeComesBack_data() {
        QTest::addColumn<QSize>("size");
        QTest::newRow("small") << QSize(800, 560);
        QTest::newRow("large") << QSize(1000, 680);
    }
    void sizeComesBack() {
        QFETCH(QSize, size);
        {
            ui::MainWindow window;
            QVERIFY(window.openPreset("gas-classroom"));
            window.resize(size);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QTest::qWait(50);
            QCOMPARE(window.size(), size);
            window.document()->setModified(false);
            QVERIFY(window.close()); // as the user closes it: the settings are written
        }
        const QSize next = programWindowSize(qEnvironmentVariable("XDG_CONFIG_HOME"));
        QCOMPARE(next, size);
    }

    void plotsKeepAReadableHeight_data() {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<bool>("projector");
        for (const BuiltinPreset& builtin : builtinPresets())
            for (bool projector : {false, true})
                QTest::newRow(
                    qPrintable(QString::fromStdString(builtin.name) + (projector ? " projector" : "")))
                    << QString::fromStdString(builtin.name) << projector;
    }
    void plotsKeepAReadableHeight() {
        QFETCH(QString, preset);
        QFETCH(bool, projector);
        ui::MainWindow window;
        QVERIFY(window.openPreset(preset));
        showInScreen(window);
        window.setProjectorMode(projector);
        QTest::qWait(150);
        QStringList parts; // what takes the height, for the log
        for (QWidget* part : window.findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly))
            if (part->isVisible() && (qobject_cast<QDockWidget*>(part) || qobject_cast<QToolBar*>(part) ||
                                      part == window.menuBar() || part == window.statusBar()))
                parts << QString("%1 %2+%3 (min %4)")
                             .arg(part->objectName())
                             .arg(part->y())
                             .arg(part->height())
                             .arg(part->minimumSizeHint().height());
        qInfo("window %dx%d, minimum %d: %s", window.width(), window.height(),
              window.minimumSizeHint().height(), qPrintable(parts.join(", ")));
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        QVERIFY2(screen.contains(window.frameGeometry()),
                 qPrintable(QString("the window grew to %1×%2").arg(window.width()).arg(window.height())));
        int plots = 0;
        for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
            if (!dock->isVisible() || dock->isFloating() || dock->objectName() == "parametersDock") continue;
            // Each drawing (a plot of one or two panels) that the dock shows now, not one in a hidden tab.
            for (QCustomPlot* canvas : dock->findChildren<QCustomPlot*>()) {
                if (!canvas->isVisible() || canvas->visibleRegion().isEmpty()) continue;
                ++plots;
                const int panels = std::max(1, canvas->axisRectCount());
                QVERIFY2(canvas->height() >= kReadablePlotHeight * panels,
                         qPrintable(QString("%1: %2 panel(s) in %3 px")
                                        .arg(dock->objectName())
                                        .arg(panels)
                                        .arg(canvas->height())));
            }
        }
        QVERIFY2(plots > 0, "no plot shown");
        QVERIFY(window.viewport()->width() >= 0.4 * window.width());
        window.setProjectorMode(false);
        window.document()->setModified(false);
    }

    // Issue 45: the docks that became tabs in a short window stayed tabs after it was enlarged. Back at
    // the size they stood one above the other, they do so again.
    void docksStackAgainWhenTheWindowGrows() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("dsmc-bkw"));
        const auto shownPlots = [&window] { // the plot docks the right area shows now, not in hidden tabs
            QStringList names;
            for (QDockWidget* dock : window.findChildren<QDockWidget*>())
                if (dock->isVisible() && !dock->visibleRegion().isEmpty() &&
                    window.dockWidgetArea(dock) == Qt::RightDockWidgetArea)
                    names << dock->objectName();
            names.sort();
            return names;
        };
        // The two histograms alone, one above the other, as a layout the user made comes back.
        auto* vx = window.findChild<QDockWidget*>("vxHistogramDock");
        QVERIFY(vx);
        for (QDockWidget* dock : window.findChildren<QDockWidget*>())
            if (window.dockWidgetArea(dock) == Qt::RightDockWidgetArea &&
                dock->objectName() != QLatin1String("speedHistogramDock"))
                dock->close();
        window.removeDockWidget(vx);
        window.addDockWidget(Qt::RightDockWidgetArea, vx, Qt::Vertical);
        vx->show();
        window.resize(kScreen);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTest::qWait(150);
        const QStringList stacked = shownPlots();
        QVERIFY2(stacked.size() >= 2, qPrintable(stacked.join(", ")));
        window.resize(kScreen.width(), 460);
        QTRY_COMPARE(shownPlots().size(), 1);
        window.resize(kScreen);
        QTRY_COMPARE(shownPlots(), stacked);
        window.document()->setModified(false);
    }

    // Issue 45: on a 1024 × 700 screen the methods lab (a floating window of 920 × 680 and its frame)
    // opened past the screen's bottom edge. Opened from the View menu, it lies inside the screen's
    // available area with the frame a window manager adds.
    void theMethodsLabOpensInsideTheScreen() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        showInScreen(window);
        auto* lab = window.findChild<QDockWidget*>("methodsLabDock");
        QVERIFY(lab && lab->isFloating() && !lab->isVisible());
        lab->toggleViewAction()->trigger();
        QTRY_VERIFY(lab->isVisible());
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        // Xvfb has no window manager: the frame one adds (title bar and borders) is counted as well.
        const QRect framed = lab->frameGeometry().adjusted(0, 0, 12, 40);
        qInfo("methods lab at %d,%d %dx%d", lab->x(), lab->y(), lab->width(), lab->height());
        QVERIFY2(screen.contains(framed), qPrintable(QString("%1,%2 %3x%4 with its frame")
                                                         .arg(framed.x())
                                                         .arg(framed.y())
                                                         .arg(framed.width())
                                                         .arg(framed.height())));
        lab->hide();
        window.document()->setModified(false);
    }

    // Present mode in projector mode on the whole 1024×700 screen, as a teacher starts it (Ctrl+Shift+P,
    // then F5), in English and German: every control of each kind's board in reach without scrolling and
    // its plot's data area (inside the axes) at least test::kReadableDataHeight high (before: a 30 px plot,
    // the piston's buttons off screen; then 40–60 px inside the axes of a 150 px plot).
    void presentBoardFitsInProjectorMode_data() {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QString>("language");
        for (const QString& name : onePresetPerKind())
            for (const QString language : {"en", "de"})
                QTest::newRow(qPrintable(QString("%1 %2").arg(name, language))) << name << language;
    }
    void presentBoardFitsInProjectorMode() {
        QFETCH(QString, preset);
        QFETCH(QString, language);
        QVERIFY(ui::installLanguage(language));
        ui::MainWindow window;
        QVERIFY(window.openPreset(preset));
        showInScreen(window);
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QTest::keyClick(window.viewport(), Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
        QTest::keyClick(window.viewport(), Qt::Key_F5);
        QVERIFY(window.presentMode()->isActive());
        window.setGeometry(QGuiApplication::primaryScreen()->geometry()); // full screen, without a WM
        QTest::qWait(250);
        QWidget* panel = window.presentMode()->panel();
        const test::BoardReach reach = test::boardReach(panel, &window);
        qInfo("%dx%d: %d of %d controls in reach, plot heights %s", window.width(), window.height(),
              reach.inReach, reach.controls,
              qPrintable(std::accumulate(reach.plotHeights.begin(), reach.plotHeights.end(), QString(),
                                         [](QString a, int h) { return a + QString::number(h) + " "; })));
        QVERIFY2(reach.inReach == reach.controls, qPrintable("out of reach: " + reach.outOfReach.join(", ")));
        QVERIFY(!reach.plotHeights.isEmpty());
        for (int height : reach.plotHeights)
            QVERIFY2(height >= test::kReadableDataHeight, qPrintable(QString::number(height)));
        const QStringList cut = test::cutOffWidgets(panel, &window);
        QVERIFY2(cut.isEmpty(), qPrintable("cut off: " + cut.join(", ")));
        QTest::keyClick(window.viewport(), Qt::Key_Escape);
        window.setProjectorMode(false);
        window.document()->setModified(false);
        ui::installLanguage("en");
    }

    // --measure-fps on a preset that stops at its run length (dsmc-write-up: 500 steps) measures while the
    // scene ran and says that it stopped, rather than "fps": 0.0.
    void measuringAPresetThatStops() {
        QProcess app;
        app.start(PARTICLELAB_GUI, {"dsmc-write-up", "--measure-fps", "3"});
        QVERIFY(app.waitForFinished(60000));
        QCOMPARE(app.exitCode(), 0);
        const QByteArray out = app.readAllStandardOutput();
        const QJsonObject line = QJsonDocument::fromJson(out.trimmed().split('\n').last()).object();
        qInfo("%s", out.constData());
        QVERIFY2(line.value("stopped").toBool(), out.constData());
        QVERIFY2(line.value("fps").toDouble() > 0, out.constData());
        QVERIFY(line.value("seconds").toDouble() < 3);
    }

    // A message too long to fit beside the status line takes the whole bar while it shows, in projector
    // mode at 1024 px too, and the status line comes back when it goes; a short one leaves it in place.
    void aLongMessageTakesTheWholeStatusBar() {
        ui::MainWindow window;
        QVERIFY(window.document()->open("dsmc-write-up", true));
        window.setProjectorMode(true);
        showInScreen(window);
        auto* line = window.findChild<QLabel*>("statusLine");
        QVERIFY(line && line->isVisible());
        window.statusBar()->showMessage(
            "Run complete: 500 steps. The series and plots keep what was sampled.");
        QVERIFY(!line->isVisible());
        window.statusBar()->clearMessage();
        QVERIFY(line->isVisible());
        window.statusBar()->showMessage("Paused.");
        QVERIFY(line->isVisible());
        window.setProjectorMode(false);
        window.document()->setModified(false);
    }

    void noToolBarItemOverflows_data() {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QString>("language");
        QTest::addColumn<bool>("projector");
        for (const QString& name : onePresetPerKind())
            for (const QString language : {"en", "de"})
                for (bool projector : {false, true})
                    QTest::newRow(
                        qPrintable(QString("%1 %2%3").arg(name, language, projector ? " projector" : "")))
                        << name << language << projector;
    }
    void noToolBarItemOverflows() {
        QFETCH(QString, preset);
        QFETCH(QString, language);
        QFETCH(bool, projector);
        QVERIFY(ui::installLanguage(language)); // before the window: its texts are translated once
        ui::MainWindow window;
        QVERIFY(window.openPreset(preset));
        showInScreen(window);
        window.setProjectorMode(projector);
        QTest::qWait(150);
        QCOMPARE(window.width(), kScreen.width());
        for (QToolBar* bar : window.findChildren<QToolBar*>()) {
            if (!bar->isVisible()) continue;
            qInfo("%s at %d,%d: %d px, needs %d", qPrintable(bar->objectName()), bar->x(), bar->y(),
                  bar->width(), bar->sizeHint().width());
            // QToolBar puts what does not fit behind its extension button ("»").
            for (QToolButton* more : bar->findChildren<QToolButton*>("qt_toolbar_ext_button"))
                QVERIFY2(!more->isVisible(), qPrintable(bar->objectName() + " overflows"));
            for (QAction* action : bar->actions()) {
                QWidget* item = bar->widgetForAction(action);
                if (!action->isVisible() || action->isSeparator() || !item) continue;
                QVERIFY2(item->isVisible() && bar->rect().contains(item->geometry()),
                         qPrintable(QString("%1: %2 is not shown").arg(bar->objectName(), action->text())));
            }
        }
        window.setProjectorMode(false);
        window.document()->setModified(false);
        ui::installLanguage("en");
    }

    // The Parameters dock's first lines, as wide as the dock is at 1024 px: the note on Reset keeps the
    // height its wrapped lines need and Reset now shows its whole text (in German projector mode the note
    // was squeezed to a word a line beside a clipped "zt zurücksetze").
    void parameterBannerFits_data() { noToolBarItemOverflows_data(); }
    void parameterBannerFits() {
        QFETCH(QString, preset);
        QFETCH(QString, language);
        QFETCH(bool, projector);
        QVERIFY(ui::installLanguage(language));
        ui::MainWindow window;
        QVERIFY(window.openPreset(preset));
        showInScreen(window);
        window.setProjectorMode(projector);
        QTest::qWait(150);
        auto* note = window.findChild<QLabel*>("idleLine");
        auto* reset = window.findChild<QPushButton*>("resetNow");
        QVERIFY(note && reset && note->isVisible() && reset->isVisible());
        QVERIFY2(note->height() >= note->heightForWidth(note->width()),
                 qPrintable(QString("the note is %1 px high and needs %2 at %3 px")
                                .arg(note->height())
                                .arg(note->heightForWidth(note->width()))
                                .arg(note->width())));
        QVERIFY2(note->width() >= reset->width(),
                 qPrintable(QString("the note gets %1 px").arg(note->width())));
        QVERIFY2(reset->width() >= reset->sizeHint().width(),
                 qPrintable(
                     QString("Reset now is %1 px of %2").arg(reset->width()).arg(reset->sizeHint().width())));
        window.setProjectorMode(false);
        window.document()->setModified(false);
        ui::installLanguage("en");
    }
};

// The settings live in a scratch XDG_CONFIG_HOME under the program's own names, so the program started
// by the test reads what this process's window wrote.
int main(int argc, char** argv) {
    QTemporaryDir config;
    qputenv("XDG_CONFIG_HOME", config.path().toUtf8());
    QApplication app(argc, argv);
    QApplication::setApplicationName("ParticleLab");
    QApplication::setOrganizationName("ParticleLab");
    TestLayoutFit test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_layout_fit.moc"
