// The DSMC cell's registration: its kind, units, parameters, creator, particle count, series and plots, once.
#include "DsmcSeries.h"
#include "catalog/ModelDescriptor.h"

namespace pl {

std::vector<TheoryRow> dsmcTheoryRows(const Model& model, const TimeSeries& series); // DsmcTheoryRows.cpp

using namespace plot_colours;

const ModelDescriptor& dsmcRegistration() {
    static const ModelDescriptor descriptor{
        .kind = "dsmc",
        .title = "Rarefied gas (DSMC)",
        .units = {"SI", "length m, time s, mass kg, temperature K; molecular mass in u", "s"},
        .specs = &DsmcParams::describe(),
        .create = []() -> std::unique_ptr<Model> { return std::make_unique<DsmcModel>(); },
        .particleCount =
            [](const Preset& preset) {
                const DsmcParams p = withValues(DsmcParams{}, DsmcParams::fields(), preset.params);
                return static_cast<std::size_t>(p.totalCount());
            },
        .series = dsmcSeriesTable().columns(),
        .plots = {{"temperaturesPlot",
                   "Temperatures",
                   {"temperature [K]", {{"Tx", "T_x", kBlue}, {"T_perp", "T_⊥", kOrange}, {"T", "T", kGrey}}},
                   {"|T_x − T_⊥| [K]", {{"anisotropy", "anisotropy", kRed}}, true}},
                  {"momentsPlot",
                   "Moments",
                   {"M_2k / M_2k(eq)",
                    {{"M4", "M4", kBlue},
                     {"M6", "M6", kGreen},
                     {"M8", "M8", kOrange},
                     {"M4_bkw", "M4 exact (BKW)", kBlue, true},
                     {"M6_bkw", "M6 exact (BKW)", kGreen, true},
                     {"M8_bkw", "M8 exact (BKW)", kOrange, true}}},
                   {"KL to Maxwellian", {{"kl_divergence", "KL divergence [nats]", kRed}}, true}},
                  {"collisionsPlot",
                   "Collisions",
                   {"pairs per step", {{"ng", "candidates ng", kBlue}, {"nc", "collisions nc", kRed}}},
                   {"(σ c_r)_max [m³/s]", {{"sigma_cr_max", "(σ c_r)_max", kGrey}}}}},
        .distributions = {"speedHistogram", "vxHistogram"},
        // The cell's relaxation (a few hundred steps of 10–20 µs) unfolds over a few seconds.
        .watchableRate = 0.005,
        .present = {.readouts = {{"Tx", "Tₓ", "K", 1.0, 'f', 0},
                                 {"T_perp", "T⊥", "K", 1.0, 'f', 0},
                                 {"collisions_per_particle", "collisions per particle", "", 1.0, 'f', 2},
                                 {"step", "step", "", 1.0, 'f', 0}},
                    .plot = "temperaturesPlot",
                    .controls = {LessonControl::Pace}},
        .lighter =
            [](const ParamValues& values, double share) {
                return fewerParticles(values, share, {"count_a", "count_b"});
            },

        .contractPreset = "dsmc-bkw",

        .theoryRows = dsmcTheoryRows,
        .peer = "sparta",
    };
    return descriptor;
}

} // namespace pl
