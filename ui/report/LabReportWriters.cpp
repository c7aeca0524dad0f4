// The report's two writers. PDF: A4 pages laid out top to bottom with QPainter on a QPdfWriter at 96 dpi
// (the screen's, so the plots' fonts keep their size), the plots drawn by QCustomPlot straight into the
// PDF as vector paths. HTML: one page that needs nothing beside it, the scene as a PNG and every plot as
// an SVG in data: URIs, written as XHTML so any XML parser can check it.
#include "LabReport.h"

#include <QBuffer>
#include <QFileInfo>
#include <QPdfWriter>
#include <QSaveFile>
#include <QSvgGenerator>
#include <array>
#include <qcustomplot.h>

namespace pl::ui {

namespace {

constexpr int kDpi = 96;              // PDF coordinates: pixels at the screen's resolution
constexpr double kMarginMm = 15.0;    // page margins
constexpr int kPlotWidth = 680;       // [px at 96 dpi] a plot across the text width
constexpr int kPlotHeight = 380;      // [px]
constexpr int kGap = 10;              // [px] between blocks
constexpr int kKeepWithHeading = 120; // [px] of what follows a heading kept on its page

class PdfFlow {
public:
    PdfFlow(QPdfWriter& writer, QCPPainter& painter) : writer_(writer), p_(painter) {
        width_ = writer.width();
        height_ = writer.height();
    }
    // keep: the height of what follows that must share the heading's page (a plot), else kKeepWithHeading.
    void heading(const QString& text, double pointSize, int keep = kKeepWithHeading) {
        QFont font = p_.font();
        font.setPointSizeF(pointSize);
        font.setBold(true);
        room(keep); // a heading never ends a page alone
        paragraph(text, font);
    }
    void paragraph(const QString& text, const QFont& font) {
        p_.setFont(font);
        const QRect bounds = p_.boundingRect(QRect(0, 0, width_, 100000), Qt::TextWordWrap, text);
        room(bounds.height());
        p_.setPen(Qt::black);
        p_.drawText(QRect(0, y_, width_, bounds.height()), Qt::TextWordWrap, text);
        y_ += bounds.height() + kGap / 2;
    }
    void body(const QString& text) { paragraph(text, bodyFont()); }
    // Rows of up to four columns, the widths in shares of the text width.
    void table(const std::vector<ReportRow>& rows, std::array<double, 4> shares) {
        const QFont font = bodyFont();
        p_.setFont(font);
        for (const ReportRow& row : rows) {
            const QString cells[4] = {row.name, row.value, row.unit, row.note};
            int rowHeight = 0;
            for (int c = 0; c < 4; ++c)
                rowHeight = std::max(rowHeight, p_.boundingRect(QRect(0, 0, cellWidth(shares[c]), 10000),
                                                                Qt::TextWordWrap, cells[c])
                                                    .height());
            room(rowHeight + 2);
            int x = 0;
            for (int c = 0; c < 4; ++c) {
                p_.drawText(QRect(x, y_, cellWidth(shares[c]), rowHeight), Qt::TextWordWrap, cells[c]);
                x += static_cast<int>(shares[c] * width_);
            }
            y_ += rowHeight + 2;
            p_.setPen(QColor(220, 220, 220));
            p_.drawLine(QLineF(0, y_ - 1, width_, y_ - 1));
            p_.setPen(Qt::black);
        }
        y_ += kGap;
    }
    void image(const QImage& image) {
        const int w = std::min(width_, kPlotWidth);
        const int h = image.height() * w / std::max(1, image.width());
        room(h);
        p_.drawImage(QRect(0, y_, w, h), image);
        y_ += h + kGap;
    }
    void plot(QCustomPlot* plot) {
        room(kPlotHeight);
        p_.save();
        p_.translate(0, y_);
        plot->toPainter(&p_, kPlotWidth, kPlotHeight);
        p_.restore();
        y_ += kPlotHeight + kGap;
    }

private:
    QFont bodyFont() const {
        QFont font = p_.font();
        font.setPointSizeF(9.5);
        font.setBold(false);
        return font;
    }
    int cellWidth(double share) const { return static_cast<int>(share * width_) - 6; }
    void room(int height) {
        if (y_ + height <= height_ || y_ == 0) return;
        writer_.newPage();
        y_ = 0;
    }
    QPdfWriter& writer_;
    QCPPainter& p_;
    int width_ = 0, height_ = 0, y_ = 0;
};

QString writePdf(const LabReportContent& c, const QString& path) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QStringLiteral("Cannot write %1: %2").arg(path, file.errorString());
    {
        QPdfWriter writer(&file);
        writer.setTitle(c.title);
        writer.setCreator(QStringLiteral("ParticleLab"));
        writer.setResolution(kDpi);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageMargins(QMarginsF(kMarginMm, kMarginMm, kMarginMm, kMarginMm), QPageLayout::Millimeter);
        QCPPainter painter(&writer);
        PdfFlow flow(writer, painter);
        flow.heading(QStringLiteral("Lab report: %1").arg(c.title), 18);
        flow.body(c.kindTitle + QStringLiteral(" — ") + QStringLiteral("units: %1").arg(c.units));
        flow.body(c.description);
        flow.image(c.scene);
        flow.heading(QStringLiteral("What was run"), 13);
        flow.table(c.run, {0.25, 0.75, 0.0, 0.0});
        if (!c.theory.empty()) {
            flow.heading(QStringLiteral("Readouts against theory"), 13);
            flow.table(c.theory, {0.3, 0.12, 0.1, 0.48});
        }
        flow.heading(QStringLiteral("Readouts at the end"), 13);
        flow.table(c.readouts, {0.55, 0.25, 0.2, 0.0});
        for (const QString& line : c.distributions) flow.body(line);
        for (const auto& plot : c.plots) {
            flow.heading(plot.title, 13, kPlotHeight + 2 * kGap + kKeepWithHeading / 4);
            flow.plot(plot.plot);
        }
        flow.heading(QStringLiteral("Parameters"), 13);
        flow.table(c.parameters, {0.42, 0.2, 0.13, 0.25});
        painter.end();
    }
    if (!file.commit()) return QStringLiteral("Cannot write %1: %2").arg(path, file.errorString());
    return {};
}

QString escaped(const QString& text) {
    return text.toHtmlEscaped();
}

QString tableHtml(const std::vector<ReportRow>& rows, const QStringList& headers) {
    QString html = QStringLiteral("<table>\n<tr>");
    for (const QString& h : headers) html += QStringLiteral("<th>%1</th>").arg(escaped(h));
    html += QStringLiteral("</tr>\n");
    for (const ReportRow& row : rows) {
        const QString cells[4] = {row.name, row.value, row.unit, row.note};
        html += QStringLiteral("<tr>");
        for (int i = 0; i < headers.size() && i < 4; ++i)
            html += QStringLiteral("<td>%1</td>").arg(escaped(cells[i]));
        html += QStringLiteral("</tr>\n");
    }
    return html + QStringLiteral("</table>\n");
}

QByteArray plotSvg(QCustomPlot* plot) {
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(QSize(kPlotWidth, kPlotHeight));
    svg.setViewBox(QRect(0, 0, kPlotWidth, kPlotHeight));
    svg.setResolution(kDpi);
    QCPPainter painter(&svg);
    plot->toPainter(&painter, kPlotWidth, kPlotHeight);
    painter.end();
    return buffer.data();
}

QString writeHtml(const LabReportContent& c, const QString& path) {
    QByteArray png;
    {
        QBuffer buffer(&png);
        buffer.open(QIODevice::WriteOnly);
        c.scene.save(&buffer, "PNG");
    }
    QString html =
        QStringLiteral(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!DOCTYPE html>\n"
            "<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
            "<title>%1</title>\n<style>\nbody{font-family:sans-serif;max-width:60em;margin:2em auto;}\n"
            "table{border-collapse:collapse;margin-bottom:1em;}\n"
            "td,th{border-bottom:1px solid #ddd;padding:2px 8px;text-align:left;vertical-align:top;}\n"
            "img{max-width:100%;}\n</style>\n</head>\n<body>\n")
            .arg(escaped(QStringLiteral("Lab report: %1").arg(c.title)));
    html += QStringLiteral("<h1>%1</h1>\n").arg(escaped(QStringLiteral("Lab report: %1").arg(c.title)));
    html += QStringLiteral("<p>%1 — %2</p>\n<p>%3</p>\n")
                .arg(escaped(c.kindTitle), escaped(QStringLiteral("units: %1").arg(c.units)),
                     escaped(c.description));
    html += QStringLiteral("<p><img alt=\"%1\" src=\"data:image/png;base64,%2\"/></p>\n")
                .arg(escaped(QStringLiteral("The scene at the end")), QString::fromLatin1(png.toBase64()));
    html += QStringLiteral("<h2>%1</h2>\n").arg(escaped(QStringLiteral("What was run")));
    html += tableHtml(c.run, {QStringLiteral("what"), QStringLiteral("value")});
    if (!c.theory.empty()) {
        html += QStringLiteral("<h2>%1</h2>\n").arg(escaped(QStringLiteral("Readouts against theory")));
        html += tableHtml(c.theory, {QStringLiteral("readout"), QStringLiteral("value"),
                                     QStringLiteral("unit"), QStringLiteral("theory")});
    }
    html += QStringLiteral("<h2>%1</h2>\n").arg(escaped(QStringLiteral("Readouts at the end")));
    html +=
        tableHtml(c.readouts, {QStringLiteral("readout"), QStringLiteral("value"), QStringLiteral("unit")});
    for (const QString& line : c.distributions) html += QStringLiteral("<p>%1</p>\n").arg(escaped(line));
    for (const auto& plot : c.plots)
        html += QStringLiteral("<h2>%1</h2>\n<p><img alt=\"%1\" src=\"data:image/svg+xml;base64,%2\"/></p>\n")
                    .arg(escaped(plot.title), QString::fromLatin1(plotSvg(plot.plot).toBase64()));
    html += QStringLiteral("<h2>%1</h2>\n").arg(escaped(QStringLiteral("Parameters")));
    html += tableHtml(c.parameters, {QStringLiteral("parameter"), QStringLiteral("value"),
                                     QStringLiteral("unit"), QStringLiteral("key")});
    html += QStringLiteral("</body>\n</html>\n");

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QStringLiteral("Cannot write %1: %2").arg(path, file.errorString());
    file.write(html.toUtf8());
    if (!file.commit()) return QStringLiteral("Cannot write %1: %2").arg(path, file.errorString());
    return {};
}

} // namespace

bool isReportPath(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("pdf") || suffix == QLatin1String("html") ||
           suffix == QLatin1String("htm");
}

QString writeLabReport(const LabReportContent& content, const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("pdf")) return writePdf(content, path);
    if (suffix == QLatin1String("html") || suffix == QLatin1String("htm")) return writeHtml(content, path);
    return QStringLiteral("%1 needs the suffix .pdf or .html").arg(path);
}

} // namespace pl::ui
