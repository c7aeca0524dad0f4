// Every plot of every built-in preset, in normal and projector mode, under a real X server: no legend
// covers a data point or a bar, no value-axis label runs past its axis (into a title or the next panel),
// every axis with data has tick values, a log axis loses no point of a quantity that changes sign,
// and after time has run backwards the time series still advance to the right, the backward stretch
// dotted. Each plot is saved as a PNG to look at.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "plots/DistributionPlot.h"
#include "plots/ReadablePlot.h"
#include "plots/SeriesPlot.h"

#include <QDockWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>
#include <qcustomplot.h>

using namespace pl;

namespace {

void runFrames(ui::MainWindow& window, int frames) {
    for (int f = 0; f < frames; ++f) window.controller()->advanceFrame();
    QTest::qWait(60);
}

// Data points and bars of a rect's visible plottables inside area, every point counted.
int dataUnder(QCPAxisRect* rect, const QRectF& area) {
    int count = 0;
    for (QCPAbstractPlottable* p : rect->plottables()) {
        if (!p->visible()) continue;
        if (auto* graph = qobject_cast<QCPGraph*>(p)) {
            for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
                if (std::isfinite(it->value) && area.contains(graph->keyAxis()->coordToPixel(it->key),
                                                              graph->valueAxis()->coordToPixel(it->value)))
                    ++count;
        } else if (auto* bars = qobject_cast<QCPBars*>(p)) {
            for (auto it = bars->data()->constBegin(); it != bars->data()->constEnd(); ++it) {
                if (it->value <= 0) continue;
                const QRectF bar(QPointF(bars->keyAxis()->coordToPixel(it->key - 0.5 * bars->width()),
                                         bars->valueAxis()->coordToPixel(0)),
                                 QPointF(bars->keyAxis()->coordToPixel(it->key + 0.5 * bars->width()),
                                         bars->valueAxis()->coordToPixel(it->value)));
                if (bar.normalized().intersects(area)) ++count;
            }
        }
    }
    return count;
}

// Problems of one plot as sentences; empty when its legends and labels leave its data readable.
QStringList problemsOf(QCustomPlot* plot) {
    QStringList problems;
    plot->replot();            // the layout of the plot as it is drawn now
    QList<QCPLegend*> legends; // inside axis rects or in the plot's own layout
    for (int i = 0; i < plot->plotLayout()->elementCount(); ++i)
        if (auto* legend = qobject_cast<QCPLegend*>(plot->plotLayout()->elementAt(i))) legends << legend;
    for (QCPAxisRect* rect : plot->axisRects())
        for (int i = 0; i < rect->insetLayout()->elementCount(); ++i)
            if (auto* legend = qobject_cast<QCPLegend*>(rect->insetLayout()->elementAt(i))) legends << legend;
    for (QCPAxisRect* rect : plot->axisRects()) {
        for (QCPLegend* legend : std::as_const(legends)) {
            if (!legend->visible() || legend->itemCount() == 0) continue;
            if (const int covered = dataUnder(rect, legend->outerRect()))
                problems << QString("a legend covers %1 data points").arg(covered);
        }
        // Values a reader can read off: at least two labelled ticks on each axis that has data.
        for (QCPAxis* axis : {rect->axis(QCPAxis::atLeft), rect->axis(QCPAxis::atBottom)})
            if (!axis->plottables().isEmpty() && axis->tickVector().size() < 2)
                problems << QString("the axis '%1' has %2 tick values")
                                .arg(axis->label())
                                .arg(axis->tickVector().size());
        // A log axis drops points at or below 0: a quantity that changes sign shows |x| instead.
        for (QCPGraph* graph : rect->graphs()) {
            if (!graph->visible() || graph->valueAxis()->scaleType() != QCPAxis::stLogarithmic) continue;
            int dropped = 0;
            for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
                dropped += it->value < 0;
            if (dropped)
                problems
                    << QString("'%1' has %2 points its log axis cannot show").arg(graph->name()).arg(dropped);
        }
        // A count or a value up to a million is read as a plain number ("molecules  32000", not 3.2E+04).
        static const QRegularExpression exponentOfAPlainNumber("\\d[eE]\\+0?[0-5]\\b");
        for (QCPLegend* legend : std::as_const(legends))
            for (int i = 0; i < legend->itemCount(); ++i)
                if (auto* item = qobject_cast<QCPPlottableLegendItem*>(legend->item(i));
                    item && exponentOfAPlainNumber.match(item->plottable()->name()).hasMatch())
                    problems << QString("the legend writes '%1'").arg(item->plottable()->name());
        // A value label shortened to fit (not merely put on two lines) gives its whole text as the tooltip
        // where it is drawn.
        QCPAxis* y = rect->axis(QCPAxis::atLeft);
        const QString fullLabel = y->property("pl_fullLabel").toString();
        if (QString(y->label()).replace('\n', ' ') != fullLabel) {
            const QPointF onLabel(rect->left() - y->offset() - y->padding() - 0.5 * y->labelPadding() - 4,
                                  rect->center().y());
            if (ui::shortenedTextAt(plot, onLabel) != fullLabel)
                problems << QString("the label '%1' is shortened and its tooltip is not '%2'")
                                .arg(y->label(), fullLabel);
        }
        double length = 0; // of its longest line
        for (const QString& line : y->label().split('\n'))
            length = std::max(length, QFontMetricsF(y->labelFont()).horizontalAdvance(line));
        if (length > rect->height() + 1)
            problems << QString("the label '%1' (%2 px) is longer than its axis (%3 px)")
                            .arg(y->label())
                            .arg(length)
                            .arg(rect->height());
    }
    return problems;
}

} // namespace

