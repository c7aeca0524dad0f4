// The gas's time-series columns, one table (GasObservables.cpp) that sampleSeries() and the registry read.
#pragma once

#include "GasModel.h"
#include "common/SeriesTable.h"

namespace pl {

const SeriesTable<GasObservables>& gasSeriesTable();

} // namespace pl
