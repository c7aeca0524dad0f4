// Everything the application knows about one model kind, written once in the kind's registration file
// (gas/GasRegistration.cpp, dsmc/DsmcRegistration.cpp, fluid/FluidRegistration.cpp,
// tunnel/TunnelRegistration.cpp) and read by the catalog, the backend factory, the CLI and the UI.
// Qt-free: plots are described as data the UI draws.
#pragma once

#include "common/Model.h"
#include "common/Preset.h"
#include "common/SeriesTable.h"
#include "common/TheoryRows.h"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace pl {

struct PlotColour {
    int red = 0, green = 0, blue = 0; // sRGB, 0…255
};

struct PlotCurve {
    std::string column; // a series column; in a profile panel, a profile's name
    std::string label;  // legend text
    PlotColour colour;
    bool dashed = false; // exact theory drawn beside the measured curve
};

struct PlotPanel {
    std::string yLabel;
    std::vector<PlotCurve> curves; // none: the panel is absent
    bool logarithmic = false;
    std::string xColumn = "time"; // the series column on the x axis
    std::string xLabel{};         // empty: "time"
    // A profile panel plots the model's profiles() of its latest state instead of series columns.
    bool profile = false;
};

// One time-series dock of the kind: an upper panel and an optional lower one.
struct PlotSpec {
    std::string name;  // stable: dock layout and export file names use it, e.g. "energyPlot"
    std::string title; // the dock's title
    PlotPanel upper;
    PlotPanel lower;
    // Shown only while the scene has a body: the forces on none would read 0 (the shock tube).
    bool needsBodies = false;
};

// The units a kind's parameters, series and presets are written in: one system per kind, declared in its
// registration and shown from there (the parameter panel's first line, `particlelab-cli list` and the
// help of `run`, `bench` and `columns`).
struct UnitSystem {
    std::string name;    // short, for a line or a column: "reduced (L, T, M)", "SI"
    std::string summary; // each quantity and its unit: "length L, time T, mass M; energies and kT in M·L²/T²"
    std::string time;    // the unit of time, as the status bar writes it: "T", "s"
};

// One number on present mode's board: a series column as the class reads it.
struct PresentReadout {
    std::string column; // one of the kind's series columns
    std::string label;  // "kT", "Tₓ"
    std::string unit{}; // after the number; empty: none
    double scale = 1.0; // shown value = column × scale (a fraction as per cent, seconds as µs)
    char format = 'g';  // 'f': fixed decimals, 'g': significant digits
    int precision = 3;  // decimals ('f') or significant digits ('g')
    // Shown only while the scene has a body: the forces on none would read 0 (the shock tube).
    bool needsBodies = false;
};

// How a readout writes a value: plain digits from 10⁻⁴ up to a million (2000 particles read "2000", not
// "2E+03"; a value of 10^precision or more as a whole number), an exponent beyond. The UI writes it in its
// language's digits (QLocale::toString(value, format, precision)).
struct NumberFormat {
    char format = 'g';
    int precision = 3;
};
NumberFormat readoutFormat(const PresentReadout& readout, double value);

// The large controls a lesson can have in present mode (ui/present/LessonControls.cpp draws them).
enum class LessonControl {
    Heat,          // held to a side it heats or cools (needs the scene's tools)
    ParticleCount, // restarts with N particles at the temperature reached (PresentSpec::particleCount)
    Piston,        // the piston switch and compress / stop / expand (piston_enabled)
    Gravity,       // a slider for `gravity` from 0 to PresentSpec::gravityMaximum
    GravitySwitch, // the `gravity_on` switch
    Pour,          // held, it adds small blocks of particles at the top (spawning)
    SpawnTool,     // chooses the viewport's spawn tool
    Pace,          // steps per frame, or the automatic pace
    FieldView,     // what the viewport shows: one button per `view` choice (sampled fields)
};

// What "the number of particles" and "the temperature" are in the kind's parameters: present mode's
// particle-count control (LessonControl::ParticleCount) restarts the experiment with N particles at the
// temperature reached, so a class compares pressures at equal temperature.
struct ParticleCountControl {
    // The particles the parameters start with now.
    double (*count)(const ParamValues& values) = nullptr;
    // The most the control offers for these parameters (the box and the cap decide).
    double (*largest)(const ParamValues& values) = nullptr;
    // The values that restart with `total` particles (each species keeping its share) at `temperature`.
    ParamValues (*restartWith)(const ParamValues& values, double total, double temperature) = nullptr;
    std::string temperatureColumn{};    // the series column of the temperature reached ("kT")
    std::string temperatureParameter{}; // the starting temperature's parameter, the fallback ("init_kT")
};

// What present mode shows for the kind. A part left empty is built from what the kind offers
// (ui/present/PresentBoard.h): readouts from its first series columns, its first distribution dock or
// plot, and controls from its tools and parameters.
struct PresentSpec {
    std::vector<PresentReadout> readouts;
    std::string plot; // shown first: a PlotSpec::name or a distribution dock ("speedHistogram")
    std::vector<LessonControl> controls;
    // The gravity slider's top for the scene's parameters (at least twice the gravity it has); nullptr:
    // twice the scene's or the default gravity.
    double (*gravityMaximum)(const ParamValues& values) = nullptr;
    // The particle-count control's meaning; without it the kind offers no such control.
    ParticleCountControl particleCount{};
};

