// The fluid's time-series columns, one table (FluidObservables.cpp) that sampleSeries() and the registry
// read.
#pragma once

#include "FluidModel.h"
#include "common/SeriesTable.h"

namespace pl {

const SeriesTable<FluidObservables>& fluidSeriesTable();

} // namespace pl
