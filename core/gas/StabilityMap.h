// Stability maps of the gas's integrators (the methods lab): dt × stiffness, each cell a pair of disks
// colliding again and again in a small box, classified stable / inaccurate / unstable, to compare with
// the linear limits ω dt = 2 (Verlet, symplectic Euler), 2√2 (RK4), 1.57 (Forest–Ruth), none (explicit
// Euler).
#pragma once

#include "common/sweep/CellOutcome.h"

#include <string>
#include <vector>

namespace pl::gas {

struct StabilitySetup {
    long long steps = 4000;     // per cell; a blow-up ends the cell early
    double tolerance = 0.01;    // max |E − E₀|/E₀ above which a cell that ran through is inaccurate
    double blowUpFactor = 50.0; // oscillation energy above factor × its start is a blow-up
};

struct StabilityCell {
    std::string integrator;
    double dt = 0, stiffness = 0;
    double omegaDt = 0;     // ω dt with the caged disk's ω = √(2k/m)
    double energyError = 0; // max |E − E₀|/E₀ of the oscillation over the steps taken
    methods::CellStatus status;
};

// A harmonic pair that stays a pair: a light disk (m = 10⁻⁶, d = 0.1) caged between two heavy ones
// (m = 10⁶), each overlapping it by 0.2 d; it starts 10 % of that overlap off centre, so
// both contacts hold for the whole run and it oscillates at ω = √(2k/m) through the gas's own force
// loop and integrators. Growth by the blow-up factor keeps the amplitude far inside the overlap, so the
// linear limits apply. (A contact that begins from free flight lasts only π/(ω dt) steps; there Verlet
// already gains energy from ω dt ≈ 1.6 on. The map is about the integrators, not about that.)
// ω of the caged disk at stiffness k: √(2k), the contact frequency of two unit-mass disks of the gas
// (the cage's springs are k·m for its light disk of mass m), so a map cell (dt, k) stands for the same
// cell of a unit-mass gas; a gas of mass m sits at k/m. The map's dt for a given ω dt is ω dt / √(2k).
double cagedOmega(double stiffness);

StabilityCell runStabilityCell(const std::string& integrator, double dt, double stiffness,
                               const StabilitySetup& setup = {});

// The largest ω dt below the first unstable cell along one row (cells of one integrator and stiffness,
// in any order): the measured limit. NaN when no cell of the row blew up.
double measuredLimit(const std::vector<StabilityCell>& row);

} // namespace pl::gas
