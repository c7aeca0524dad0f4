// PlotExport: renders through QCustomPlot::toPainter into a QSaveFile-backed device for every format.
#include "PlotExport.h"

#include "ExportImageDialog.h"
#include "FileDialogs.h"

#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPdfWriter>
#include <QSaveFile>
#include <QSvgGenerator>
#include <QTextStream>
#include <qcustomplot.h>

#include <algorithm>

namespace pl::ui {

namespace {

QString commitOrError(QSaveFile& file) {
    if (!file.commit()) return QObject::tr("Cannot write %1: %2").arg(file.fileName(), file.errorString());
    return {};
}

QString renderPng(QCustomPlot* plot, QSaveFile& file, const ImageExportOptions& o) {
    // The file has exactly the pixels the dialog names. The DPI scales the plot's 96-DPI layout onto
    // them (text and lines twice as large at 192 DPI) and is stored as the image's resolution.
    const double scale = o.dpi / 96.0;
    const int logicalWidth = std::max(1, qRound(o.size.width() / scale));
    const int logicalHeight = std::max(1, qRound(o.size.height() / scale));
    QImage image(o.size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent); // toPainter fills the plot's own background
    QCPPainter painter;
    if (!painter.begin(&image)) return QObject::tr("Cannot start the PNG renderer.");
    painter.setMode(QCPPainter::pmNoCaching);
    if (scale > 1.0) painter.setMode(QCPPainter::pmNonCosmetic); // lines grow with the text
    painter.scale(o.size.width() / static_cast<double>(logicalWidth),
                  o.size.height() / static_cast<double>(logicalHeight));
    plot->toPainter(&painter, logicalWidth, logicalHeight);
    painter.end();
    const int dotsPerMetre = static_cast<int>(o.dpi / 0.0254 + 0.5);
    image.setDotsPerMeterX(dotsPerMetre);
    image.setDotsPerMeterY(dotsPerMetre);
    if (!image.save(&file, "PNG")) return QObject::tr("Cannot encode the PNG image.");
    return {};
}

QString renderSvg(QCustomPlot* plot, QSaveFile& file, const ImageExportOptions& o) {
    QSvgGenerator svg;
    svg.setOutputDevice(&file);
    svg.setSize(o.size);
    svg.setViewBox(QRect(QPoint(0, 0), o.size));
    svg.setResolution(o.dpi);
    svg.setTitle(plot->objectName());
    QCPPainter painter;
    if (!painter.begin(&svg)) return QObject::tr("Cannot start the SVG renderer.");
    plot->toPainter(&painter, o.size.width(), o.size.height());
    painter.end();
    return {};
}

QString renderPdf(QCustomPlot* plot, QSaveFile& file, const ImageExportOptions& o) {
    QPdfWriter pdf(&file);
    pdf.setResolution(o.dpi);
    pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
    // Page size in points (1/72 in) from the logical size at 96 dpi.
    pdf.setPageSize(QPageSize(QSizeF(o.size) * 72.0 / 96.0, QPageSize::Point));
    QCPPainter painter;
    if (!painter.begin(&pdf)) return QObject::tr("Cannot start the PDF renderer.");
    painter.setMode(QCPPainter::pmVectorized);
    painter.setMode(QCPPainter::pmNoCaching);
    const double scale = pdf.width() / static_cast<double>(o.size.width());
    painter.scale(scale, scale);
    plot->toPainter(&painter, o.size.width(), o.size.height());
    painter.end();
    return {};
}

template <class DataContainer>
void writeData(QTextStream& out, const QString& name, const DataContainer& data) {
    for (auto it = data->constBegin(); it != data->constEnd(); ++it)
        out << name << ',' << QString::number(it->mainKey(), 'g', 17) << ','
            << QString::number(it->mainValue(), 'g', 17) << '\n';
}

QString csvField(QString text) {
    if (text.contains(',') || text.contains('"')) text = '"' + text.replace('"', "\"\"") + '"';
    return text;
}

} // namespace

QString savePlotImage(QCustomPlot* plot, const QString& path, const ImageExportOptions& options) {
    if (options.size.width() < 16 || options.size.height() < 16 || options.dpi < 24)
        return QObject::tr("The image must be at least 16 × 16 pixels at 24 DPI or more.");
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != "png" && suffix != "svg" && suffix != "pdf")
        return QObject::tr("Unknown image format '.%1': use .png, .svg or .pdf.").arg(suffix);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QObject::tr("Cannot write %1: %2").arg(path, file.errorString());
    const QString error = suffix == "png"   ? renderPng(plot, file, options)
                          : suffix == "svg" ? renderSvg(plot, file, options)
                                            : renderPdf(plot, file, options);
    if (!error.isEmpty()) {
        file.cancelWriting();
        return error;
    }
    return commitOrError(file);
}

QString savePlotCsv(QCustomPlot* plot, const QString& path) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return QObject::tr("Cannot write %1: %2").arg(path, file.errorString());
    QTextStream out(&file);
    out << "series,x,y\n";
    for (int i = 0; i < plot->plottableCount(); ++i) {
        QCPAbstractPlottable* p = plot->plottable(i);
        const QString name = csvField(p->name().isEmpty() ? QStringLiteral("series %1").arg(i) : p->name());
        if (auto* graph = qobject_cast<QCPGraph*>(p))
            writeData(out, name, graph->data());
        else if (auto* bars = qobject_cast<QCPBars*>(p))
            writeData(out, name, bars->data());
        else if (auto* curve = qobject_cast<QCPCurve*>(p))
            writeData(out, name, curve->data());
    }
    out.flush();
    return commitOrError(file);
}

void exportPlotImageInteractively(QCustomPlot* plot, QWidget* parent) {
    QString filter;
    const QString path = files::saveFileName(
        parent, files::Place::Exports, QObject::tr("Save plot image"), plot->objectName() + ".png",
        QObject::tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"), &filter);
    if (path.isEmpty()) return;
    ExportImageDialog dialog(plot->size(), QFileInfo(path).suffix().toLower() == "png", parent);
    if (dialog.exec() != QDialog::Accepted) return;
    const QString error = savePlotImage(plot, path, dialog.options());
    if (!error.isEmpty()) QMessageBox::critical(parent, QObject::tr("Cannot save the image"), error);
}

void exportPlotCsvInteractively(QCustomPlot* plot, QWidget* parent) {
    const QString path = files::saveFileName(parent, files::Place::Exports, QObject::tr("Export plot data"),
                                             plot->objectName() + ".csv", QObject::tr("CSV table (*.csv)"));
    if (path.isEmpty()) return;
    const QString error = savePlotCsv(plot, path);
    if (!error.isEmpty()) QMessageBox::critical(parent, QObject::tr("Cannot export the data"), error);
}

void installPlotExportMenu(QCustomPlot* plot) {
    plot->setContextMenuPolicy(Qt::CustomContextMenu);
    QObject::connect(plot, &QWidget::customContextMenuRequested, plot, [plot](const QPoint& at) {
        QMenu menu(plot);
        menu.addAction(QObject::tr("Save image (PNG, SVG, PDF)…"),
                       [plot] { exportPlotImageInteractively(plot, plot->window()); });
        menu.addAction(QObject::tr("Export data as CSV…"),
                       [plot] { exportPlotCsvInteractively(plot, plot->window()); });
        menu.exec(plot->mapToGlobal(at));
    });
}

} // namespace pl::ui
