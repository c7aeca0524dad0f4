// Parameters of the soft-disk gas (reduced units: length L, mass M, time T, energy M·L²/T²).
#pragma once

#include "common/MemoryBudget.h"

#include "GasIntegratorTable.h"
#include "common/ParamSpec.h"

#include <string>
#include <vector>

namespace pl {

enum class GasInitVelocity { FixedSpeed, MaxwellBoltzmann };
enum class GasInitPlacement { Random, Lattice };
enum class GasForceMethod { CellList, AllPairs };
enum class GasWallMode { Reflecting, Thermal };
// The names of each choice as preset files and the command line spell them.
const ChoiceTable<GasInitVelocity>& choiceTable(GasInitVelocity);
const ChoiceTable<GasInitPlacement>& choiceTable(GasInitPlacement);
const ChoiceTable<GasForceMethod>& choiceTable(GasForceMethod);
const ChoiceTable<GasWallMode>& choiceTable(GasWallMode);

struct GasSpeciesParams {
    long long count = 0;           // number of disks; 0 disables the species
    double mass = 1.0;             // [M], typical 1, range [1e-6, 1e6]
    double diameter = 0.01;        // [L], typical 0.01 (write-up), range [1e-6, 1e3]
    std::string color = "#6e87b0"; // drawing colour when colouring by species
};

struct GasParams {
    // Box [−W/2, W/2] × [−H/2, H/2]; the write-up's box is [−1, 1]².
    double boxWidth = 2.0;  // [L], range [1e-3, 1e5]
    double boxHeight = 2.0; // [L], range [1e-3, 1e5]

    GasSpeciesParams a{4096, 1.0, 0.01, "#6e87b0"};
    GasSpeciesParams b{0, 4.0, 0.02, "#c87d3b"};

    double stiffness = 1000.0; // k of U = k/2 (d − r)² [M/T²], typical 1e3 (write-up), range [1e-6, 1e12]

    GasInitVelocity initVelocity = GasInitVelocity::FixedSpeed; // fixed speed (write-up) or Maxwell–Boltzmann
    double initSpeed = 1.0;                                     // fixed-speed magnitude [L/T], seed 1
    double initKT = 0.5;                                        // Maxwell–Boltzmann kT [M·L²/T²]
    GasInitPlacement initPlacement =
        GasInitPlacement::Random; // random (write-up; overlaps allowed) or lattice

    GasIntegrator integrator = GasIntegrator::VelocityVerlet; // an entry of GasIntegratorTable.h
    double dt = 1e-4; // signed time step [T]; negative runs time backwards
    GasForceMethod forceMethod = GasForceMethod::CellList; // or all pairs (the write-up's O(N²) loop)

    double gravity = 0.0;       // downward acceleration [L/T²] while gravityOn
    bool gravityOn = true;      // the gravity switch (key G), shared with the fluid
    bool pistonEnabled = false; // a movable vertical wall replacing the right wall
    double pistonX = 1.0;       // its position [L], must lie inside the box
    double pistonSpeed = 0.05;  // Compress / Expand speed of the piston [× initial rms speed]
    double toolSpeed = 0.3;     // fastest a dragged obstacle or piston moves [× initial rms speed]
    GasWallMode wallMode = GasWallMode::Reflecting; // or thermal (diffuse walls at wallKT)
    double wallKT = 0.5;                            // thermal wall temperature [M·L²/T²]

    long long maxParticles = 1 << 20;  // cap on disks, enforced by reset and spawning
    double spawnMaxOverlap = 0.25;     // refuse a spawned disk overlapping another by more than this × d
    long long histogramBins = 40;      // speed histogram bins
    double pressureWindow = 1.0;       // wall-pressure averaging window [T]
    double blowupEnergyFactor = 100.0; // stop when total energy exceeds this × the reference energy

    long long totalCount() const { return a.count + b.count; }
    const GasSpeciesParams& species(int s) const { return s == 0 ? a : b; }
    double maxDiameter() const;
    double appliedGravity() const { return gravityOn ? gravity : 0.0; } // acting now [L/T²]
    double left() const { return -0.5 * boxWidth; }
    double right() const { return pistonEnabled ? pistonX : 0.5 * boxWidth; }
    double bottom() const { return -0.5 * boxHeight; }
    double top() const { return 0.5 * boxHeight; }

    static const std::vector<ParamField<GasParams>>& fields();
    static const std::vector<ParamSpec>& describe();

    // Cross-field checks (the disks fit in the box and under the cap, the piston lies in the box). Throws
    // ParamError naming the key.
    void validate() const;
    // The most memory the state can come to hold, which the base checks after validate() (ModelBase.h).
    MemoryNeed memoryNeed() const;
};

} // namespace pl
