// SeriesPlot: graphs bound to store columns by name when a model is loaded; new rows reach the graphs at
// once, the drawing follows at the live replot rate (LiveReplot.h).
#include "SeriesPlot.h"

#include "LiveReplot.h"
#include "PlotExport.h"
#include "PlotStyle.h"
#include "ReadablePlot.h"
#include "SimulationController.h"

#include <QLocale>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <qcustomplot.h>

namespace pl::ui {

SeriesPlot::SeriesPlot(SimulationController* controller, SeriesPlotSpec spec, QWidget* parent)
    : QWidget(parent), controller_(controller), spec_(std::move(spec)), plot_(new QCustomPlot(this)) {
    plot_->setObjectName(spec_.objectName);
    plot_->setAutoAddPlottableToLegend(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(plot_);
    installPlotExportMenu(plot_);
    keepDataReadable(plot_);
    connect(controller->series(), &SeriesStore::restarted, this, &SeriesPlot::rebuild);
    connect(controller->series(), &SeriesStore::appended, this, &SeriesPlot::refresh);
    rebuild();
}

void SeriesPlot::addPanel(QCPAxisRect* rect, const SeriesPanel& panel, QCPLegend* legend) {
    const SeriesStore* store = controller_->series();
    rect->axis(QCPAxis::atLeft)->setLabel(panel.yLabel);
    rect->axis(QCPAxis::atBottom)->setLabel(panel.xLabel.isEmpty() ? tr("time") : panel.xLabel);
    if (panel.logarithmic) {
        rect->axis(QCPAxis::atLeft)->setScaleType(QCPAxis::stLogarithmic);
        rect->axis(QCPAxis::atLeft)->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
        rect->axis(QCPAxis::atLeft)->setNumberFormat("eb"); // 10⁻⁴ rather than 0.0001
        rect->axis(QCPAxis::atLeft)->setNumberPrecision(0);
    }
    const int xColumn = store->column(panel.xColumn);
    const bool timePanel = !panel.profile && panel.xColumn == QLatin1String("time");
    QCPAxis* x = rect->axis(QCPAxis::atBottom);
    QCPAxis* y = rect->axis(QCPAxis::atLeft);
    for (const auto& curve : panel.curves) {
        const int column = panel.profile ? -1 : store->column(curve.column);
        if (!panel.profile && (column < 0 || xColumn < 0)) continue;
        QCPGraph* graph = plot_->addGraph(x, y);
        graph->setName(curve.label);
        graph->setPen(QPen(curve.colour, 1.6, curve.style));
        if (panel.profile) graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 5));
        graph->addToLegend(legend);
        Bound bound{plot_->graphCount() - 1,
                    column,
                    xColumn,
                    panel.profile ? curve.column.toStdString() : std::string(),
                    curve.label,
                    legend};
        if (timePanel) {
            QCPGraph* back = plot_->addGraph(x, y);
            back->setName(tr("%1 (backwards)").arg(curve.label)); // its CSV column
            back->setPen(QPen(curve.colour, 1.6, Qt::DotLine));
            back->removeFromLegend(legend);
            bound.backGraph = plot_->graphCount() - 1;
        }
        bound_.push_back(bound);
    }
    if (timePanel && !panel.curves.empty()) {
        QCPGraph* key = plot_->addGraph(x, y);
        key->setName(tr("time running backwards"));
        key->setPen(QPen(QColor(90, 90, 90), 1.6, Qt::DotLine));
        key->removeFromLegend(legend);
        backKeys_.push_back({plot_->graphCount() - 1, legend, x});
    }
}

namespace {
// The time run up to each row, Σ|Δt| from the first row's time: equal to the time while it only runs
// forwards, and still increasing when it runs backwards.
QVector<double> timeRun(const QVector<double>& times) {
    QVector<double> run(times.size());
    for (qsizetype i = 0; i < times.size(); ++i)
        run[i] = i == 0 ? times[0] : run[i - 1] + std::abs(times[i] - times[i - 1]);
    return run;
}

// values where a stretch of the wanted direction touches the row, NaN elsewhere (QCustomPlot breaks the
// line at NaN). Row i ends the stretch from row i − 1.
QVector<double> directionPart(const QVector<double>& times, const QVector<double>& values, bool backwards) {
    QVector<double> part(values.size(), std::numeric_limits<double>::quiet_NaN());
    const auto stretch = [&](qsizetype end) { return (times[end] < times[end - 1]) == backwards; };
    for (qsizetype i = 0; i < values.size(); ++i) {
        const bool before = i > 0 && stretch(i), after = i + 1 < values.size() && stretch(i + 1);
        if (before || after || (values.size() == 1 && !backwards)) part[i] = values[i];
    }
    return part;
}
} // namespace

void SeriesPlot::rebuild() {
    plot_->clearGraphs();
    plot_->plotLayout()->clear();
    bound_.clear();
    backKeys_.clear();
    // Each panel: its legend in a row above it, then the panel.
    auto* upperLegend = new QCPLegend;
    placeLegendRow(plot_, upperLegend, 0);
    auto* upper = new QCPAxisRect(plot_);
    plot_->plotLayout()->addElement(1, 0, upper);
    addPanel(upper, spec_.upper, upperLegend);
    if (!spec_.lower.curves.empty()) {
        auto* lowerLegend = new QCPLegend;
        placeLegendRow(plot_, lowerLegend, 2);
        auto* lower = new QCPAxisRect(plot_);
        plot_->plotLayout()->addElement(3, 0, lower);
        addPanel(lower, spec_.lower, lowerLegend);
        // One time axis for both panels.
        if (spec_.upper.xColumn == spec_.lower.xColumn && !spec_.upper.profile && !spec_.lower.profile)
            connect(upper->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
                    lower->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::setRange));
    }
    applyPlotFont(plot_, font());
    refresh();
}

