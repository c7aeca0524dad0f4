// The DSMC parameter table: units, ranges, tooltips, and which values act at once.
#include "DsmcParams.h"
#include "MolecularParams.h"
#include "common/MemoryBudget.h"

#include <sstream>

namespace pl {

namespace {
constexpr double kMaxParticles = 1 << 26;  // 67 M: 32 bytes each
constexpr double kBytesPerParticle = 32.0; // velocities and origin (measured: 26 B each from 1 M to 4 M)

// The molecule (the table the wind tunnel shares, MolecularParams.h): the mass with the cell, the
// cross-section model in a section of its own; the defaults are O2, and the write-up's σ is used as written.
const MolecularParamsText kMolecule{
    .massGroup = "Gas and cell", .collisionGroup = "Collisions", .gas = "O2", .writeUpScene = true};
} // namespace

double DsmcParams::mass() const {
    return massAmu * kAtomicMass;
}

MemoryNeed DsmcParams::memoryNeed() const {
    return {static_cast<double>(totalCount()) * kBytesPerParticle, "count_a", [](double fitting) {
                return "use at most " + std::to_string(static_cast<long long>(fitting / kBytesPerParticle)) +
                       " particles ({count_a} + {count_b})";
            }};
}

void DsmcParams::validate() const {
    const long long n = totalCount();
    if (n < 2)
        throw ParamError("count_a",
                         "a DSMC cell needs at least 2 particles to collide ({count_a} + {count_b} = " +
                             std::to_string(n) + ")");
    if (static_cast<double>(n) > kMaxParticles)
        throw ParamError("count_a", std::to_string(n) + " particles exceed the limit of " +
                                        std::to_string(static_cast<long long>(kMaxParticles)));
    if (velocityComponents != 2 && velocityComponents != 3)
        throw ParamError("velocity_components",
                         "'{velocity_components}' must be 2 (in the plane) or 3 (in space), not " +
                             std::to_string(velocityComponents));
    if (planar() && initial == DsmcInitialState::Bkw)
        throw ParamError("velocity_components",
                         "the BKW solution is for 3 velocity components; use 3, or another initial state");
}

const std::vector<ParamField<DsmcParams>>& DsmcParams::fields() {
    using P = DsmcParams;
    static const std::vector<ParamField<P>> list = [] {
        const P d;
        std::vector<ParamField<P>> f;
        f.push_back(molecularMassField<P>(kMolecule));
        f.push_back(
            bindReal(&P::fn, makeSpec("fn", "Particle weight F_N", "", "Gas and cell",
                                      "Real molecules each simulated particle stands for (write-up: 5e8).",
                                      1e-6, 1e30, 0, d.fn, true)));
        f.push_back(bindReal(&P::cellVolume, makeSpec("cell_volume", "Cell volume", "m³", "Gas and cell",
                                                      "Volume of the collision cell (write-up: 1e-8).", 1e-30,
                                                      1e6, 0, d.cellVolume, true)));
        f.push_back(bindReal(&P::dt, makeSpec("dt", "Time step", "s", "Gas and cell",
                                              "Collision time step; keep ν Δt well below 1 (write-up: 2e-5).",
                                              1e-15, 1e3, 0, d.dt, true)));
        f.push_back(bindInteger(&P::runSteps,
                                makeSpec("run_steps", "Run length", "steps", "Gas and cell",
                                         "The run stops after this many steps (write-up: 500); 0 runs on.", 0,
                                         1e12, 100, double(d.runSteps), true)));
        for (auto& field : crossSectionFields<P>(kMolecule)) f.push_back(std::move(field));
        f.push_back(bindReal(&P::sigmaCrMaxInit,
                             makeSpec("sigma_cr_max_init", "Initial (σ c_r)_max", "m³/s", "Collisions",
                                      "First guess of (σ c_r)_max (write-up: 1e-18); 0 estimates it from the "
                                      "initial state. It is raised whenever a pair exceeds it.",
                                      0, 1e-5, 0, d.sigmaCrMaxInit)));
        f.push_back(bindInteger(
            &P::velocityComponents,
            makeSpec("velocity_components", "Velocity components", "", "Collisions",
                     "3: molecules scatter isotropically in space; 2: velocities and scattering stay in the "
                     "plane, like the 2D disk gas (for comparing the two).",
                     2, 3, 1, double(d.velocityComponents))));
        f.push_back(bindChoice(&P::initial,
                               makeChoice("initial", "Initial state", "Initial state",
                                          "two-beams: the write-up's beams along x; maxwellian: one gas at "
                                          "rest; bkw: the BKW initial distribution (K₀ = 0.6).")));
        f.push_back(bindInteger(&P::countA, makeSpec("count_a", "Particles (beam 1)", "", "Initial state",
                                                     "Simulated particles of beam 1, or of the single gas.",
                                                     0, kMaxParticles, 100, double(d.countA))));
        f.push_back(bindInteger(&P::countB, makeSpec("count_b", "Particles (beam 2)", "", "Initial state",
                                                     "Simulated particles of beam 2 (two-beams only).", 0,
                                                     kMaxParticles, 100, double(d.countB))));
        f.push_back(bindReal(&P::driftA, makeSpec("drift_a", "Beam 1 velocity", "m/s", "Initial state",
                                                  "Velocity of beam 1 along x (write-up: 100).", -1e6, 1e6,
                                                  10, d.driftA)));
        f.push_back(bindReal(&P::driftB, makeSpec("drift_b", "Beam 2 velocity", "m/s", "Initial state",
                                                  "Velocity of beam 2 along x (write-up: 300).", -1e6, 1e6,
                                                  10, d.driftB)));
        f.push_back(bindReal(&P::temperature,
                             makeSpec("temperature", "Temperature", "K", "Initial state",
                                      "Temperature of each beam, or of the single gas (write-up: 5).", 1e-6,
                                      1e7, 1, d.temperature)));
        f.push_back(bindReal(&P::histogramSpeedMax,
                             makeSpec("histogram_speed_max", "Histogram range", "m/s", "Observation",
                                      "Upper end of the speed histogram (write-up: 450).", 1e-3, 1e8, 10,
                                      d.histogramSpeedMax, true)));
        f.push_back(
            bindInteger(&P::histogramBins, makeSpec("histogram_bins", "Histogram bins", "", "Observation",
                                                    "Bins of the speed histogram (write-up: 25).", 2, 10000,
                                                    5, double(d.histogramBins), true)));
        return f;
    }();
    return list;
}

const ChoiceTable<DsmcCrossSection>& choiceTable(DsmcCrossSection) {
    static const ChoiceTable<DsmcCrossSection> table{{DsmcCrossSection::InverseRoot, "inverse-root"},
                                                     {DsmcCrossSection::HardSphere, "hard-sphere"},
                                                     {DsmcCrossSection::Vhs, "vhs"},
                                                     {DsmcCrossSection::Maxwell, "maxwell"}};
    return table;
}

const ChoiceTable<DsmcInitialState>& choiceTable(DsmcInitialState) {
    static const ChoiceTable<DsmcInitialState> table{{DsmcInitialState::TwoBeams, "two-beams"},
                                                     {DsmcInitialState::Maxwellian, "maxwellian"},
                                                     {DsmcInitialState::Bkw, "bkw"}};
    return table;
}

const std::vector<ParamSpec>& DsmcParams::describe() {
    static const std::vector<ParamSpec> list = specsOf(fields());
    return list;
}

} // namespace pl
