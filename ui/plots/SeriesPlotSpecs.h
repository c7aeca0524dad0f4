// The time-series docks of every scene: which columns each plots, with which labels and colours.
// A new scene adds its entries here; the main window makes one dock per entry.
#pragma once

#include "SeriesPlot.h"

#include <vector>

namespace pl::ui {

const std::vector<SeriesPlotSpec>& seriesPlotSpecs();

} // namespace pl::ui
