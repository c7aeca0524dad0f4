// FieldOverlay: the colour map is an image of one pixel per cell that QPainter scales onto the cell
// rectangle (in the GL viewport as a texture), so a field of 10⁴ cells costs one upload per frame.
#include "FieldOverlay.h"

#include "Palette.h"
#include "i18n/Translations.h"

#include <QCoreApplication>
#include <QLocale>
#include <QPainter>
#include <algorithm>
#include <climits>
#include <cmath>

namespace pl::ui {

namespace {
const QColor kLegendBack(0, 0, 0, 150);
const QColor kProbeBack(10, 12, 24, 215);
const QColor kProbeRim(200, 205, 220);
const QColor kProfileLine(255, 255, 255);
constexpr double kLegendWidthLines = 11.0; // legend width in text lines
constexpr double kLegendMarginPx = 8.0;
constexpr double kProbeOffsetPx = 16.0; // the table sits this far right of and below the cursor
// Outside [1e-3, 1e5) values read better with a power of ten than with many zeros.
constexpr double kSmallestPlain = 1e-3, kLargestPlain = 1e5;

QString superscript(int exponent) {
    static const QString digits = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    QString out = exponent < 0 ? QStringLiteral("⁻") : QString();
    for (const QChar c : QString::number(std::abs(exponent))) out += digits.at(c.digitValue());
    return out;
}

// A colour bar over bar, left to right across the map's stops.
void paintColourBar(QPainter& painter, const QRectF& bar, ColourMap map) {
    QLinearGradient gradient(bar.topLeft(), bar.topRight());
    const QVector<QColor>& stops = paletteStops(map);
    for (qsizetype s = 0; s < stops.size(); ++s)
        gradient.setColorAt(static_cast<double>(s) / static_cast<double>(stops.size() - 1), stops[s]);
    painter.setPen(Qt::NoPen);
    painter.setBrush(gradient);
    painter.drawRect(bar);
}

// The particles' legend as it has always been: categories, or a bar from 0 to colourMax; its bottom.
double paintParticleLegend(QPainter& painter, const ViewTransform& transform, const SceneView& scene) {
    const QFontMetricsF metrics(painter.font());
    const double line = metrics.height();
    const double width = kLegendWidthLines * line;
    const double left = transform.size().width() - width - kLegendMarginPx;
    if (isCategorical(scene.colours)) {
        if (scene.categories.empty()) return 0.0;
        const QRectF frame(left, kLegendMarginPx, width,
                           (static_cast<double>(scene.categories.size()) + 0.6) * line);
        painter.setPen(Qt::NoPen);
        painter.setBrush(kLegendBack);
        painter.drawRoundedRect(frame, 4, 4);
        for (std::size_t c = 0; c < scene.categories.size(); ++c) {
            const double y = frame.top() + (static_cast<double>(c) + 0.3) * line;
            painter.setBrush(paletteColour(scene.colours, static_cast<double>(c)));
            painter.setPen(Qt::NoPen);
            painter.drawEllipse(QPointF(frame.left() + 0.7 * line, y + 0.5 * line), 0.3 * line, 0.3 * line);
            painter.setPen(Qt::white);
            painter.drawText(QRectF(frame.left() + 1.4 * line, y, width - 1.6 * line, line), Qt::AlignVCenter,
                             coreSentence(scene.categories[c]));
        }
        return frame.bottom();
    }
    // The title sits between the ends of the scale where it fits, else on a line of its own above.
    const QString title = coreText(scene.colourLabel);
    const QString top = formatFieldValue(scene.colourMax); // 5274, not 5.27E+03
    const double inner = width - line;
    const bool ownLine = metrics.horizontalAdvance(title) + 2 * metrics.horizontalAdvance(top) + line > inner;
    const double titleHeight = ownLine ? line : 0.0;
    const QRectF frame(left, kLegendMarginPx, width, 2.6 * line + titleHeight);
    painter.setPen(Qt::NoPen);
    painter.setBrush(kLegendBack);
    painter.drawRoundedRect(frame, 4, 4);
    const QRectF bar(frame.left() + 0.5 * line, frame.top() + 0.3 * line + titleHeight, inner, 0.8 * line);
    paintColourBar(painter, bar, scene.colours);
    painter.setPen(Qt::white);
    const QRectF labels(bar.left(), bar.bottom() + 0.1 * line, bar.width(), line);
    painter.drawText(labels, Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("0"));
    if (ownLine)
        painter.drawText(QRectF(bar.left(), frame.top() + 0.2 * line, inner, line),
                         Qt::AlignHCenter | Qt::AlignVCenter,
                         metrics.elidedText(title, Qt::ElideRight, inner));
    else
        painter.drawText(labels, Qt::AlignHCenter | Qt::AlignVCenter, title);
    painter.drawText(labels, Qt::AlignRight | Qt::AlignVCenter, top);
    return frame.bottom();
}

// The field's legend below top: its title on a line of its own (field names are long), then the bar,
// then the physical values at its ends.
void paintFieldLegend(QPainter& painter, const ViewTransform& transform, const SceneFieldImage& field,
                      double top) {
    const QFontMetricsF metrics(painter.font());
    const double line = metrics.height();
    // Over how much time the picture is an average: a moving shock needs a short, moving window.
    const int steps = static_cast<int>(std::min<long long>(field.sampledSteps, INT_MAX));
    const QString averaged =
        field.window > 0
            ? QCoreApplication::translate("FieldOverlay", "mean of the last %n step(s)", nullptr, steps)
            : QCoreApplication::translate("FieldOverlay", "mean of %n step(s)", nullptr, steps);
    const QString title = coreText(field.label), lowest = formatFieldValue(field.minimum),
                  highest = formatFieldValue(field.maximum);
    // As wide as its longest line needs (German lines run longer), up to 60 % of the view.
    const double needed =
        std::max({metrics.horizontalAdvance(title), metrics.horizontalAdvance(averaged),
                  metrics.horizontalAdvance(lowest) + metrics.horizontalAdvance(highest) + line});
    const double width =
        std::min(std::max(kLegendWidthLines * line, needed + 1.2 * line), 0.6 * transform.size().width());
    const QRectF frame(transform.size().width() - width - kLegendMarginPx, top, width, 4.7 * line);
    painter.setPen(Qt::NoPen);
    painter.setBrush(kLegendBack);
    painter.drawRoundedRect(frame, 4, 4);
    const QRectF titleBox(frame.left() + 0.5 * line, frame.top() + 0.2 * line, width - line, line);
    painter.setPen(Qt::white);
    painter.drawText(titleBox, Qt::AlignHCenter | Qt::AlignVCenter,
                     metrics.elidedText(title, Qt::ElideRight, titleBox.width()));
    const QRectF bar(titleBox.left(), titleBox.bottom() + 0.1 * line, titleBox.width(), 0.8 * line);
    paintColourBar(painter, bar, field.colours);
    painter.setPen(Qt::white);
    const QRectF labels(bar.left(), bar.bottom() + 0.1 * line, bar.width(), line);
    painter.drawText(labels, Qt::AlignLeft | Qt::AlignVCenter, lowest);
    painter.drawText(labels, Qt::AlignRight | Qt::AlignVCenter, highest);
    if (steps > 0) // before the window opens the scene's hint says so
        painter.drawText(labels.translated(0, line), Qt::AlignHCenter | Qt::AlignVCenter,
                         metrics.elidedText(averaged, Qt::ElideRight, labels.width()));
}
} // namespace

QImage fieldImage(const SceneFieldImage& field) {
    if (field.nx <= 0 || field.ny <= 0 ||
        field.value.size() != static_cast<std::size_t>(field.nx) * static_cast<std::size_t>(field.ny))
        return {};
    QImage image(field.nx, field.ny, QImage::Format_ARGB32_Premultiplied);
    for (int j = 0; j < field.ny; ++j) {
        auto* row = reinterpret_cast<QRgb*>(image.scanLine(field.ny - 1 - j)); // y grows upwards
        for (int i = 0; i < field.nx; ++i) {
            const float v = field.value[static_cast<std::size_t>(j) * field.nx + i];
            row[i] = std::isfinite(v) ? paletteColour(field.colours, v).rgba() : qRgba(0, 0, 0, 0);
        }
    }
    return image;
}

void paintField(QPainter& painter, const ViewTransform& transform, const SceneFieldImage& field) {
    const QImage image = fieldImage(field);
    if (image.isNull()) return;
    painter.save();
    // Bilinear between cell centres: the picture of a smooth flow, not of the grid; the probe reads cells.
    painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
    painter.drawImage(transform.toWidget(field.left, field.bottom, field.right, field.top), image);
    painter.restore();
}

void paintLegends(QPainter& painter, const ViewTransform& transform, const SceneView& scene) {
    double bottom = 0.0;
    if (scene.drawParticles) bottom = paintParticleLegend(painter, transform, scene);
    if (scene.field) paintFieldLegend(painter, transform, *scene.field, bottom + kLegendMarginPx);
}

QString formatFieldValue(double value) {
    if (std::isnan(value)) return QStringLiteral("—");
    const double size = std::abs(value);
    const QLocale locale; // the UI's language: German 2,50 × 10²¹
    if (size == 0.0 || (size >= kSmallestPlain && size < kLargestPlain)) {
        QString plain = locale.toString(value, 'g', 4);
        return plain.remove(locale.groupSeparator()); // 2634, not 2,634
    }
    int exponent = static_cast<int>(std::floor(std::log10(size)));
    double mantissa = value / std::pow(10.0, exponent);
    if (std::abs(std::round(mantissa * 100.0) / 100.0) >= 10.0) { // 9.999e20 rounds to 10.00
        mantissa /= 10.0;
        ++exponent;
    }
    return QStringLiteral("%1 × 10%2").arg(locale.toString(mantissa, 'f', 2), superscript(exponent));
}

QStringList probeLines(const std::vector<FieldValue>& values) {
    QStringList lines;
    for (const FieldValue& v : values) {
        QString line = QStringLiteral("%1: %2").arg(coreText(v.choice.label), formatFieldValue(v.value));
        if (!v.choice.unit.empty() && !std::isnan(v.value))
            line += QStringLiteral(" ") + QString::fromStdString(v.choice.unit);
        lines << line;
    }
    return lines;
}

void paintProbe(QPainter& painter, QPointF at, const QString& title, const QStringList& lines,
                QSizeF widget) {
    QFont bold = painter.font();
    bold.setBold(true);
    const QFontMetricsF metrics(painter.font());
    const double line = metrics.height();
    double width = QFontMetricsF(bold).horizontalAdvance(title);
    for (const QString& text : lines) width = std::max(width, metrics.horizontalAdvance(text));
    width += line;
    const double height = (static_cast<double>(lines.size()) + 1.5) * line;
    // Beside the cursor, flipped to the other side where the widget ends.
    double x = at.x() + kProbeOffsetPx, y = at.y() + kProbeOffsetPx;
    if (x + width > widget.width()) x = at.x() - kProbeOffsetPx - width;
    if (y + height > widget.height()) y = at.y() - kProbeOffsetPx - height;
    const QRectF frame(std::max(0.0, x), std::max(0.0, y), width, height);
    painter.save();
    painter.setPen(QPen(kProbeRim, 1.0));
    painter.setBrush(kProbeBack);
    painter.drawRoundedRect(frame, 4, 4);
    // The probed point: a small cross, so the values say where they were read.
    painter.drawLine(at + QPointF(-5, 0), at + QPointF(5, 0));
    painter.drawLine(at + QPointF(0, -5), at + QPointF(0, 5));
    painter.setPen(Qt::white);
    for (qsizetype k = 0; k < lines.size(); ++k)
        painter.drawText(QRectF(frame.left() + 0.5 * line,
                                frame.top() + (static_cast<double>(k) + 1.25) * line, width - line, line),
                         Qt::AlignLeft | Qt::AlignVCenter, lines[k]);
    painter.setFont(bold);
    painter.drawText(QRectF(frame.left() + 0.5 * line, frame.top() + 0.25 * line, width - line, line),
                     Qt::AlignLeft | Qt::AlignVCenter, title);
    painter.restore();
}

void paintProfileLine(QPainter& painter, QLineF line) {
    painter.save();
    painter.setPen(QPen(QColor(0, 0, 0, 160), 4.0)); // a dark rim keeps it visible over a light field
    painter.drawLine(line);
    painter.setPen(QPen(kProfileLine, 2.0));
    painter.drawLine(line);
    painter.setBrush(kProfileLine);
    painter.drawEllipse(line.p1(), 4.0, 4.0); // the start: distance 0 in the Profile dock
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(line.p2(), 4.0, 4.0);
    painter.restore();
}

} // namespace pl::ui
