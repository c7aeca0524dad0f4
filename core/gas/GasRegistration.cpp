// The gas's registration: its kind, units, parameters, creator, particle count, series and plots, once.
#include "GasSeries.h"
#include "catalog/ModelDescriptor.h"

namespace pl {

using namespace plot_colours;

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
                        }},
        .lighter =
            [](const ParamValues& values, double share) {
                return fewerParticles(values, share, {"count_a", "count_b"});
            },

        .contractPreset = "gas-classroom",
        .stateArrays = {.x = "x", .y = "y", .id = "id"},
    };
    return descriptor;
}

} // namespace pl