// How the machine benchmark (core/gl/MachineBenchmark.h: the desktop's "Benchmark this machine" and
// particlelab-bench) times the kind at growing N. A kind without scaledPreset is not benchmarked.
struct BenchmarkScale {
    // The kind's benchmark experiment with about n particles.
    Preset (*scaledPreset)(std::size_t n) = nullptr;
    // The most particles scaledPreset may be asked for, and what sets that limit (for the bench's help).
    std::size_t (*largest)() = nullptr;
    std::string limit{};
    std::vector<std::size_t> dialogSizes{}; // the desktop dialog's N on each backend; empty: not there
    std::vector<std::size_t> benchSizes{};  // particlelab-bench's default sizes (its --KIND option)
    std::string sizesHelp{};                // that option's help: what a size counts
    // The GPU twin's traffic [bytes per particle-step] counted from its kernels' loads and stores (a model,
    // not a measurement), and the goal a GPU point is set against: the copy bandwidth divided by
    // goalBytesPerParticleStep, or a fixed goalParticleStepsPerSecond where that is set instead.
    double gpuBytesPerParticleStep = 0;
    double goalBytesPerParticleStep = 0;
    double goalParticleStepsPerSecond = 0;
    PlotColour colour{}; // its curves in the dialog's plot
};

struct StateArrayNames {
    std::string x{}, y{}, id{};
};

struct ModelDescriptor {
    std::string kind;  // "gas": presets' "model", resources/presets/<kind>/, the CLI's scene names
    std::string title; // "Gas (molecular dynamics)"
    UnitSystem units;
    const std::vector<ParamSpec>* specs = nullptr;
    // A CPU model reset to its defaults.
    std::unique_ptr<Model> (*create)() = nullptr;
    // The particles reset(preset) makes, computed from the preset's parameters and obstacles without
    // building a model. Throws ParamError for a value its specs refuse.
    std::size_t (*particleCount)(const Preset& preset) = nullptr;
    // What sampleSeries() returns, column for column (from the model's SeriesTable).
    std::vector<SeriesColumn> series;
    std::vector<PlotSpec> plots;
    // The distribution docks that apply, by the UI's dock name: "speedHistogram", "vxHistogram".
    std::vector<std::string> distributions;
    // The fastest the app runs the kind's scenes [units.time of simulated time per second of wall time]:
    // the motion stays watchable on a fast machine (a slow one runs slower). The app's automatic pace
    // steps up to it, and Heat / Cool are a rate per simulated time derived from it (docs/gas.md).
    double watchableRate = 0.0;
    PresentSpec present;
    // A lighter experiment for a machine that cannot keep the watchable pace: the values that make each
    // step about `share` (0 < share < 1) of its work now, by the parameters that set the particle count
    // (the gas's and the DSMC cell's counts; the tunnel's F_N, to which the molecules are inversely
    // proportional). nullptr: the kind has none to offer. The app offers it in the status bar and the
    // teacher decides; the new values take effect at a reset.
    ParamValues (*lighter)(const ParamValues& values, double share) = nullptr;
    // The preset the model contract (tests/core/tst_model_contract.cpp) starts from, by name: one of the
    // kind's built-in presets, its teaching scene. Empty: the kind's defaults (a kind without presets).
    std::string contractPreset{};
    // The snapshot arrays that hold each particle's position, and its identity where the model reorders
    // its arrays (a spatial sort; empty: the arrays keep the particles' order). The contract matches the
    // particles of a run with time reversed to those of its start through them.
    StateArrayNames stateArrays{};
    // The key readouts at the end of a run beside their theory, with verdicts (common/TheoryRows.h), for a
    // model of the kind and the series its run sampled: the lab report's "Readouts against theory" and a
    // lesson's checks read the same rows. nullptr: no theory applies.
    std::vector<TheoryRow> (*theoryRows)(const Model& model, const TimeSeries& series) = nullptr;
    BenchmarkScale benchmark{};
    // The peer program the kind is handed to (`particlelab-cli export PEER`, docs/scale-out.md): "lammps",
    // "sparta"; empty: none.
    std::string peer{};
};

// lighter() for a kind whose work per step follows its particle counts: each named count × share, at
// least 1 where it was not 0.
ParamValues fewerParticles(const ParamValues& values, double share, const std::vector<std::string>& counts);

// Colours the plot specs share, so the scenes' docks read alike.
namespace plot_colours {
inline constexpr PlotColour kBlue{40, 90, 170}, kOrange{220, 120, 20}, kGreen{40, 140, 70}, kRed{190, 40, 40},
    kGrey{90, 90, 90};
} // namespace plot_colours

// A preset of this kind with every parameter at its spec default, seed 1 and no obstacles: what a new
// experiment starts from.
Preset defaultPreset(const ModelDescriptor& descriptor);

} // namespace pl
