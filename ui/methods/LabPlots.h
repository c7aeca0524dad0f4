// Plot helpers shared by the methods lab's pages: log axes, one styled curve per scheme, cells of a map
// coloured by outcome, and a marker for the experiment's current setting.
#pragma once

#include "common/sweep/CellOutcome.h"

#include <QColor>
#include <QString>

class QCustomPlot;
class QCPGraph;

namespace pl::ui::lab {

// A new plot: export menu, the widget's font, labelled axes, legend; log axes where asked.
QCustomPlot* makePlot(QWidget* parent, const QString& xLabel, const QString& yLabel, bool logX, bool logY);
void setLogAxis(QCustomPlot* plot, bool x, bool log);
QCPGraph* addCurve(QCustomPlot* plot, const QString& name, const QColor& colour);
void rescale(QCustomPlot* plot);

QColor schemeColour(int index);
QColor outcomeColour(methods::CellOutcome outcome);
// One graph per outcome class (squares, no lines), in CellOutcome order, for a map; the legend names them.
void addOutcomeGraphs(QCustomPlot* plot, const std::vector<methods::CellOutcome>& classes);
// Adds a map cell to its outcome's graph (added by addOutcomeGraphs with the same classes).
void addCell(QCustomPlot* plot, const std::vector<methods::CellOutcome>& classes,
             methods::CellOutcome outcome, double x, double y);
// Moves the legend out of the axis rectangle into a row below it (maps fill their whole rectangle).
void legendBelow(QCustomPlot* plot);
// A star at the experiment's current setting, named for the legend.
QCPGraph* markCurrent(QCustomPlot* plot, double x, double y, const QString& name);

} // namespace pl::ui::lab
