// ViewportAxes: the axes of a view that is not physical space (a phase plot), drawn inside its box.
#include "ViewportAxes.h"

#include "i18n/Translations.h"

#include <QPainter>
#include <cmath>

namespace pl::ui {

namespace {
const QColor kWalls(200, 205, 220);
} // namespace

void paintAxes(QPainter& painter, const ViewTransform& transform, const SceneView& scene, const QRectF& box) {
    painter.setPen(QPen(kWalls, 1.0, Qt::DashLine));
    const QPointF origin = transform.toWidget(0, 0);
    painter.drawLine(QPointF(box.left(), origin.y()), QPointF(box.right(), origin.y()));
    painter.drawLine(QPointF(origin.x(), box.top()), QPointF(origin.x(), box.bottom()));
    // Tick values along the bottom and the left edge of what is visible, inside the box (the view's
    // margin is narrow): steps of 1, 2 or 5 × 10^k, about one per kTickSpacingPx, following zoom and pan.
    constexpr double kTickSpacingPx = 90.0, kTickPx = 5.0;
    const auto niceStep = [](double span, double pixels) {
        const double raw = std::abs(span) * kTickSpacingPx / std::max(pixels, 1.0);
        const double decade = std::pow(10.0, std::floor(std::log10(raw)));
        for (const double m : {1.0, 2.0, 5.0})
            if (m * decade >= raw) return m * decade;
        return 10.0 * decade;
    };
    const auto tickText = [](double v, double step) {
        return QString::number(std::abs(v) < 1e-6 * step ? 0.0 : v, 'g', 4);
    };
    const QFontMetricsF metrics(painter.font());
    const double line = metrics.height();
    const QRectF shown = box.intersected(QRectF(QPointF(0, 0), transform.size()));
    const QPointF low = transform.toWorld(shown.bottomLeft()), high = transform.toWorld(shown.topRight());
    painter.setPen(kWalls);
    double numbersWidth = 0; // of the y tick values, so the y label starts beside them
    if (shown.width() > 0 && shown.height() > 0 && high.x() > low.x() && high.y() > low.y()) {
        const double dx = niceStep(high.x() - low.x(), shown.width());
        for (double v = std::ceil(low.x() / dx) * dx; v <= high.x() + 1e-9 * dx; v += dx) {
            const double px = transform.toWidget(v, 0).x();
            painter.drawLine(QPointF(px, shown.bottom()), QPointF(px, shown.bottom() - kTickPx));
            painter.drawText(QRectF(px - 4 * line, shown.bottom() - kTickPx - line, 8 * line, line),
                             Qt::AlignCenter, tickText(v, dx));
        }
        const double dy = niceStep(high.y() - low.y(), shown.height());
        for (double v = std::ceil(low.y() / dy) * dy; v <= high.y() + 1e-9 * dy; v += dy) {
            const double py = transform.toWidget(0, v).y();
            const QString text = tickText(v, dy);
            painter.drawLine(QPointF(shown.left(), py), QPointF(shown.left() + kTickPx, py));
            painter.drawText(QRectF(shown.left() + kTickPx + 2, py - 0.5 * line, 8 * line, line),
                             Qt::AlignLeft | Qt::AlignVCenter, text);
            numbersWidth = std::max(numbersWidth, metrics.horizontalAdvance(text));
        }
    }
    // The axis names sit clear of the tick values: x above the bottom row, y right of the left column.
    painter.drawText(shown.adjusted(4, 0, -4, -(kTickPx + line + 2)), Qt::AlignRight | Qt::AlignBottom,
                     coreText(scene.xLabel));
    painter.drawText(shown.adjusted(kTickPx + numbersWidth + 12, 4, 0, 0), Qt::AlignLeft | Qt::AlignTop,
                     coreText(scene.yLabel));
}

} // namespace pl::ui
