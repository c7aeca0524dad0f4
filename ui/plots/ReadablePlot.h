// Keeps a plot's data readable: legends live outside the data, in a row above their panel, their entries
// flowing in as many columns as the width allows (in a small plot, in smaller text, so the legend never
// takes more than a third of its panel); a value-axis label longer than its axis, or a title wider than
// the plot, is set smaller (then shortened) so it never runs into a title, a neighbour or the edge; short
// or narrow axes get fewer ticks, so their values never overlap.
#pragma once

class QCustomPlot;
class QCPLegend;
class QCPTextElement;
class QPointF;
class QString;

namespace pl::ui {

// Puts legend (new, or taken from an axis rect's inset) into the plot's layout at row, column 0, rows
// below moving down; the row keeps the legend's height.
void placeLegendRow(QCustomPlot* plot, QCPLegend* legend, int row);

// Sets a title's full text, already fitted to the plot's present width, so the next layout gives it the
// height of the lines it shows (a summary that changes every frame is never laid out as one long line).
void setFittedTitle(QCPTextElement* title, const QString& text);

// The whole text of a value label or title shown shortened ("probability …") at the point, in the
// plot's pixels; empty elsewhere. The plot shows it as the tooltip there.
QString shortenedTextAt(QCustomPlot* plot, const QPointF& at);

// Call once per plot: from then on its legends re-flow and its value labels fit after every layout.
void keepDataReadable(QCustomPlot* plot);

} // namespace pl::ui
