// Parameters of the position-based fluid (world units: L, s; unit particle mass). One table drives presets,
// the CLI and the UI. Defaults are the write-up's (80 × 40 world, h = 1.1, ε = 100, 5 iterations, Δt = 1/20).
#pragma once

#include "common/MemoryBudget.h"

#include "FluidKernels.h"
#include "common/ParamSpec.h"

#include <string>
#include <vector>

namespace pl {

// Where the rest density ρ₀ comes from: the value rest_density, or the density of the spawn lattice.
enum class FluidRestDensitySource { Value, SpawnLattice };
// The names of each choice as preset files and the command line spell them.
const ChoiceTable<FluidKernelConstants>& choiceTable(FluidKernelConstants);
const ChoiceTable<FluidRestDensitySource>& choiceTable(FluidRestDensitySource);

struct FluidParams {
    // World and external field
    double boxWidth = 80.0, boxHeight = 40.0; // box [0, W] × [0, H]
    bool gravityOn = true;                    // the write-up's toggle (key G), shared with the gas
    double gravity = 9.8;                     // downward acceleration [L/s²]; negative pulls up
    double gravityX = 0.0;                    // horizontal acceleration [L/s²]

    // Solver (Macklin & Müller 2013)
    double dt = 0.05;              // [s]
    long long runSteps = 0;        // a run stops here; 0 runs on (the write-up)
    long long iterations = 5;      // Jacobi iterations of λ and Δx per step
    double h = 1.1;                // kernel support radius [L]
    double neighbourFactor = 1.05; // neighbour search radius / h
    double epsilon = 100.0;        // constraint relaxation ε
    FluidKernelConstants kernel =
        FluidKernelConstants::Unnormalised3d; // 3D constants as written, or normalised in 2D
    bool selfDensity = false;                 // ρ_i includes W(0) (the paper); the write-up omits it
    FluidRestDensitySource restDensitySource = FluidRestDensitySource::Value; // or ρ of the spawn grid
    double restDensity = 1.0;                                                 // ρ₀
    double scorrK = 0.001, scorrDq = 0.3; // s_corr = −k (W(r) / W(Δq h))ⁿ
    long long scorrN = 4;
    double particleRadius = 0.3; // walls and obstacles keep centres this far away [L]
    double xsph = 0.0;           // XSPH viscosity c (paper: 0.01); 0: off
    // The density constraint as the inequality ρ_i ≤ ρ₀ (λ from max(C_i, 0)): compressed fluid pushes apart,
    // under-dense fluid (the free surface, along the walls) does not pull together. Off: eq. 1's equality,
    // whose λ_i > 0 at every under-dense particle pulls the fluid together (the write-up).
    bool compressionOnly = false;
    // Bound on the velocity that compression left from earlier steps may release, in units of |g| Δt per
    // step (FluidSolver.cpp, limitRelease): the solver runs twice, once on the full C_i and once on the
    // compression that arose during the step; their difference moves the positions, but adds at most
    // release_limit |g| Δt to the velocity. Typical 2, range 0–100; 0: off (the write-up, one solve).
    double releaseLimit = 0.0;
    double vorticity = 0.0; // vorticity confinement ε_vort; 0: off
    // Surface forces (Akinci et al. 2013; FluidSolver.cpp, applySurfaceForces), each as the acceleration its
    // spline gives at its peak [L/s²]: cohesion γ, the attraction between neighbours that surface tension
    // comes from (one neighbour at h/2), and adhesion β, the pull of a wall or obstacle on fluid 3h/4 from
    // it, so the fluid wets the walls. 0: off (the paper, the write-up).
    double cohesion = 0.0, adhesion = 0.0;

    // Particles
    double spawnSpacing = 0.8; // spawn lattice spacing / h
    long long maxParticles = 3000;
    bool drain = true; // over the cap, the lowest particles drain away (the write-up); off: spawns refused
    double fillX0 = 0, fillY0 = 0, fillX1 = 0, fillY1 = 0; // initial block of fluid; empty when x1 ≤ x0

    // Tools
    double toolSpeed = 0.25; // fastest a dragged obstacle moves [× √(g H), the shallow-water wave speed of
                             // a tank-deep layer]

    // Display
    double colourSpeedMax = 5.0; // speed at the red end of the colour scale [L/s]

    // The acceleration acting now [L/s²]: zero while gravity is off.
    double accelerationX() const { return gravityOn ? gravityX : 0.0; }
    double accelerationY() const { return gravityOn ? -gravity : 0.0; }
    // |g| [L/s²], also while switched off.
    double gravityMagnitude() const;
    double spacing() const { return spawnSpacing * h; }
    double neighbourRadius() const { return neighbourFactor * h; }
    bool hasFill() const { return fillX1 > fillX0 && fillY1 > fillY0; }
    // √(g H) [L/s] with g the gravity's magnitude (also while switched off) and H the tank height.
    double waveSpeed() const;
    long long fillCount() const; // particles of the initial block: its spawn grid
    // Cross-field checks; throws ParamError naming the key.
    void validate() const;
    // The most memory the state can come to hold, which the base checks after validate() (ModelBase.h).
    MemoryNeed memoryNeed() const;

    static const std::vector<ParamField<FluidParams>>& fields();
    static const std::vector<ParamSpec>& describe();
};

} // namespace pl
