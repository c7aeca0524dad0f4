// The gas's report rows (ModelDescriptor::theoryRows): the speeds against Maxwell–Boltzmann (the KS
// distance against its 1 % critical value, and the maximum-likelihood fit) and, once the piston has moved,
// kT·A against the adiabat of a 2D monatomic gas.
#include "GasModel.h"
#include "common/Statistics.h"
#include "common/TheoryRows.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace pl {

namespace {
constexpr double kKsSignificance = 0.01; // the 1 % critical value
constexpr double kAreaChanged = 0.05;    // a compression or expansion: the area changed by more than this
constexpr double kOnTheAdiabat = 0.05;   // kT·A within this of its start: the slow piston's adiabat

// Half the summed difference of the histogram's bin shares and the theory's (the total variation
// distance, 0 … 1): the share of the area where the two differ.
double areaOutsideTheory(const NamedHistogram& h) {
    const double total = h.counts.total();
    if (!(total > 0) || !h.theoryDensity) return NAN;
    double difference = 0.0;
    for (std::size_t i = 0; i < h.counts.bins(); ++i)
        difference += std::abs(h.counts.count(i) / total -
                               h.theoryDensity(h.counts.binCentre(i)) * h.counts.binWidth());
    return 0.5 * difference;
}

void speedRows(const Model& model, const SeriesColumns& columns, std::vector<TheoryRow>& rows) {
    const ParamValues params = model.params();
    const bool mixture = std::isfinite(columns.last("ks_a")) && std::isfinite(columns.last("ks_b"));
    const std::vector<NamedHistogram> histograms = model.histograms();
    for (const std::string species : {"a", "b"}) {
        const double ks = columns.last("ks_" + species);
        if (!std::isfinite(ks)) continue;
        const std::string of = mixture ? ", species " + std::string(1, char(std::toupper(species[0]))) : "";
        // All disks in a one-species scene, else the preset's count of the species.
        const auto count = params.find("count_" + species);
        const double n = !mixture ? columns.last("particles")
                         : count != params.end() && std::holds_alternative<double>(count->second)
                             ? std::get<double>(count->second)
                             : NAN;
        if (n >= 2) {
            const double critical = ksCritical(n, kKsSignificance);
            const bool consistent = ks <= critical;
            rows.push_back({"KS distance of the speeds to Maxwell–Boltzmann" + of, theoryNumber(ks), "",
                            "1 % critical value 1.63/√n = " + theoryNumber(critical) +
                                " for n = " + std::to_string(static_cast<long long>(n)) + " disks: " +
                                (consistent ? "consistent with Maxwell–Boltzmann"
                                            : "above it, not (yet) Maxwell–Boltzmann"),
                            consistent});
        }
        const double kT = columns.last(mixture ? "kT_" + species : "kT");
        const auto histogram =
            std::find_if(histograms.begin(), histograms.end(),
                         [&](const NamedHistogram& h) { return h.name == "speed_" + species; });
        if (std::isfinite(kT) && histogram != histograms.end())
            rows.push_back(
                {"Maxwell–Boltzmann fit of the speeds" + of + ": kT", theoryNumber(kT), "M·L²/T²",
                 "maximum-likelihood fit (the mean kinetic energy per disk in the plane); the histogram "
                 "differs from the fitted curve by " +
                     theoryPercent(areaOutsideTheory(*histogram)) + " of its area"});
    }
}

// A compression or expansion by the piston: on the adiabat of a 2D monatomic ideal gas (γ = 2) kT·A stays
// what it was (docs/gas.md); a fast piston drives a compression wave and heats more. The area is the one
// the ideal-gas pressure was computed with, A = N kT / p_ideal.
void compressionRows(const SeriesColumns& columns, std::vector<TheoryRow>& rows) {
    const auto area = [&](bool atEnd) {
        const auto read = [&](const std::string& name) {
            return atEnd ? columns.last(name) : columns.first(name);
        };
        return read("particles") * read("kT") / read("pressure_ideal");
    };
    const double a0 = area(false), a1 = area(true);
    if (!std::isfinite(a0) || !std::isfinite(a1) || !(a0 > 0) || std::abs(a1 / a0 - 1.0) <= kAreaChanged)
        return;
    const double ratio = columns.last("kT") * a1 / (columns.first("kT") * a0);
    const bool adiabatic = std::abs(ratio - 1.0) <= kOnTheAdiabat;
    rows.push_back(
        {"kT·A at the end against its start (area × " + theoryNumber(a1 / a0) + ")", theoryNumber(ratio), "",
         std::string("on the adiabat of a 2D monatomic gas (γ = 2) kT·A stays constant: ") +
             (adiabatic     ? "within 5 %, a slow (adiabatic) change"
              : ratio > 1.0 ? "heated beyond the adiabat (a fast piston's compression wave, or Heat)"
                            : "cooled below the adiabat (Cool, or a fast expansion)"),
         adiabatic});
}
} // namespace

std::vector<TheoryRow> gasTheoryRows(const Model& model, const TimeSeries& series) {
    std::vector<TheoryRow> rows;
    const SeriesColumns columns(series);
    speedRows(model, columns, rows);
    compressionRows(columns, rows);
    return rows;
}

} // namespace pl
