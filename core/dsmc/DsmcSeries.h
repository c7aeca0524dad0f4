// The DSMC cell's time-series columns, one table (DsmcObservables.cpp) that sampleSeries() and the
// registry read.
#pragma once

#include "DsmcModel.h"
#include "common/SeriesTable.h"

namespace pl {

// One sample: the observables of the state and the counters of the last step.
struct DsmcSeriesRow {
    DsmcObservables observed;
    long long candidates = 0; // NTC candidate pairs ng of the last step
    long long collisions = 0; // accepted pairs nc of the last step
    double sigmaCrMax = 0.0;  // (σ c_r)_max [m³/s]
};

const SeriesTable<DsmcSeriesRow>& dsmcSeriesTable();

} // namespace pl
