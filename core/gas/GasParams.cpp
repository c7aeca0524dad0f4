// The gas model's parameter table: one row per field, with units, ranges and tooltips.
#include "GasParams.h"

#include "GasIntegratorTable.h"
#include "common/MemoryBudget.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <unistd.h>

namespace pl {

namespace {

constexpr double kMaxAreaFraction = 0.9; // beyond this the disks cannot be placed, even on a lattice
constexpr double kBytesPerDisk = 240.0;  // SoA state, accumulators, cell list and sorted copies
constexpr double kMaxDisks =
    1
    << 26; // upper bound of every count field (67 M)  // SoA state, accumulators, cell list and sorted copies

ParamSpec color(std::string key, std::string label, std::string group, std::string def) {
    ParamSpec s =
        makeSpec(key, label, "", group, "Colour of this species when disks are coloured by species.", 0, 0, 0,
                 std::move(def), true);
    s.kind = ParamKind::Color;
    return s;
}

// Species fields live one struct deeper; bind them through explicit get/set closures.
template <class T>
ParamField<GasParams> speciesField(GasSpeciesParams GasParams::*species, T GasSpeciesParams::*member,
                                   ParamSpec s) {
    ParamField<GasParams> f;
    if constexpr (std::is_same_v<T, long long>) s.kind = ParamKind::Integer;
    f.spec = std::move(s);
    f.get = [=](const GasParams& p) -> ParamValue {
        if constexpr (std::is_same_v<T, long long>)
            return static_cast<double>((p.*species).*member);
        else
            return (p.*species).*member;
    };
    f.set = [=](GasParams& p, const ParamValue& v) {
        if constexpr (std::is_same_v<T, long long>)
            (p.*species).*member = static_cast<long long>(std::get<double>(v));
        else
            (p.*species).*member = std::get<T>(v);
    };
    return f;
}

// The four rows of one species: count, mass, diameter, colour (keys count_a, mass_b, …).
void addSpecies(std::vector<ParamField<GasParams>>& f, GasSpeciesParams GasParams::*member,
                const std::string& name, const GasSpeciesParams& d, const std::string& countNote,
                const std::string& diameterNote) {
    const std::string key = name == "A" ? "a" : "b";
    const std::string group = "Species " + name;
    f.push_back(speciesField(member, &GasSpeciesParams::count,
                             makeSpec("count_" + key, "Disks (" + name + ")", "", group,
                                      "Number of disks of species " + name + "; " + countNote, 0, kMaxDisks,
                                      1, double(d.count))));
    f.push_back(speciesField(member, &GasSpeciesParams::mass,
                             makeSpec("mass_" + key, "Mass (" + name + ")", "M", group,
                                      "Mass of one " + name + " disk.", 1e-6, 1e6, 0.1, d.mass)));
    f.push_back(speciesField(member, &GasSpeciesParams::diameter,
                             makeSpec("diameter_" + key, "Diameter (" + name + ")", "L", group,
                                      "Contact diameter of one " + name + " disk." + diameterNote, 1e-6, 1e3,
                                      0.001, d.diameter)));
    f.push_back(speciesField(member, &GasSpeciesParams::color,
                             color("color_" + key, "Colour (" + name + ")", group, d.color)));
}

std::vector<ParamField<GasParams>> makeFields() {
    using P = GasParams;
    const GasParams d;
    std::vector<ParamField<P>> f;
    f.push_back(bindReal(&P::boxWidth, makeSpec("box_width", "Box width", "L", "Box",
                                                "Width of the container; the write-up's box is 2 wide.", 1e-3,
                                                1e5, 0.1, d.boxWidth)));
    f.push_back(bindReal(&P::boxHeight, makeSpec("box_height", "Box height", "L", "Box",
                                                 "Height of the container; the write-up's box is 2 high.",
                                                 1e-3, 1e5, 0.1, d.boxHeight)));
    addSpecies(f, &P::a, "A", d.a, "the write-up has 4096.", " The write-up uses 0.01.");
    addSpecies(f, &P::b, "B", d.b, "0 for a one-species gas.", "");
    f.push_back(bindReal(
        &P::stiffness,
        makeSpec("stiffness", "Stiffness k", "M/T²", "Interaction",
                 "Spring constant of the harmonic repulsion U = k/2 (d − r)²; the write-up uses 1000.", 1e-6,
                 1e12, 100, d.stiffness, true)));
    f.push_back(bindChoice(&P::initVelocity,
                           makeChoice("init_velocity", "Initial velocities", "Initial state",
                                      "fixed-speed: every disk at init_speed in a random direction (the "
                                      "write-up); maxwell-boltzmann: Gaussian components at init_kT.")));
    f.push_back(
        bindReal(&P::initSpeed, makeSpec("init_speed", "Initial speed", "L/T", "Initial state",
                                         "Speed of every disk for fixed-speed starts; the write-up uses 1.",
                                         0, 1e6, 0.1, d.initSpeed)));
    f.push_back(bindReal(&P::initKT, makeSpec("init_kT", "Initial kT", "M·L²/T²", "Initial state",
                                              "Temperature of maxwell-boltzmann starts and of spawned disks.",
                                              0, 1e12, 0.1, d.initKT, true)));
    f.push_back(bindChoice(&P::initPlacement,
                           makeChoice("init_placement", "Initial placement", "Initial state",
                                      "random: uniform positions, overlaps allowed (the write-up); "
                                      "lattice: a square lattice, no overlaps.")));
    f.push_back(bindChoice(
        &P::integrator,
        makeChoice("integrator", "Integrator", "Integration",
                   "Time-stepping method; velocity Verlet is symplectic and time-reversible.", true)));
    ParamSpec dt = makeSpec("dt", "Time step", "T", "Integration",
                            "Signed step; negative runs time backwards. The write-up uses 1e-4.", -1, 1, 1e-5,
                            d.dt, true);
    dt.nonZero = true;
    f.push_back(bindReal(&P::dt, dt));
    f.push_back(bindChoice(
        &P::forceMethod,
        makeChoice("force_method", "Force search", "Integration",
                   "cell-list: O(N) neighbour search; all-pairs: the write-up's O(N²) loop, for comparison.",
                   true)));
    f.push_back(
        bindReal(&P::gravity, makeSpec("gravity", "Gravity", "L/T²", "Walls and fields",
                                       "Downward acceleration; 0 for none.", 0, 1e6, 0.1, d.gravity, true)));
    f.push_back(bindBool(&P::gravityOn, makeSpec("gravity_on", "Gravity on", "", "Walls and fields",
                                                 "The gravity switch (key G); off, the disks feel none.", 0,
                                                 0, 0, d.gravityOn, true)));
    f.push_back(bindBool(&P::pistonEnabled, makeSpec("piston_enabled", "Piston", "", "Walls and fields",
                                                     "Replace the right wall by a movable piston.", 0, 0, 0,
                                                     d.pistonEnabled, true)));
    f.push_back(bindReal(&P::pistonX, makeSpec("piston_x", "Piston position", "L", "Walls and fields",
                                               "x of the piston; moving it compresses or expands the gas.",
                                               -5e4, 5e4, 0.01, d.pistonX, true)));
    f.push_back(bindReal(
        &P::pistonSpeed,
        makeSpec("piston_speed_factor", "Piston speed", "× rms speed", "Walls and fields",
                 "Speed of Compress and Expand, in units of the initial rms speed: well below 1 the gas "
                 "follows the adiabat T·A = const; near 1 it heats more.",
                 1e-4, 10, 0.01, d.pistonSpeed, true)));
    f.push_back(bindReal(
        &P::toolSpeed,
        makeSpec("tool_speed_factor", "Drag speed limit", "× rms speed", "Walls and fields",
                 "Fastest a dragged obstacle or the piston moves, in units of the initial rms speed: the "
                 "disks always meet a wall of finite speed, whatever the frame rate.",
                 1e-3, 100, 0.1, d.toolSpeed, true)));
    f.push_back(bindChoice(&P::wallMode, makeChoice("wall_mode", "Walls", "Walls and fields",
                                                    "reflecting: elastic walls; thermal: disks leave a wall "
                                                    "with velocities drawn at wall_kT (heating or cooling).",
                                                    true)));
    f.push_back(
        bindReal(&P::wallKT, makeSpec("wall_kT", "Wall kT", "M·L²/T²", "Walls and fields",
                                      "Temperature of thermal walls.", 0, 1e12, 0.05, d.wallKT, true)));
    f.push_back(bindInteger(&P::maxParticles, makeSpec("max_particles", "Particle cap", "", "Limits",
                                                       "Most disks the scene may hold; spawning stops here.",
                                                       1, kMaxDisks, 1000, double(d.maxParticles), true)));
    f.push_back(bindReal(
        &P::spawnMaxOverlap,
        makeSpec("spawn_max_overlap", "Spawn overlap limit", "d", "Limits",
                 "A spawned disk overlapping another by more than this fraction of a diameter is refused.", 0,
                 1, 0.05, d.spawnMaxOverlap, true)));
    f.push_back(bindInteger(&P::histogramBins, makeSpec("histogram_bins", "Histogram bins", "", "Observation",
                                                        "Bins of the speed histogram.", 5, 1000, 5,
                                                        double(d.histogramBins), true)));
    f.push_back(
        bindReal(&P::pressureWindow, makeSpec("pressure_window", "Pressure window", "T", "Observation",
                                              "Time over which wall impulses are averaged into a pressure.",
                                              1e-9, 1e9, 0.1, d.pressureWindow, true)));
    f.push_back(
        bindReal(&P::blowupEnergyFactor,
                 makeSpec("blowup_energy_factor", "Blow-up factor", "", "Observation",
                          "The run stops when the total energy exceeds this multiple of its reference.", 1.5,
                          1e12, 10, d.blowupEnergyFactor, true)));
    return f;
}

std::string number(double v) {
    std::ostringstream out;
    out.precision(6);
    out << v;
    return out.str();
}

} // namespace

const ChoiceTable<GasInitVelocity>& choiceTable(GasInitVelocity) {
    static const ChoiceTable<GasInitVelocity> table{{GasInitVelocity::FixedSpeed, "fixed-speed"},
                                                    {GasInitVelocity::MaxwellBoltzmann, "maxwell-boltzmann"}};
    return table;
}

const ChoiceTable<GasInitPlacement>& choiceTable(GasInitPlacement) {
    static const ChoiceTable<GasInitPlacement> table{{GasInitPlacement::Random, "random"},
                                                     {GasInitPlacement::Lattice, "lattice"}};
    return table;
}

const ChoiceTable<GasForceMethod>& choiceTable(GasForceMethod) {
    static const ChoiceTable<GasForceMethod> table{{GasForceMethod::CellList, "cell-list"},
                                                   {GasForceMethod::AllPairs, "all-pairs"}};
    return table;
}

const ChoiceTable<GasWallMode>& choiceTable(GasWallMode) {
    static const ChoiceTable<GasWallMode> table{{GasWallMode::Reflecting, "reflecting"},
                                                {GasWallMode::Thermal, "thermal"}};
    return table;
}

double GasParams::maxDiameter() const {
    double d = a.count > 0 ? a.diameter : 0.0;
    if (b.count > 0) d = std::max(d, b.diameter);
    return d > 0 ? d : std::max(a.diameter, b.diameter);
}

const std::vector<ParamField<GasParams>>& GasParams::fields() {
    static const std::vector<ParamField<GasParams>> f = makeFields();
    return f;
}

const std::vector<ParamSpec>& GasParams::describe() {
    static const std::vector<ParamSpec> s = specsOf(fields());
    return s;
}

// Spawning may fill the gas up to its cap, so the cap's disks must fit.
MemoryNeed GasParams::memoryNeed() const {
    const long long n = totalCount();
    return {static_cast<double>(maxParticles) * kBytesPerDisk, "max_particles", [n](double fitting) {
                const auto most = static_cast<long long>(fitting / kBytesPerDisk);
                return most >= n ? "use {max_particles} ≤ " + std::to_string(most)
                                 : "use at most " + std::to_string(most) +
                                       " disks ({count_a} + {count_b}, and {max_particles})";
            }};
}

void GasParams::validate() const {
    const long long n = totalCount();
    if (n > maxParticles)
        throw ParamError("count_a", "{count_a} + {count_b} = " + std::to_string(n) +
                                        " exceeds {max_particles} = " + std::to_string(maxParticles));
    if (pistonEnabled && !(pistonX > left() + maxDiameter() && pistonX <= 0.5 * boxWidth))
        throw ParamError("piston_x", "'{piston_x}' = " + number(pistonX) + " must lie inside the box, in (" +
                                         number(left() + maxDiameter()) + ", " + number(0.5 * boxWidth) +
                                         "]");
    const double area = (right() - left()) * boxHeight;
    const double disks =
        std::numbers::pi / 4 * (a.count * a.diameter * a.diameter + b.count * b.diameter * b.diameter);
    if (disks > kMaxAreaFraction * area) {
        const std::string key = b.count > 0 ? "count_b" : "count_a";
        throw ParamError(key, "the disks cover " + number(100 * disks / area) + " % of the " +
                                  number(right() - left()) + " × " + number(boxHeight) + " box; at most " +
                                  number(100 * kMaxAreaFraction) +
                                  " % fits (fewer or smaller disks, or a larger box)");
    }
    for (const auto* sp : {&a, &b})
        if (sp->count > 0 && (sp->diameter >= boxWidth || sp->diameter >= boxHeight))
            throw ParamError(sp == &a ? "diameter_a" : "diameter_b",
                             "a disk of diameter " + number(sp->diameter) + " does not fit in the box");
}

} // namespace pl
