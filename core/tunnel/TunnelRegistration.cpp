// The tunnel's registration: its kind, units, parameters, creator, particle count, series and plots, once.
#include "TunnelBenchmarkScale.h"
#include "TunnelSeries.h"
#include "catalog/ModelDescriptor.h"

namespace pl {

std::vector<TheoryRow> tunnelTheoryRows(const Model& model, const TimeSeries& series); // TunnelTheoryRows.cpp

using namespace plot_colours;

const ModelDescriptor& tunnelRegistration() {
    static const ModelDescriptor descriptor{
        .kind = "tunnel",
        .title = "Rarefied flow (DSMC)",
        .units =
            {"SI",
             "length m, time s, mass kg, temperature K; molecular mass in u; forces and F_N per m of depth",
             "s"},
        .specs = &TunnelParams::describe(),
        .create = []() -> std::unique_ptr<Model> { return std::make_unique<TunnelModel>(); },
        .particleCount =
            [](const Preset& preset) {
                const TunnelParams p = withValues(TunnelParams{}, TunnelParams::fields(), preset.params);
                // The count's open fractions take 8 bytes a cell: the cell limit first.
                validateParams(p);
                return TunnelModel::initialFillCount(p, preset.obstacles);
            },
        .series = tunnelSeriesTable().columns(),
        .plots = {{"forcesPlot",
                   "Forces on the bodies",
                   {"drag [N/m]", {{"drag", "drag", kBlue}, {"drag_avg", "drag, window mean", kBlue, true}}},
                   {"lift [N/m]",
                    {{"lift", "lift", kOrange}, {"lift_avg", "lift, window mean", kOrange, true}}},
                   true}, // needsBodies: no forces dock in the shock tube or Couette flow
                  {"particlesPlot",
                   "Molecules",
                   {"simulated molecules", {{"particles", "molecules", kBlue}}},
                   {"collisions per step", {{"collisions", "collisions", kRed}}}}},
        .distributions = {"speedHistogram"},
        // A molecule of a 2600 m/s stream crosses a 0.2 m tunnel in 0.8 s of wall time.
        .watchableRate = 1e-4,
        // Its time runs in microseconds at the watchable rate.
        .present = {.readouts = {{"particles", "molecules", "", 1.0, 'f', 0},
                                 {"collisions", "collisions per step", "", 1.0, 'f', 0},
                                 {"drag", "drag", "N/m", 1.0, 'g', 3, true},
                                 {"time", "t", "µs", 1e6, 'f', 1}},
                    .plot = "speedHistogram",
                    .controls = {LessonControl::Pace, LessonControl::FieldView}},
        // The molecules, and with them a step's work, are inversely proportional to F_N.
        .lighter =
            [](const ParamValues& values, double share) {
                ParamValues lighter;
                if (const auto fn = values.find("fn");
                    fn != values.end() && std::holds_alternative<double>(fn->second))
                    lighter["fn"] = std::get<double>(fn->second) / share;
                return lighter;
            },

        .contractPreset = "tunnel-couette",
        .stateArrays = {.x = "x", .y = "y"},

        .theoryRows = tunnelTheoryRows,
        .benchmark = tunnelBenchmarkScale(),
        .peer = "sparta",
    };
    return descriptor;
}

} // namespace pl
