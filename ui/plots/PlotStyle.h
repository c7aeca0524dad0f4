// Fonts of a QCustomPlot follow the application font (the projector mode enlarges both).
#pragma once

#include <QFont>

class QCustomPlot;

namespace pl::ui {

void applyPlotFont(QCustomPlot* plot, const QFont& font);

} // namespace pl::ui
