// The wind tunnel's time-series columns, one table (TunnelObservables.cpp) that sampleSeries() and the
// registry read.
#pragma once

#include "TunnelModel.h"
#include "common/SeriesTable.h"

namespace pl {

// One sample: the observables and the step and time they were taken at.
struct TunnelSeriesRow {
    std::int64_t step = 0;
    double time = 0;
    TunnelObservables observed;
};

const SeriesTable<TunnelSeriesRow>& tunnelSeriesTable();

} // namespace pl
