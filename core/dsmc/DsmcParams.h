// Parameters of the DSMC cell (SI units: m, s, kg, K). One table drives presets, the CLI and the UI.
#pragma once

#include "common/MemoryBudget.h"

#include "common/ParamSpec.h"
#include "common/PhysicalConstants.h"

#include <string>
#include <vector>

namespace pl {

// σ c_r as a function of c_r: the write-up's σ = 1e-18 c_r^-1/2 m², hard spheres, VHS or Maxwell molecules.
enum class DsmcCrossSection { InverseRoot, HardSphere, Vhs, Maxwell };
// The initial velocities: the write-up's two beams along x, one Maxwellian gas at rest, or the BKW state.
enum class DsmcInitialState { TwoBeams, Maxwellian, Bkw };
// The names of each choice as preset files and the command line spell them.
const ChoiceTable<DsmcCrossSection>& choiceTable(DsmcCrossSection);
const ChoiceTable<DsmcInitialState>& choiceTable(DsmcInitialState);

struct DsmcParams {
    // Gas and cell (write-up: O2, F_N = 5e8, V_c = 1e-8 m³, Δt = 2e-5 s, 500 steps)
    double massAmu = 32.0;    // molecular mass [u]
    double fn = 5e8;          // real molecules per simulated particle
    double cellVolume = 1e-8; // [m³]
    double dt = 2e-5;         // [s]
    long long runSteps = 500; // the run stops here (as the write-up does); 0 runs on

    // Collision model: σ c_r as a function of the relative speed c_r
    DsmcCrossSection crossSection = DsmcCrossSection::InverseRoot;
    double diameter = 4.07e-10;      // hard-sphere diameter [m]
    double vhsDiameter = 4.07e-10;   // VHS reference diameter d_ref [m] (O2, Bird 1994 App. A)
    double vhsTref = 273.0;          // VHS reference temperature [K]
    double vhsOmega = 0.77;          // VHS viscosity index ω (O2)
    double maxwellSigmaCr = 1.5e-17; // σ c_r of Maxwell molecules [m³/s]
    double sigmaCrMaxInit = 0.0;     // first (σ c_r)_max [m³/s]; 0: estimated from the initial state
    // 3: isotropic scattering in space (a real gas); 2: velocities and scattering in the plane, the
    // velocity space of the 2D disk gas (the methods lab compares the two on one observable)
    long long velocityComponents = 3;

    // Initial state
    DsmcInitialState initial = DsmcInitialState::TwoBeams;
    long long countA = 1000;  // beam 1 (or all particles of a single population)
    long long countB = 1000;  // beam 2 (two-beams only)
    double driftA = 100.0;    // beam 1 velocity along x [m/s]
    double driftB = 300.0;    // beam 2 velocity along x [m/s]
    double temperature = 5.0; // of each beam, or of the Maxwellian / BKW state [K]

    // Observation
    double histogramSpeedMax = 450.0; // speed histogram range [0, max] [m/s] (write-up: 0–450, 25 bins)
    long long histogramBins = 25;

    double mass() const; // [kg]
    bool planar() const { return velocityComponents == 2; }
    long long totalCount() const { return initial == DsmcInitialState::TwoBeams ? countA + countB : countA; }
    // Cross-field checks; throws ParamError naming the key.
    void validate() const;
    // The most memory the state can come to hold, which the base checks after validate() (ModelBase.h).
    MemoryNeed memoryNeed() const;

    static const std::vector<ParamField<DsmcParams>>& fields();
    static const std::vector<ParamSpec>& describe();
};

} // namespace pl
