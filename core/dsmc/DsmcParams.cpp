// The DSMC parameter table: units, ranges, tooltips, and which values act at once.
#include "DsmcParams.h"

#include <sstream>

namespace pl {

namespace {
constexpr double kMaxParticles = 1 << 26; // 67 M: 32 bytes each
} // namespace

double DsmcParams::mass() const {
    return massAmu * kAtomicMass;
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
        f.push_back(
            bindReal(&P::massAmu, makeSpec("mass_amu", "Molecular mass", "u", "Gas and cell",
                                           "Mass of one molecule; O2 is 32.", 1e-3, 1e6, 1, d.massAmu)));
        f.push_back(bindReal(&P::fn, makeSpec("fn", "Particle weight F_N", "", "Gas and cell",
                                              "Real molecules each simulated particle stands for (seed 5e8).",
                                              1e-6, 1e30, 0, d.fn, true)));
        f.push_back(bindReal(&P::cellVolume, makeSpec("cell_volume", "Cell volume", "m³", "Gas and cell",
                                                      "Volume of the collision cell (seed 1e-8).", 1e-30, 1e6,
                                                      0, d.cellVolume, true)));
        f.push_back(bindReal(&P::dt, makeSpec("dt", "Time step", "s", "Gas and cell",
                                              "Collision time step; keep ν Δt well below 1 (seed 2e-5).",
                                              1e-15, 1e3, 0, d.dt, true)));
        f.push_back(
            bindInteger(&P::runSteps, makeSpec("run_steps", "Run length", "steps", "Gas and cell",
                                               "The run stops after this many steps (seed 500); 0 runs on.",
                                               0, 1e12, 100, double(d.runSteps), true)));
        f.push_back(bindChoice(&P::crossSection,
                               makeChoice("cross_section", "Cross-section", "Collisions",
                                          "seed: σ = 1e-18 c_r^-1/2 m² as written; hard-sphere: σ = π d²; "
                                          "vhs: variable hard sphere (d_ref, T_ref, ω); maxwell: σ c_r "
                                          "constant.",
                                          true)));
        f.push_back(bindReal(&P::diameter, makeSpec("diameter", "Hard-sphere diameter", "m", "Collisions",
                                                    "Molecular diameter of the hard-sphere model.", 1e-12,
                                                    1e-6, 0, d.diameter, true)));
        f.push_back(bindReal(&P::vhsDiameter, makeSpec("vhs_d_ref", "VHS d_ref", "m", "Collisions",
                                                       "VHS reference diameter (O2: 4.07e-10).", 1e-12, 1e-6,
                                                       0, d.vhsDiameter, true)));
        f.push_back(bindReal(&P::vhsTref, makeSpec("vhs_T_ref", "VHS T_ref", "K", "Collisions",
                                                   "Temperature at which d = d_ref (273 K).", 1e-3, 1e6, 1,
                                                   d.vhsTref, true)));
        f.push_back(bindReal(&P::vhsOmega, makeSpec("vhs_omega", "VHS ω", "", "Collisions",
                                                    "Viscosity index: 0.5 hard sphere, 1 Maxwell, O2 0.77.",
                                                    0.5, 1.0, 0.01, d.vhsOmega, true)));
        f.push_back(
            bindReal(&P::maxwellSigmaCr, makeSpec("maxwell_sigma_cr", "Maxwell σ c_r", "m³/s", "Collisions",
                                                  "The constant σ c_r of Maxwell molecules.", 1e-30, 1e-5, 0,
                                                  d.maxwellSigmaCr, true)));
        f.push_back(bindReal(&P::sigmaCrMaxInit,
                             makeSpec("sigma_cr_max_init", "Initial (σ c_r)_max", "m³/s", "Collisions",
                                      "First guess of (σ c_r)_max (the seed: 1e-18); 0 estimates it from the "
                                      "initial state. It is raised whenever a pair exceeds it.",
                                      0, 1e-5, 0, d.sigmaCrMaxInit)));
        f.push_back(bindInteger(
            &P::velocityComponents,
            makeSpec("velocity_components", "Velocity components", "", "Collisions",
                     "3: molecules scatter isotropically in space; 2: velocities and scattering stay in the "
                     "plane, like the 2D disk gas (for comparing the two).",
                     2, 3, 1, double(d.velocityComponents))));
        f.push_back(
            bindChoice(&P::initial, makeChoice("initial", "Initial state", "Initial state",
                                               "two-beams: the seed's beams along x; maxwellian: one gas at "
                                               "rest; bkw: the BKW initial distribution (K₀ = 0.6).")));
        f.push_back(bindInteger(&P::countA, makeSpec("count_a", "Particles (beam 1)", "", "Initial state",
                                                     "Simulated particles of beam 1, or of the single gas.",
                                                     0, kMaxParticles, 100, double(d.countA))));
        f.push_back(bindInteger(&P::countB, makeSpec("count_b", "Particles (beam 2)", "", "Initial state",
                                                     "Simulated particles of beam 2 (two-beams only).", 0,
                                                     kMaxParticles, 100, double(d.countB))));
        f.push_back(bindReal(&P::driftA,
                             makeSpec("drift_a", "Beam 1 velocity", "m/s", "Initial state",
                                      "Velocity of beam 1 along x (seed 100).", -1e6, 1e6, 10, d.driftA)));
        f.push_back(bindReal(&P::driftB,
                             makeSpec("drift_b", "Beam 2 velocity", "m/s", "Initial state",
                                      "Velocity of beam 2 along x (seed 300).", -1e6, 1e6, 10, d.driftB)));
        f.push_back(
            bindReal(&P::temperature, makeSpec("temperature", "Temperature", "K", "Initial state",
                                               "Temperature of each beam, or of the single gas (seed 5).",
                                               1e-6, 1e7, 1, d.temperature)));
        f.push_back(bindReal(&P::histogramSpeedMax,
                             makeSpec("histogram_speed_max", "Histogram range", "m/s", "Observation",
                                      "Upper end of the speed histogram (seed 450).", 1e-3, 1e8, 10,
                                      d.histogramSpeedMax, true)));
        f.push_back(
            bindInteger(&P::histogramBins, makeSpec("histogram_bins", "Histogram bins", "", "Observation",
                                                    "Bins of the speed histogram (seed 25).", 2, 10000, 5,
                                                    double(d.histogramBins), true)));
        return f;
    }();
    return list;
}

const ChoiceTable<DsmcCrossSection>& choiceTable(DsmcCrossSection) {
    static const ChoiceTable<DsmcCrossSection> table{{DsmcCrossSection::Seed, "seed"},
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
