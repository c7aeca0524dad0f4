// The methods lab's plot helpers: log axes, styled scheme curves, outcome-coloured map cells, markers.
#include "LabPlots.h"
#include "i18n/Translations.h"

#include "plots/PlotExport.h"
#include "plots/PlotStyle.h"

#include <qcustomplot.h>

namespace pl::ui::lab {

QCustomPlot* makePlot(QWidget* parent, const QString& xLabel, const QString& yLabel, bool logX, bool logY) {
    auto* plot = new QCustomPlot(parent);
    plot->setMinimumSize(320, 240);
    applyPlotFont(plot, parent->font());
    setLogAxis(plot, true, logX);
    setLogAxis(plot, false, logY);
    plot->xAxis->setLabel(xLabel);
    plot->yAxis->setLabel(yLabel);
    plot->legend->setVisible(true);
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignLeft);
    installPlotExportMenu(plot);
    return plot;
}

void setLogAxis(QCustomPlot* plot, bool x, bool log) {
    QCPAxis* axis = x ? plot->xAxis : plot->yAxis;
    axis->setScaleType(log ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
    if (log)
        axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    else
        axis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
}

QCPGraph* addCurve(QCustomPlot* plot, const QString& name, const QColor& colour) {
    QCPGraph* g = plot->addGraph();
    g->setName(name);
    g->setPen(QPen(colour, 2));
    g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 6));
    return g;
}

void rescale(QCustomPlot* plot) {
    plot->rescaleAxes();
    plot->xAxis->scaleRange(1.3);
    plot->yAxis->scaleRange(1.5);
    plot->replot();
}

QColor schemeColour(int index) {
    static const QColor colours[] = {QColor(200, 70, 60),  QColor(230, 150, 40), QColor(60, 110, 200),
                                     QColor(40, 150, 110), QColor(140, 80, 180), QColor(90, 90, 90),
                                     QColor(30, 170, 200), QColor(170, 120, 60)};
    return colours[index % 8];
}

QColor outcomeColour(methods::CellOutcome outcome) {
    using methods::CellOutcome;
    switch (outcome) {
    case CellOutcome::Stable:
        return QColor(70, 170, 90);
    case CellOutcome::Inaccurate:
        return QColor(235, 190, 60);
    case CellOutcome::OverCompressed:
        return QColor(240, 140, 50);
    case CellOutcome::Unstable:
    case CellOutcome::Exploded:
        return QColor(205, 60, 55);
    case CellOutcome::Rejected:
        return QColor(150, 150, 150);
    }
    return Qt::black;
}

void addOutcomeGraphs(QCustomPlot* plot, const std::vector<methods::CellOutcome>& classes) {
    for (methods::CellOutcome c : classes) {
        QCPGraph* g = plot->addGraph();
        g->setName(coreText(methods::outcomeName(c)));
        g->setLineStyle(QCPGraph::lsNone);
        g->setScatterStyle(
            QCPScatterStyle(QCPScatterStyle::ssSquare, outcomeColour(c), outcomeColour(c), 11));
    }
}

void addCell(QCustomPlot* plot, const std::vector<methods::CellOutcome>& classes,
             methods::CellOutcome outcome, double x, double y) {
    for (std::size_t k = 0; k < classes.size(); ++k)
        if (classes[k] == outcome) plot->graph(static_cast<int>(k))->addData(x, y);
}

void legendBelow(QCustomPlot* plot) {
    QCPLayoutGrid* row = new QCPLayoutGrid;
    plot->plotLayout()->addElement(1, 0, row);
    plot->axisRect()->insetLayout()->take(plot->legend);
    row->addElement(0, 0, plot->legend);
    plot->legend->setFillOrder(QCPLegend::foColumnsFirst);
    plot->legend->setWrap(3);
    plot->plotLayout()->setRowStretchFactor(1, 0.001);
    row->setMargins(QMargins(0, 0, 0, 0));
}

QCPGraph* markCurrent(QCustomPlot* plot, double x, double y, const QString& name) {
    QCPGraph* g = plot->addGraph();
    g->setName(name);
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssStar, QPen(Qt::black, 2), Qt::NoBrush, 16));
    g->addData(x, y);
    return g;
}

} // namespace pl::ui::lab
