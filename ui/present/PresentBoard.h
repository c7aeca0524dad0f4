// What present mode shows for a scene, read from its kind's registration (ModelDescriptor::present) and,
// where the registration leaves a part empty, built from what the model offers: readouts from its first
// series columns, the first of its plots, lesson controls from its tools and parameters. So a new kind
// gets a useful board without a word of its own under ui/.
#pragma once

#include "catalog/ModelDescriptor.h"

#include <string>
#include <vector>

namespace pl::ui {

// The board's readouts: the registration's, or (none given) the first series columns other than the
// step count, each with its label and unit.
std::vector<PresentReadout> presentReadouts(const Model& model);
// The plot shown first: the registration's, or the kind's first distribution dock, or its first plot.
std::string presentPlot(const Model& model);
// The lesson's controls: the registration's, or those the model's capabilities allow (a gravity slider
// and switch where it has those parameters, heat and the spawn tool where it has tools, the piston where
// it can have one, the pace, and the field buttons where it samples fields).
std::vector<LessonControl> lessonControls(Model& model);
// The top of the gravity slider for the model's current parameters.
double gravityMaximum(const Model& model);
// What the particle-count control means for the model's kind, or nullptr where it has none.
const ParticleCountControl* particleCountControl(const Model& model);

} // namespace pl::ui
