// The axes of a viewport whose scene is not physical space (SceneView::xLabel, yLabel): the zero lines,
// tick values that follow zoom and pan, and the axis names.
#pragma once

#include "ViewTransform.h"
#include "common/SceneView.h"

#include <QRectF>

class QPainter;

namespace pl::ui {

// box: the scene's rectangle in widget coordinates.
void paintAxes(QPainter& painter, const ViewTransform& transform, const SceneView& scene, const QRectF& box);

} // namespace pl::ui