void SeriesPlot::refresh() {
    if (!isVisible()) return; // nobody sees it: showEvent refreshes it when it comes back
    const SeriesStore* store = controller_->series();
    std::vector<NamedProfile> profiles;
    if (const Model* model = controller_->model(); model && hasProfiles()) profiles = model->profiles();
    const QVector<double> times = store->values(store->column("time"));
    const bool reversed = std::adjacent_find(times.begin(), times.end(), std::greater<>()) != times.end();
    const QVector<double> run = reversed ? timeRun(times) : times;
    for (const auto& b : bound_) {
        QVector<double> xs, values;
        if (b.column >= 0) {
            xs = b.backGraph >= 0 ? run : store->values(b.xColumn);
            values = store->values(b.column);
        } else {
            for (const auto& p : profiles)
                if (p.name == b.profile) {
                    xs = QVector<double>(p.x.begin(), p.x.end());
                    values = QVector<double>(p.y.begin(), p.y.end());
                }
        }
        QCPGraph* graph = plot_->graph(b.graph);
        // A log axis shows magnitudes (its label says |x|), so a quantity that changes sign keeps its line;
        // the legend keeps the signed value.
        QVector<double> shown = values;
        if (graph->valueAxis()->scaleType() == QCPAxis::stLogarithmic)
            for (double& v : shown) v = std::abs(v);
        if (b.backGraph >= 0) {
            QCPGraph* back = plot_->graph(b.backGraph);
            reversed ? back->setData(xs, directionPart(times, shown, true), true) : back->data()->clear();
            graph->setData(xs, reversed ? directionPart(times, shown, false) : shown, true);
        } else {
            graph->setData(xs, shown, b.column < 0);
        }
        // A column that is NaN throughout (kT of an absent species) stays out of the plot and legend.
        const bool any = std::any_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
        graph->setVisible(any);
        if (b.backGraph >= 0) plot_->graph(b.backGraph)->setVisible(any && reversed);
        if (any)
            graph->addToLegend(b.legend);
        else
            graph->removeFromLegend(b.legend);
        // The legend shows the latest value: the number a teacher reads out, in the UI's language.
        QLocale locale;
        locale.setNumberOptions(QLocale::OmitGroupSeparator);
        // Up to a million as a plain number: "molecules  32000", not 3.2E+04.
        const auto number = [&locale](double v) {
            return std::abs(v) >= 1e3 && std::abs(v) < 1e6 ? locale.toString(v, 'f', 0)
                                                           : locale.toString(v, 'g', 4);
        };
        graph->setName(!values.isEmpty() && std::isfinite(values.back())
                           ? QStringLiteral("%1  %2").arg(b.label, number(values.back()))
                           : b.label);
    }
    for (const BackKey& key : backKeys_) {
        QCPGraph* graph = plot_->graph(key.graph);
        reversed ? graph->addToLegend(key.legend) : graph->removeFromLegend(key.legend);
        graph->setVisible(reversed);
        key.timeAxis->setLabel(reversed ? tr("time run, Σ |Δt|") : tr("time"));
    }
    for (auto* rect : plot_->axisRects()) {
        // x: the span of the data (a time axis follows the run; T and iteration axes start at 0).
        bool found = false;
        QCPRange span;
        for (QCPGraph* graph : rect->axis(QCPAxis::atBottom)->graphs()) {
            bool has = false;
            const QCPRange r = graph->getKeyRange(has);
            if (!has) continue;
            span = found ? QCPRange(std::min(span.lower, r.lower), std::max(span.upper, r.upper)) : r;
            found = true;
        }
        if (found && span.size() > 0) rect->axis(QCPAxis::atBottom)->setRange(span);
    }
    for (auto* rect : plot_->axisRects()) {
        QCPAxis* y = rect->axis(QCPAxis::atLeft);
        const auto graphs = y->graphs();
        if (graphs.isEmpty()) continue;
        // Each panel's value range covers all its graphs, with a margin so curves do not touch the frame.
        bool first = true;
        QCPRange range;
        for (QCPGraph* graph : graphs) {
            if (!graph->visible()) continue;
            bool found = false;
            const bool log = y->scaleType() == QCPAxis::stLogarithmic;
            const QCPRange r = graph->getValueRange(found, log ? QCP::sdPositive : QCP::sdBoth);
            if (!found) continue;
            if (first)
                range = r;
            else
                range.expand(r);
            first = false;
        }
        if (first) continue;
        if (y->scaleType() == QCPAxis::stLogarithmic) {
            // At least two decades, so the log ticks have powers of ten to mark.
            range.lower = std::max(range.lower, range.upper * 1e-12);
            y->setRange(std::min(range.lower / 2, range.upper / 100), range.upper * 2);
        } else {
            // A constant curve gets ±5 % of its value (any scale: (σ c_r)_max is ~1e-17), or ±1 at zero.
            const double pad = range.size() > 0     ? 0.08 * range.size()
                               : range.upper != 0.0 ? 0.05 * std::abs(range.upper)
                                                    : 1.0;
            y->setRange(range.lower - pad, range.upper + pad);
        }
    }
    replotLive(plot_);
}

bool SeriesPlot::hasProfiles() const {
    return spec_.upper.profile || spec_.lower.profile;
}

void SeriesPlot::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    refresh();
}

void SeriesPlot::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) applyPlotFont(plot_, font());
}

} // namespace pl::ui