class TestPlots : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QDir().mkpath(QString(PARTICLELAB_SCREENSHOT_DIR) + "/plots");
    }

    void everyPlotLeavesItsDataReadable_data() {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<bool>("projector");
        for (const auto& builtin : builtinPresets())
            for (const bool projector : {false, true})
                QTest::newRow(qPrintable(QString("%1 %2").arg(QString::fromStdString(builtin.name),
                                                              projector ? "projector" : "normal")))
                    << QString::fromStdString(builtin.name) << projector;
    }

    void everyPlotLeavesItsDataReadable() {
        QFETCH(QString, preset);
        QFETCH(bool, projector);
        ui::MainWindow window;
        QVERIFY(window.openPreset(preset));
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.setProjectorMode(projector);
        Model* model = window.controller()->model();
        if (model->particleCount() == 0) // the fluid write-up's empty tank: pour a block as a user would
            model->tools()->spawnInRectangle(10, 2, 40, 12);
        runFrames(window, 24); // 8 samples: every plot has curves to place its legend beside
        QStringList failures;
        for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
            if (!dock->toggleViewAction()->isEnabled() || dock->objectName() == "methodsLabDock") continue;
            QCustomPlot* plot = nullptr;
            if (auto* series = qobject_cast<ui::SeriesPlot*>(dock->widget())) plot = series->plot();
            if (auto* histogram = qobject_cast<ui::DistributionPlot*>(dock->widget()))
                plot = histogram->plot();
            if (!plot) continue;
            dock->show();
            dock->raise();
            runFrames(window, 3);
            for (const QString& problem : problemsOf(plot)) failures << dock->objectName() + ": " + problem;
            QVERIFY(plot->toPixmap().save(QString("%1/plots/%2-%3-%4.png")
                                              .arg(PARTICLELAB_SCREENSHOT_DIR, preset, plot->objectName(),
                                                   projector ? "projector" : "normal")));
        }
        window.setProjectorMode(false);
        window.document()->setModified(false);
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
    }

    // Issue 45: on a 1024 × 700 screen the DSMC plots' value labels read "pairs per st…" and
    // "M_2k / M_2k(…". A label too long for its axis goes on two lines before anything is cut.
    void valueLabelsWrapRatherThanEndInAnEllipsis() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("dsmc-bkw"));
        window.resize(1024, 700);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.setProjectorMode(true);
        runFrames(window, 6);
        QStringList checked, cut;
        for (const char* name : {"collisionsPlotDock", "momentsPlotDock"}) {
            auto* dock = window.findChild<QDockWidget*>(name);
            QVERIFY2(dock, name);
            dock->show();
            dock->raise();
            runFrames(window, 3);
            auto* series = qobject_cast<ui::SeriesPlot*>(dock->widget());
            QVERIFY(series);
            series->plot()->replot();
            for (QCPAxisRect* rect : series->plot()->axisRects()) {
                const QString shown = rect->axis(QCPAxis::atLeft)->label().replace(QChar('\n'), " | ");
                checked << QString("%1 (%2 px)").arg(shown).arg(rect->height());
                if (shown.contains(QChar(0x2026))) cut << shown;
            }
        }
        qInfo("%s", qPrintable(checked.join("; ")));
        window.setProjectorMode(false);
        window.document()->setModified(false);
        QVERIFY2(cut.isEmpty(), qPrintable(cut.join("; ")));
    }

    void timeSeriesAdvanceAfterTimeRunsBackwards() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        auto* controller = window.controller();
        QVERIFY(controller->setParameters({{"count_a", 400.0}}).isEmpty());
        controller->reset();
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        ui::SeriesPlot* energy = window.seriesPlots().front();
        QCOMPARE(energy->spec().objectName, QString("energyPlot"));
        window.findChild<QDockWidget*>("energyPlotDock")->raise();
        controller->setStepsPerFrame(5);
        runFrames(window, 30);
        QCOMPARE(energy->plot()->axisRect(0)->axis(QCPAxis::atBottom)->label(), QString("time"));
        controller->setStepsPerFrame(-5);
        runFrames(window, 30);
        QVERIFY(controller->model()->time() < 0.5 * 30 * 5 * 3.5e-4); // it did run back
        QCustomPlot* plot = energy->plot();
        int dotted = 0;
        for (int g = 0; g < plot->graphCount(); ++g) {
            QCPGraph* graph = plot->graph(g);
            double last = -std::numeric_limits<double>::infinity();
            for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it) {
                QVERIFY2(it->key >= last, "a time series ran back over itself");
                last = it->key;
            }
            int finite = 0;
            for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
                finite += std::isfinite(it->value);
            if (graph->visible() && graph->pen().style() == Qt::DotLine && finite >= 5) ++dotted;
        }
        QVERIFY2(dotted >= 3, qPrintable(QString::number(dotted))); // kinetic, potential, total, drift
        QCOMPARE(plot->axisRect(0)->axis(QCPAxis::atBottom)->label(), QString("time run, Σ |Δt|"));
        QVERIFY2(problemsOf(plot).isEmpty(), qPrintable(problemsOf(plot).join("\n")));
        QVERIFY(
            plot->toPixmap().save(QString(PARTICLELAB_SCREENSHOT_DIR) + "/plots/energy-after-reversal.png"));
        window.document()->setModified(false);
    }
};

QTEST_MAIN(TestPlots)
#include "tst_plots.moc"
