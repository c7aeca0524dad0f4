// The viewport in words, for a student who cannot see it: the accessible name and description a screen
// reader speaks for the scene. Both are built from the kind's registration (its title and present mode's
// readouts, PresentBoard.h) and the frame's scene, so every kind, a new one too, is described without a
// line of its own under ui/.
#pragma once

#include <QString>

namespace pl {
class Model;
struct SceneView;
} // namespace pl

namespace pl::ui {

class SeriesStore;

// "Scene: Gas (molecular dynamics)", in the UI's language.
QString sceneAccessibleName(const Model& model);

// What a sighted student reads off the picture, in sentences: how many particles and what their colour
// shows, the bodies and the piston, the scene's own hint, and the kind's readouts with their latest values
// from series ("N = 2000, kT = 0.474, P = 0.951, t = 12.30").
QString sceneAccessibleDescription(const Model& model, const SceneView& scene, const SeriesStore& series);

} // namespace pl::ui
