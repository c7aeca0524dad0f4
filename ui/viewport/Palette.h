// Colour maps of the scenes: the gas write-up's 10-stop thermal palette, the fluid write-up's blue → red, and
// distinct colours for categories (species, beams). Shared by the CPU painter, the GL shader and legends.
#pragma once

#include "common/SceneView.h"

#include <QColor>
#include <QVector>

namespace pl::ui {

// Stops of a continuous map (evenly spaced over [0, 1]) or the colours of a categorical one.
const QVector<QColor>& paletteStops(ColourMap map);
bool isCategorical(ColourMap map);
// value in [0, 1] (clamped) for continuous maps; a category index for ColourMap::Category.
QColor paletteColour(ColourMap map, double value);

} // namespace pl::ui
