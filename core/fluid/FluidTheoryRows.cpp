// The fluid's report rows (ModelDescriptor::theoryRows): the density error against the methods lab's
// tolerance and the dam-break front against Ritter's shallow-water bound.
#include "FluidSweep.h"
#include "common/Model.h"
#include "common/TheoryRows.h"

#include <algorithm>
#include <cmath>

namespace pl {

std::vector<TheoryRow> fluidTheoryRows(const Model& /*model*/, const TimeSeries& series) {
    std::vector<TheoryRow> rows;
    const SeriesColumns columns(series);
    const std::vector<double> mean = columns.run("density_error_mean");
    const std::vector<double> worst = columns.run("density_error_max");
    if (!mean.empty()) {
        double sum = 0.0;
        for (double v : mean) sum += v;
        const double average = sum / static_cast<double>(mean.size());
        const double tolerance = fluid::FluidSweepSetup{}.tolerance;
        const bool within = average <= tolerance;
        rows.push_back({"Mean density error ρ/ρ₀ − 1, averaged over the run", theoryPercent(average), "",
                        "the methods lab's tolerance " + theoryPercent(tolerance) + ": " +
                            (within ? "within it, incompressible enough" : "above it, over-compressed"),
                        within});
    }
    if (!worst.empty())
        rows.push_back({"Largest compression of any particle in the run",
                        theoryPercent(*std::max_element(worst.begin(), worst.end())), "",
                        "at the end: " + theoryPercent(columns.last("density_error_max"))});
    const double front = columns.last("front_Z"), bound = columns.last("front_Z_shallow_water");
    if (std::isfinite(front) && std::isfinite(bound))
        rows.push_back(
            {"Surge front Z = z/a at T = " + theoryNumber(columns.last("front_T")), theoryNumber(front), "",
             "Ritter's shallow-water bound 1 + 2T = " + theoryNumber(bound) + ": " +
                 (front <= bound ? "below it, as measured fronts are (Martin & Moyce 1952)" : "above it"),
             front <= bound});
    return rows;
}

} // namespace pl
