// The time-series docks of every scene, made from the plot specs of the model registrations
// (core/catalog/ModelDescriptor.h); the main window makes one dock per entry.
#pragma once

#include "SeriesPlot.h"

#include <vector>

namespace pl::ui {

const std::vector<SeriesPlotSpec>& seriesPlotSpecs();

// The kinds whose registration lists the distribution dock of this object name ("speedHistogram", …).
QStringList distributionKinds(const QString& distribution);

} // namespace pl::ui
