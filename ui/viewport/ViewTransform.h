// World ↔ widget mapping of a viewport: aspect-correct (one scale for x and y), the scene fitted with a
// margin, then the user's zoom and pan. Follows resizes because fit() runs before every paint.
#pragma once

#include "common/SceneView.h"

#include <QPointF>
#include <QRectF>
#include <QSizeF>

namespace pl::ui {

class ViewTransform {
public:
    void fit(const SceneView& view, QSizeF widgetSize, double marginPx);
    QPointF toWidget(double x, double y) const {
        return {0.5 * size_.width() + scale_ * (x - cx_), 0.5 * size_.height() - scale_ * (y - cy_)};
    }
    QPointF toWorld(QPointF p) const {
        return {cx_ + (p.x() - 0.5 * size_.width()) / scale_, cy_ - (p.y() - 0.5 * size_.height()) / scale_};
    }
    QRectF toWidget(double left, double bottom, double right, double top) const {
        return QRectF(toWidget(left, top), toWidget(right, bottom));
    }
    double scale() const { return scale_; } // pixels per world unit
    QSizeF size() const { return size_; }
    double centreX() const { return cx_; }
    double centreY() const { return cy_; }

    void zoomAt(QPointF widgetPoint, double factor); // keeps the world point under the cursor still
    void panBy(QPointF deltaPx);
    void zoomToFit(); // back to the whole scene

private:
    QSizeF size_{1, 1};
    double scale_ = 1.0, cx_ = 0.0, cy_ = 0.0;
    double zoom_ = 1.0;
    bool panned_ = false;
};

} // namespace pl::ui
