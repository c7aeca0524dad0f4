// The seed's 10-stop thermal palette (pale blue-white → navy → turquoise → ochre → maroon) for speeds.
#pragma once

#include <QColor>

namespace pl::ui {

// t in [0, 1] (clamped): linear interpolation between the ten stops.
QColor thermalColor(double t);

} // namespace pl::ui
