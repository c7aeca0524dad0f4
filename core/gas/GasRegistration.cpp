// The gas's registration: its kind, units, parameters, creator, particle count, series and plots, once.
#include "GasBenchmarkScale.h"
#include "GasSeries.h"
#include "catalog/ModelDescriptor.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pl {

std::vector<TheoryRow> gasTheoryRows(const Model& model, const TimeSeries& series); // GasTheoryRows.cpp

using namespace plot_colours;

namespace {
constexpr double kCountRange = 2.0; // the particle control reaches twice the scene's starting N
constexpr double kMaxPacking = 0.4; // … but never past 40 % of the box covered by disks

GasParams gasParams(const ParamValues& values) {
    return withValues(GasParams{}, GasParams::fields(), values);
}

// Present mode's particle count: both species, in the box the piston leaves open at the start.
double largestCount(const ParamValues& values) {
    const GasParams p = gasParams(values);
    const double total = std::max<double>(1, static_cast<double>(p.totalCount()));
    const double meanDiscArea = std::numbers::pi / 4 *
                                (static_cast<double>(p.a.count) * p.a.diameter * p.a.diameter +
                                 static_cast<double>(p.b.count) * p.b.diameter * p.b.diameter) /
                                total;
    const double packed = kMaxPacking * p.boxWidth * p.boxHeight / meanDiscArea;
    return std::max(total, std::min({kCountRange * total, packed, static_cast<double>(p.maxParticles)}));
}

// N disks, each species keeping its share, drawn from a Maxwell–Boltzmann distribution at kT.
ParamValues restartWith(const ParamValues& values, double total, double kT) {
    const GasParams p = gasParams(values);
    const double shareA =
        p.totalCount() > 0 ? static_cast<double>(p.a.count) / static_cast<double>(p.totalCount()) : 1.0;
    const double a = std::round(shareA * total);
    return {{"count_a", a},
            {"count_b", total - a},
            {"init_velocity", std::string("maxwell-boltzmann")},
            {"init_kT", kT}};
}
} // namespace

const ModelDescriptor& gasRegistration() {
    static const ModelDescriptor descriptor{
        .kind = "gas",
        .title = "Gas (molecular dynamics)",
        .units = {"reduced (L, T, M)", "length L, time T, mass M; energies and kT in M·L²/T²", "T"},
        .specs = &GasParams::describe(),
        .create = []() -> std::unique_ptr<Model> { return std::make_unique<GasModel>(); },
        .particleCount =
            [](const Preset& preset) {
                const GasParams p = withValues(GasParams{}, GasParams::fields(), preset.params);
                return static_cast<std::size_t>(p.totalCount());
            },
        .series = gasSeriesTable().columns(),
        .plots = {{"energyPlot",
                   "Energy",
                   {"energy",
                    {{"kinetic", "kinetic", kBlue},
                     {"potential", "potential", kOrange},
                     {"total", "total", kGrey}}},
                   {"|E − E₀| / E₀", {{"energy_drift", "relative drift", kRed}}, true}},
                  {"thermodynamicsPlot",
                   "Thermodynamics",
                   {"pressure",
                    {{"pressure_wall", "P from wall impulses", kBlue},
                     {"pressure_virial", "P from the virial", kGreen},
                     {"pressure_ideal", "N kT / A", kGrey}}},
                   {"kT", {{"kT", "kT", kRed}, {"kT_a", "kT of A", kBlue}, {"kT_b", "kT of B", kOrange}}}}},
        .distributions = {"speedHistogram"},
        // At kT ≈ 0.5 a disk moves about 1 L per T: 2.5 T a second crosses the 2 L box in about a second,
        // and a dragged disc (tool speed 0.3 L/T) crosses it in under 3 s.
        .watchableRate = 2.5,
        .present = {.readouts = {{"particles", "N", "", 1.0, 'f', 0},
                                 {"kT", "kT"},
                                 {"pressure_wall", "P"},
                                 {"time", "t", "", 1.0, 'f', 2}},
                    .plot = "speedHistogram",
                    .controls = {LessonControl::Heat, LessonControl::ParticleCount, LessonControl::Gravity,
                                 LessonControl::Piston},
                    // The strongest gravity makes the scale height kT / (m g) a fifth of the box.
                    .gravityMaximum =
                        [](const ParamValues& values) {
                            const GasParams p = withValues(GasParams{}, GasParams::fields(), values);
                            const double kT =
                                p.initVelocity == GasInitVelocity::FixedSpeed
                                    ? 0.5 * p.a.mass * p.initSpeed * p.initSpeed // 2D: ½ m v² = kT
                                    : p.initKT;
                            return 5.0 * kT / (p.a.mass * p.boxHeight);
                        },
                    .particleCount = {.count =
                                          [](const ParamValues& values) {
                                              return static_cast<double>(gasParams(values).totalCount());
                                          },
                                      .largest = largestCount,
                                      .restartWith = restartWith,
                                      .temperatureColumn = "kT",
                                      .temperatureParameter = "init_kT"}},
        .lighter =
            [](const ParamValues& values, double share) {
                return fewerParticles(values, share, {"count_a", "count_b"});
            },

        .contractPreset = "gas-classroom",
        .stateArrays = {.x = "x", .y = "y", .id = "id"},

        .theoryRows = gasTheoryRows,
        .benchmark = gasBenchmarkScale(),
        .peer = "lammps",
    };
    return descriptor;
}

} // namespace pl
