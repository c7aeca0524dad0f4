// Observables of the gas: energies, kT per species, momentum, virial and wall pressure, KS distance to
// the 2D Maxwell–Boltzmann distribution, contact rate, speed histograms. Sums are serial (deterministic).
#include "GasModel.h"
#include "GasSeries.h"
#include "common/Statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace pl {

namespace {
constexpr double kHistogramSigmas = 5.0; // speed histogram range: 0 … 5 √(kT/m) holds all but e^{-12.5}
const double kNaN = std::numeric_limits<double>::quiet_NaN();
} // namespace

const SeriesTable<GasObservables>& gasSeriesTable() {
    using O = GasObservables;
    static const SeriesTable<O> table{
        {{"step", "", "step"}, [](const O& o) { return static_cast<double>(o.step); }},
        {{"time", "T", "time"}, [](const O& o) { return o.time; }},
        {{"particles", "", "disks"}, [](const O& o) { return static_cast<double>(o.particles); }},
        {{"kinetic", "M·L²/T²", "kinetic energy"}, [](const O& o) { return o.kinetic; }},
        {{"potential", "M·L²/T²", "potential energy (pairs and gravity)"},
         [](const O& o) { return o.potential; }},
        {{"total", "M·L²/T²", "total energy"}, [](const O& o) { return o.total; }},
        {{"kT", "M·L²/T²", "kT (kinetic energy per disk)"}, [](const O& o) { return o.kT; }},
        {{"kT_a", "M·L²/T²", "kT of species A"}, [](const O& o) { return o.kTSpecies[0]; }},
        {{"kT_b", "M·L²/T²", "kT of species B"}, [](const O& o) { return o.kTSpecies[1]; }},
        {{"px", "M·L/T", "momentum x"}, [](const O& o) { return o.px; }},
        {{"py", "M·L/T", "momentum y"}, [](const O& o) { return o.py; }},
        {{"pressure_virial", "M/T²", "pressure from the virial"},
         [](const O& o) { return o.pressureVirial; }},
        {{"pressure_wall", "M/T²", "pressure from wall impulses"}, [](const O& o) { return o.pressureWall; }},
        {{"pressure_ideal", "M/T²", "ideal-gas pressure N kT / A"},
         [](const O& o) { return o.pressureIdeal; }},
        {{"ks_a", "", "KS distance to Maxwell–Boltzmann, A"}, [](const O& o) { return o.ksDistance[0]; }},
        {{"ks_b", "", "KS distance to Maxwell–Boltzmann, B"}, [](const O& o) { return o.ksDistance[1]; }},
        {{"collision_rate", "1/T", "contacts begun per time"}, [](const O& o) { return o.collisionRate; }},
        {{"energy_drift", "", "relative energy drift |E − E₀| / E₀"},
         [](const O& o) { return o.energyDrift; }},
    };
    return table;
}

std::vector<std::string> GasModel::seriesColumns() const {
    return gasSeriesTable().names();
}

std::vector<double> GasModel::sampleSeries() {
    return gasSeriesTable().sample(observe());
}

GasObservables GasModel::observe() {
    pullState();
    refreshEnergies();
    GasSums sums;
    const double mass[2] = {params_.a.mass, params_.b.mass};
    for (std::size_t i = 0; i < state_.size(); ++i) {
        const int s = state_.species[i];
        const double m = mass[s];
        sums.kinetic[s] += 0.5 * m * (state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i]);
        ++sums.count[s];
        sums.potential +=
            state_.potential[i] + m * params_.appliedGravity() * (state_.y[i] - params_.bottom());
        sums.px += m * state_.vx[i];
        sums.py += m * state_.vy[i];
        sums.virial += state_.virial[i];
        sums.impulse += state_.wallImpulse[i];
        sums.contactsBegun += state_.contactsBegun[i];
        state_.wallImpulse[i] = 0.0;
        state_.contactsBegun[i] = 0;
    }
    GasObservables o = summarise(sums);
    for (int s = 0; s < 2; ++s) {
        if (sums.count[s] < 2 || !(o.kTSpecies[s] > 0)) continue;
        std::vector<double> speeds;
        speeds.reserve(static_cast<std::size_t>(sums.count[s]));
        for (std::size_t i = 0; i < state_.size(); ++i)
            if (state_.species[i] == s) speeds.push_back(std::hypot(state_.vx[i], state_.vy[i]));
        const double kT = o.kTSpecies[s], m = mass[s];
        o.ksDistance[s] = ksDistance(speeds, [kT, m](double v) { return rayleighCdf(v, kT, m); });
    }
    return o;
}

