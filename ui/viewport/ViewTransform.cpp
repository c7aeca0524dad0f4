// ViewTransform: the fitted scale is recomputed for every paint; zoom multiplies it, pan moves the centre.
#include "ViewTransform.h"

#include <algorithm>

namespace pl::ui {

void ViewTransform::fit(const SceneView& view, QSizeF widgetSize, double marginPx) {
    size_ = QSizeF(std::max(1.0, widgetSize.width()), std::max(1.0, widgetSize.height()));
    const double w = std::max(view.right - view.left, 1e-12), h = std::max(view.top - view.bottom, 1e-12);
    const double fitted =
        std::max(1e-12, std::min((size_.width() - 2 * marginPx) / w, (size_.height() - 2 * marginPx) / h));
    scale_ = fitted * zoom_;
    if (!panned_) {
        cx_ = 0.5 * (view.left + view.right);
        cy_ = 0.5 * (view.bottom + view.top);
    }
}

void ViewTransform::zoomAt(QPointF widgetPoint, double factor) {
    const QPointF anchor = toWorld(widgetPoint);
    const double fitted = scale_ / zoom_;
    zoom_ = std::clamp(zoom_ * factor, 0.2, 200.0);
    scale_ = fitted * zoom_;
    cx_ = anchor.x() - (widgetPoint.x() - 0.5 * size_.width()) / scale_;
    cy_ = anchor.y() + (widgetPoint.y() - 0.5 * size_.height()) / scale_;
    panned_ = true;
}

void ViewTransform::panBy(QPointF deltaPx) {
    cx_ -= deltaPx.x() / scale_;
    cy_ += deltaPx.y() / scale_;
    panned_ = true;
}

void ViewTransform::zoomToFit() {
    zoom_ = 1.0;
    panned_ = false;
}

} // namespace pl::ui
