// What the viewport draws of a scene's sampled fields and its colour scales: the field as a colour map
// over its rectangle, the legends (particles and field), the click probe's table of local values and the
// profile line. Free functions over QPainter, shared by the GL and the QPainter viewport.
#pragma once

#include "ViewTransform.h"
#include "common/SampledFields.h"
#include "common/SceneView.h"

#include <QImage>
#include <QLineF>
#include <QPointF>
#include <QStringList>
#include <vector>

class QPainter;

namespace pl::ui {

// The field as an nx × ny image, one pixel per cell, row 0 at the top (the largest y); NaN cells are
// transparent so the background shows through them.
QImage fieldImage(const SceneFieldImage& field);
// The field stretched over its world rectangle (bilinear between cell centres).
void paintField(QPainter& painter, const ViewTransform& transform, const SceneFieldImage& field);

// The legends in the top right corner: the particles' colour scale (when particles are drawn) and below
// it the field's (title, minimum, the colour bar, maximum).
void paintLegends(QPainter& painter, const ViewTransform& transform, const SceneView& scene);

// A value for reading: 4 significant digits, very large or small ones as "1.23 × 10²¹"; "—" for NaN.
QString formatFieldValue(double value);
// The probe's lines: "label: value unit" for every value.
QStringList probeLines(const std::vector<FieldValue>& values);
// A table of lines beside the cursor at widget point `at`, kept inside the widget.
void paintProbe(QPainter& painter, QPointF at, const QString& title, const QStringList& lines, QSizeF widget);

// The profile line from a to b (widget points), with its ends marked.
void paintProfileLine(QPainter& painter, QLineF line);

} // namespace pl::ui
