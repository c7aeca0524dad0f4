// The gas's time-series columns, one table (MdObservables.cpp) that sampleSeries() and the registry read.
#pragma once

#include "MdModel.h"
#include "common/SeriesTable.h"

namespace pl {

const SeriesTable<MdObservables>& mdSeriesTable();

} // namespace pl
