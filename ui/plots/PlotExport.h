// Export of any QCustomPlot: PNG, SVG or PDF at a chosen size and resolution, and its data as CSV.
// Every file is written atomically (QSaveFile): a failed export never leaves half a file behind.
#pragma once

#include <QSize>
#include <QString>

class QCustomPlot;
class QWidget;

namespace pl::ui {

struct ImageExportOptions {
    QSize size{800, 600}; // a PNG's pixels; an SVG's or PDF's size in px at 96 dpi
    int dpi = 150;        // a PNG's resolution: scales text and lines, stored in the file
};

// Format from the suffix (.png, .svg, .pdf). Returns an error sentence, or empty on success.
QString savePlotImage(QCustomPlot* plot, const QString& path, const ImageExportOptions& options);
// One row per data point of every plottable: series,x,y (header included). Returns an error or empty.
QString savePlotCsv(QCustomPlot* plot, const QString& path);

// Adds "Save image…" and "Export data as CSV…" to the plot's right-click menu.
void installPlotExportMenu(QCustomPlot* plot);
// The same two actions driven by dialogs (file, then size and DPI for images).
void exportPlotImageInteractively(QCustomPlot* plot, QWidget* parent);
void exportPlotCsvInteractively(QCustomPlot* plot, QWidget* parent);

} // namespace pl::ui
