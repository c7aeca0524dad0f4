// The fluid's time-series columns, one table (PbfObservables.cpp) that sampleSeries() and the registry
// read.
#pragma once

#include "PbfModel.h"
#include "common/SeriesTable.h"

namespace pl {

const SeriesTable<PbfObservables>& pbfSeriesTable();

} // namespace pl
