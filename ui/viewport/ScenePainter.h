// A scene drawn with QPainter alone, shared by the viewports (their particles and bodies) and by every
// picture made without a window: the recorder's frames and the lab report's image. Free functions over
// a SceneView and a ViewTransform, so they need no widget and no model.
#pragma once

#include "ViewTransform.h"
#include "common/SceneView.h"

#include <QImage>
#include <QRect>
#include <QSize>
#include <QString>
#include <optional>

class QPainter;

namespace pl::ui {

// The margin between a viewport's edge and its scene [px].
inline constexpr double kSceneMarginPx = 14.0;

// The particles (discs of their radius, points of a few pixels, or a splatted image for dense point
// scenes, ParticleSplat.h) within `clip`, the target's rectangle in pixels.
void paintSceneParticles(QPainter& painter, const ViewTransform& transform, const SceneView& scene,
                         QRect clip);

// The box, the axes of a non-spatial view, the scene's hint and its obstacles; `active` is drawn
// highlighted (hovered or dragged).
void paintSceneBodies(QPainter& painter, const ViewTransform& transform, const SceneView& scene,
                      std::optional<std::size_t> active = std::nullopt);

// The piston, thicker while it is dragged.
void paintScenePiston(QPainter& painter, const ViewTransform& transform, const SceneView& scene,
                      bool active = false);

// A sentence the user must read before going on (the run stopped: Reset), in a dark box in the middle
// of `area`, wrapped to fit.
void paintNotice(QPainter& painter, QRect area, const QString& text);

// The whole scene at `size` pixels as the software viewport shows it untouched (no tool, no probe):
// background, field, particles, bodies, piston and legends, fitted with kSceneMarginPx.
QImage renderScene(const SceneView& scene, QSize size);
// The same into a rectangle of a painter that draws a larger picture (a frame beside a plot).
void paintScene(QPainter& painter, const SceneView& scene, QRect area);

} // namespace pl::ui
