// The fluid's registration: its kind, units, parameters, creator, particle count, series and plots, once.
#include "FluidBenchmarkScale.h"
#include "FluidSeries.h"
#include "FluidSpawnGrid.h"
#include "catalog/ModelDescriptor.h"

namespace pl {

std::vector<TheoryRow> fluidTheoryRows(const Model& model, const TimeSeries& series); // FluidTheoryRows.cpp

using namespace plot_colours;

namespace {
PlotPanel densityErrorPanel(bool profile) {
    PlotPanel panel{"compression ρ/ρ₀ − 1",
                    {{"density_error_mean", "mean", kBlue}, {"density_error_max", "max", kRed}},
                    true};
    if (profile) {
        panel.xLabel = "iterations done in the last step";
        panel.profile = true;
    }
    return panel;
}
} // namespace

const ModelDescriptor& fluidRegistration() {
    static const ModelDescriptor descriptor{
        .kind = "fluid",
        .title = "Fluid (position-based)",
        .units = {"mixed (L, s)", "length L, time s, unit particle mass; gravity in L/s²", "s"},
        .specs = &FluidParams::describe(),
        .create = []() -> std::unique_ptr<Model> { return std::make_unique<FluidModel>(); },
        .particleCount =
            [](const Preset& preset) {
                const FluidParams p = withValues(FluidParams{}, FluidParams::fields(), preset.params);
                return static_cast<std::size_t>(fluid::initialFillCount(p, preset.obstacles));
            },
        .series = fluidSeriesTable().columns(),
        .plots = {{"densityErrorPlot", "Density error", densityErrorPanel(true), densityErrorPanel(false)},
                  {"frontPlot",
                   "Dam-break front",
                   {"front Z = z / a",
                    {{"front_Z", "surge front", kBlue},
                     {"front_Z_shallow_water", "shallow-water bound 1 + 2T", kGrey, true}},
                    false,
                    "front_T",
                    "T = n t √(g/a)"},
                   {}},
                  {"flowPlot",
                   "Flow",
                   {"kinetic energy Σ ½ v²", {{"kinetic", "kinetic", kBlue}}},
                   {"neighbours within h",
                    {{"neighbours_mean", "mean", kGreen},
                     {"neighbours_max", "max", kOrange},
                     {"neighbours_min", "min", kGrey}}}}},
        .distributions = {},
        // A tank tens of L high under g = 9.8 L/s² empties in seconds of model time: ten a second keeps a
        // dam break to a few seconds on the screen.
        .watchableRate = 10.0,
        .present = {.readouts = {{"particles", "N", "", 1.0, 'f', 0},
                                 {"density_error_mean", "density error", "%", 100.0, 'f', 2},
                                 {"density_error_max", "worst density error", "%", 100.0, 'f', 1},
                                 {"time", "t", "s", 1.0, 'f', 2}},
                    .plot = "densityErrorPlot",
                    .controls = {LessonControl::GravitySwitch, LessonControl::Pour, LessonControl::Gravity,
                                 LessonControl::SpawnTool},
                    // Twice the write-up's g.
                    .gravityMaximum = [](const ParamValues&) { return 2 * 9.8; }},

        .contractPreset = "fluid-dam-break",
        .stateArrays = {.x = "x", .y = "y"},

        .theoryRows = fluidTheoryRows,
        .benchmark = fluidBenchmarkScale(),
    };
    return descriptor;
}

} // namespace pl
