// Dense point scenes (the wind tunnel's 50 000 molecules) drawn as one image: each particle sets a 2 × 2
// pixel block to its colour. A software rasteriser spends most of a frame setting up the two tiny
// triangles of each antialiased dot; an image costs one pass over the particles and one texture.
#pragma once

#include "ViewTransform.h"
#include "common/SceneView.h"

#include <QImage>
#include <QRect>

namespace pl::ui {

// From this many particles drawn as points (radius 0) the viewports splat them into an image.
inline constexpr std::size_t kSplatParticles = 20000;
bool splatsParticles(const SceneView& scene);

// The scene's particles in the widget rectangle `area` (pixels outside stay transparent; the last
// particle drawn on a pixel wins, as the dots would overlap).
QImage splatParticles(const SceneView& scene, const ViewTransform& transform, QRect area);

} // namespace pl::ui
