// The DSMC cell's report rows (ModelDescriptor::theoryRows): its moments against the exact BKW solution
// and the kurtosis of v_x against a Maxwellian's.
#include "common/Model.h"
#include "common/TheoryRows.h"

#include <cmath>

namespace pl {

namespace {
constexpr double kMaxwellianKurtosis = 3.0;
} // namespace

std::vector<TheoryRow> dsmcTheoryRows(const Model& /*model*/, const TimeSeries& series) {
    std::vector<TheoryRow> rows;
    const SeriesColumns columns(series);
    for (const int k : {4, 6, 8}) {
        const std::string name = std::string("M").append(std::to_string(k)); // GCC 12 misreads "M" + string
        const double measured = columns.last(name), exact = columns.last(name + "_bkw");
        if (!std::isfinite(measured) || !std::isfinite(exact)) continue;
        const std::string m = std::to_string(k);
        rows.push_back({"Moment M" + m + " / M" + m + "(eq) against BKW", theoryNumber(measured), "",
                        "exact (BKW) " + theoryNumber(exact) + "; error " + theoryNumber(measured - exact) +
                            " (" + theoryPercent((measured - exact) / exact) + ")"});
    }
    if (const double kurtosis = columns.last("kurtosis_vx"); std::isfinite(kurtosis))
        rows.push_back({"Kurtosis of v_x", theoryNumber(kurtosis), "",
                        "a Maxwellian's is 3; difference " + theoryNumber(kurtosis - kMaxwellianKurtosis)});
    return rows;
}

} // namespace pl