GasObservables GasModel::summarise(const GasSums& sums) {
    GasObservables o;
    o.step = stepCount();
    o.time = time();
    o.particles = static_cast<std::size_t>(sums.count[0] + sums.count[1]);
    o.kinetic = sums.kinetic[0] + sums.kinetic[1];
    o.potential = sums.potential;
    o.px = sums.px;
    o.py = sums.py;
    o.total = o.kinetic + o.potential;
    const auto n = static_cast<double>(o.particles);
    // Reflecting walls do not conserve momentum: 2 degrees of freedom per disk
    // (docs/gas.md#temperature-and-degrees-of-freedom).
    o.kT = n > 0 ? o.kinetic / n : 0.0;
    for (int s = 0; s < 2; ++s)
        o.kTSpecies[s] = sums.count[s] > 0 ? sums.kinetic[s] / static_cast<double>(sums.count[s]) : kNaN;

    double area = (rightWall() - params_.left()) * params_.boxHeight;
    for (const auto& ob : obstacles_) area -= ob.grownArea(0.5 * params_.a.diameter);
    // Virial pressure (docs/gas.md#virial-pressure): P A = N kT + ½ Σ_{i<j} r_ij·f_ij.
    o.pressureIdeal = n * o.kT / area;
    o.pressureVirial = (n * o.kT + sums.virial) / area;

    // Wall pressure: impulse per unit wall length per unit time over the last pressure_window.
    const double elapsed = time() - lastSampleTime_;
    const double perimeter = 2.0 * (rightWall() - params_.left()) + 2.0 * params_.boxHeight;
    if (elapsed != 0.0) wallWindow_.push_back({sums.impulse, elapsed, perimeter * elapsed});
    double windowTime = 0.0;
    for (const auto& w : wallWindow_) windowTime += std::abs(w.duration);
    while (wallWindow_.size() > 1 &&
           windowTime - std::abs(wallWindow_.front().duration) >= params_.pressureWindow) {
        windowTime -= std::abs(wallWindow_.front().duration);
        wallWindow_.pop_front();
    }
    double windowImpulse = 0.0, windowPerimeterTime = 0.0;
    for (const auto& w : wallWindow_) windowImpulse += w.impulse, windowPerimeterTime += w.perimeterTime;
    o.pressureWall = windowPerimeterTime != 0.0 ? windowImpulse / windowPerimeterTime : kNaN;

    // A row taken with no time since the previous one (the first row of a resumed snapshot) describes the
    // interval that row did.
    if (elapsed != 0.0)
        lastCollisionRate_ = 0.5 * static_cast<double>(sums.contactsBegun) / std::abs(elapsed);
    o.collisionRate = lastCollisionRate_;
    lastSampleTime_ = time();
    o.ksDistance = {kNaN, kNaN};
    o.energyDrift =
        energyBaseline_ != 0.0 ? std::abs(o.total - energyBaseline_) / std::abs(energyBaseline_) : 0.0;
    return o;
}

double GasModel::histogramRange(double kT, double mass) const {
    return kT > 0 ? kHistogramSigmas * std::sqrt(kT / mass) : 1.0;
}

NamedHistogram GasModel::speedHistogram(int species) const {
    pullState();
    const double m = params_.species(species).mass;
    std::vector<double> speeds;
    double kinetic = 0.0;
    for (std::size_t i = 0; i < state_.size(); ++i) {
        if (state_.species[i] != species) continue;
        const double v2 = state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i];
        kinetic += 0.5 * m * v2;
        speeds.push_back(std::sqrt(v2));
    }
    const double kT = speeds.empty() ? 0.0 : kinetic / static_cast<double>(speeds.size());
    Histogram counts(0.0, histogramRange(kT, m), static_cast<std::size_t>(params_.histogramBins));
    for (double v : speeds) counts.add(v);
    const double ks = ksDistance(speeds, [kT, m](double v) { return rayleighCdf(v, kT, m); });
    return describeSpeedHistogram(species, kT, ks, std::move(counts));
}

NamedHistogram GasModel::describeSpeedHistogram(int species, double kT, double ks, Histogram counts) const {
    const double m = params_.species(species).mass;
    NamedHistogram h;
    h.name = species == 0 ? "speed_a" : "speed_b";
    h.label = species == 0 ? "species A" : "species B";
    h.axis = "speed [L/T]";
    h.counts = std::move(counts);
    h.theoryDensity = [kT, m](double v) { return rayleighPdf(v, kT, m); };
    std::ostringstream summary;
    summary.precision(3);
    const bool mixture = params_.a.count > 0 && params_.b.count > 0;
    summary << (mixture ? (species == 0 ? "A: " : "B: ") : "") << "kT = " << kT << ", KS distance " << ks;
    h.summary = summary.str();
    return h;
}

} // namespace pl
