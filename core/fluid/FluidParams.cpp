// The fluid's parameter table: units, ranges, tooltips, and which values act at once.
#include "FluidParams.h"
#include "common/MemoryBudget.h"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {
constexpr double kMaxParticles = 1 << 24; // 16 M
// State, solver copies, neighbour lists and the cell grid (measured: 730 B each at 125 k and 500 k).
constexpr double kBytesPerParticle = 800.0;
} // namespace

void FluidParams::validate() const {
    const auto n = [](double v) { return formatNumber(v, 6); };
    if (2.0 * particleRadius >= std::min(boxWidth, boxHeight))
        throw ParamError("particle_radius", "{particle_radius} = " + n(particleRadius) +
                                                " is too large: a particle does not fit in the " +
                                                n(boxWidth) + " × " + n(boxHeight) + " box");
    if (neighbourRadius() * 4 > std::min(boxWidth, boxHeight))
        throw ParamError("h", "{h} = " + n(h) + " is too large for the " + n(boxWidth) + " × " +
                                  n(boxHeight) + " box: it needs at least 4 h across");
    if (hasFill() && (fillX0 < 0 || fillY0 < 0 || fillX1 > boxWidth || fillY1 > boxHeight))
        throw ParamError("fill_x1", "the initial block must lie inside the box [0, " + n(boxWidth) +
                                        "] × [0, " + n(boxHeight) + "]");
    if (hasFill() && fillCount() > maxParticles)
        throw ParamError("max_particles",
                         "the initial block holds " + std::to_string(fillCount()) +
                             " particles, more than {max_particles} = " + std::to_string(maxParticles));
}

// Pouring may fill the tank up to its cap, so the cap's particles must fit.
MemoryNeed FluidParams::memoryNeed() const {
    return {static_cast<double>(maxParticles) * kBytesPerParticle, "max_particles", [](double fitting) {
                return "use {max_particles} ≤ " +
                       std::to_string(static_cast<long long>(fitting / kBytesPerParticle));
            }};
}

long long FluidParams::fillCount() const {
    if (!hasFill()) return 0;
    const double d = spacing();
    const auto columns =
        std::max<long long>(1, static_cast<long long>(std::floor((fillX1 - fillX0) / d + 1e-6)));
    const auto rows =
        std::max<long long>(1, static_cast<long long>(std::floor((fillY1 - fillY0) / d + 1e-6)));
    return columns * rows;
}

const std::vector<ParamField<FluidParams>>& FluidParams::fields() {
    using P = FluidParams;
    static const std::vector<ParamField<P>> list = [] {
        const P d;
        std::vector<ParamField<P>> f;
        const auto real = [&f](double P::*member, ParamSpec spec) {
            f.push_back(bindReal(member, std::move(spec)));
        };
        real(&P::boxWidth, makeSpec("box_width", "Box width", "L", "World",
                                    "Width of the tank (write-up: 80).", 1, 1e5, 1, d.boxWidth));
        real(&P::boxHeight, makeSpec("box_height", "Box height", "L", "World",
                                     "Height of the tank (write-up: 40).", 1, 1e5, 1, d.boxHeight));
        f.push_back(bindBool(&P::gravityOn,
                             makeSpec("gravity_on", "Gravity on", "", "World",
                                      "The write-up's gravity toggle (key G).", 0, 1, 1, d.gravityOn, true)));
        real(&P::gravity, makeSpec("gravity", "Gravity", "L/s²", "World",
                                   "Downward acceleration; 0 for none.", -1e4, 1e4, 0.5, d.gravity, true));
        real(&P::gravityX, makeSpec("gravity_x", "Gravity x", "L/s²", "World",
                                    "Horizontal component of gravity.", -1e4, 1e4, 0.5, d.gravityX, true));

        real(&P::dt, makeSpec("dt", "Time step", "s", "Solver", "Step Δt (write-up: 1/20 = 0.05).", 1e-6, 1,
                              0.005, d.dt, true));
        f.push_back(bindInteger(&P::runSteps,
                                makeSpec("run_steps", "Run length", "steps", "Solver",
                                         "The run stops after this many steps; 0 runs on (the write-up).", 0,
                                         1e12, 100, double(d.runSteps), true)));
        f.push_back(bindInteger(
            &P::iterations, makeSpec("iterations", "Iterations", "", "Solver",
                                     "Jacobi iterations of the density constraint per step (write-up: 5).", 1,
                                     1000, 1, double(d.iterations), true)));
        real(&P::h, makeSpec("h", "Kernel radius h", "L", "Solver",
                             "Support radius of the kernels (write-up: 1.1); spawn spacing is 0.8 h.", 1e-3,
                             1e4, 0.1, d.h));
        real(&P::neighbourFactor,
             makeSpec("neighbour_factor", "Neighbour radius / h", "", "Solver",
                      "Neighbours are searched within this multiple of h (write-up: 1.05).", 1, 3, 0.05,
                      d.neighbourFactor, true));
        real(&P::epsilon,
             makeSpec("epsilon", "Relaxation ε", "", "Solver",
                      "Added to the constraint's gradient norm; larger is softer (write-up: 100).", 0, 1e6, 1,
                      d.epsilon, true));
        f.push_back(bindChoice(&P::kernel, makeChoice("kernel", "Kernel constants", "Solver",
                                                      "3d: poly6 315/(64π h⁹), spiky 45/(π h⁶), as "
                                                      "written (3D constants in 2D); 2d: 4/(π h⁸) and "
                                                      "30/(π h⁵).",
                                                      true)));
        f.push_back(
            bindBool(&P::selfDensity,
                     makeSpec("self_density", "Self term in ρ", "", "Solver",
                              "Include W(0) in each particle's density, as SPH does (the write-up omits it).",
                              0, 1, 1, d.selfDensity, true)));
        f.push_back(bindChoice(&P::restDensitySource,
                               makeChoice("rest_density_source", "Rest density from", "Solver",
                                          "value: ρ₀ = rest_density; spawn-lattice: ρ₀ is the density of a "
                                          "particle inside the spawn grid, so spawned fluid starts at rest.",
                                          true)));
        real(&P::restDensity,
             makeSpec("rest_density", "Rest density ρ₀", "", "Solver",
                      "Target density with unit masses (write-up: 1).", 1e-9, 1e9, 0.1, d.restDensity, true));
        real(&P::scorrK, makeSpec("scorr_k", "s_corr k", "", "Solver",
                                  "Strength of the artificial pressure (write-up: 0.001); 0: off.", 0, 10,
                                  0.001, d.scorrK, true));
        real(&P::scorrDq, makeSpec("scorr_dq", "s_corr Δq / h", "", "Solver",
                                   "Reference distance of the artificial pressure (write-up: 0.3).", 0, 1,
                                   0.05, d.scorrDq, true));
        f.push_back(bindInteger(&P::scorrN, makeSpec("scorr_n", "s_corr n", "", "Solver",
                                                     "Exponent of the artificial pressure (write-up: 4).", 1,
                                                     16, 1, double(d.scorrN), true)));
        real(&P::particleRadius, makeSpec("particle_radius", "Particle radius", "L", "Solver",
                                          "Walls and obstacles keep particle centres this far away (0.3).", 0,
                                          100, 0.05, d.particleRadius, true));
        real(&P::xsph, makeSpec("xsph", "XSPH viscosity c", "", "Solver",
                                "Velocity smoothing of the paper (0.01 there); 0: off, as in the write-up.",
                                0, 1, 0.01, d.xsph, true));
        f.push_back(bindBool(
            &P::compressionOnly,
            makeSpec(
                "compression_only", "Pressure pushes only", "", "Solver",
                "The density constraint as ρ ≤ ρ₀: compressed fluid pushes apart, under-dense fluid (the "
                "free surface, along the walls) does not pull together. Off: the paper's equality, as in "
                "the write-up.",
                0, 1, 1, d.compressionOnly, true)));
        real(&P::releaseLimit,
             makeSpec(
                 "release_limit", "Release of old compression", "× |g| Δt", "Solver",
                 "Compression the solver left from earlier steps moves the particles but adds at most this "
                 "much velocity per step, so it is not released as a launch when gravity is switched off. "
                 "Costs a second solve. 0: off, as in the write-up.",
                 0, 100, 0.5, d.releaseLimit, true));
        real(&P::vorticity, makeSpec("vorticity", "Vorticity confinement ε", "", "Solver",
                                     "Re-injects vorticity lost to damping; 0: off, as in the write-up.", 0,
                                     100, 0.01, d.vorticity, true));
        real(&P::cohesion,
             makeSpec(
                 "cohesion", "Cohesion γ", "L/s²", "Solver",
                 "Attraction between neighbours, the origin of surface tension: it holds the free surface "
                 "together where nothing else does (gravity switched off). The pull of one neighbour at "
                 "h/2; 0: off, as in the paper and the write-up.",
                 0, 1000, 0.5, d.cohesion, true));
        real(
            &P::adhesion,
            makeSpec("adhesion", "Adhesion β", "L/s²", "Solver",
                     "Pull of the walls and obstacles on the fluid within h of them, so it wets them instead "
                     "of balling up under cohesion. The pull at 3h/4; 0: off, as in the paper and the "
                     "write-up.",
                     0, 1000, 0.5, d.adhesion, true));

        real(&P::spawnSpacing, makeSpec("spawn_spacing", "Spawn spacing / h", "", "Particles",
                                        "Grid spacing of spawned fluid in units of h (write-up: 0.8).", 0.2,
                                        2, 0.05, d.spawnSpacing, true));
        f.push_back(
            bindInteger(&P::maxParticles, makeSpec("max_particles", "Particle cap", "", "Particles",
                                                   "Most particles in the tank (write-up: 3000).", 1,
                                                   kMaxParticles, 100, double(d.maxParticles), true)));
        f.push_back(
            bindBool(&P::drain, makeSpec("drain", "Drain over the cap", "", "Particles",
                                         "On: the lowest particles drain away over the cap (the write-up); "
                                         "off: spawns over the cap are refused.",
                                         0, 1, 1, d.drain, true)));
        real(&P::fillX0, makeSpec("fill_x0", "Initial block x₀", "L", "Particles",
                                  "Left edge of the fluid present at t = 0.", 0, 1e5, 1, d.fillX0));
        real(&P::fillY0, makeSpec("fill_y0", "Initial block y₀", "L", "Particles",
                                  "Bottom edge of the fluid present at t = 0.", 0, 1e5, 1, d.fillY0));
        real(&P::fillX1, makeSpec("fill_x1", "Initial block x₁", "L", "Particles",
                                  "Right edge of the initial block; x₁ ≤ x₀ starts empty (the write-up).", 0,
                                  1e5, 1, d.fillX1));
        real(&P::fillY1, makeSpec("fill_y1", "Initial block y₁", "L", "Particles",
                                  "Top edge of the initial block.", 0, 1e5, 1, d.fillY1));
        real(&P::toolSpeed,
             makeSpec("tool_speed_factor", "Drag speed limit", "× √(g H)", "Tools",
                      "Fastest a dragged obstacle moves, in units of the wave speed √(g H) of a tank-deep "
                      "layer: the fluid always meets a wall of finite speed, whatever the frame rate.",
                      1e-3, 10, 0.05, d.toolSpeed, true));
        real(&P::colourSpeedMax,
             makeSpec("colour_speed_max", "Colour scale top", "L/s", "Display",
                      "Speed drawn fully red (write-up: 5).", 1e-6, 1e6, 0.5, d.colourSpeedMax, true));
        return f;
    }();
    return list;
}

double FluidParams::gravityMagnitude() const {
    return std::hypot(gravityX, gravity);
}

double FluidParams::waveSpeed() const {
    return std::sqrt(gravityMagnitude() * boxHeight);
}

const ChoiceTable<FluidKernelConstants>& choiceTable(FluidKernelConstants) {
    static const ChoiceTable<FluidKernelConstants> table{{FluidKernelConstants::Unnormalised3d, "3d"},
                                                         {FluidKernelConstants::Normalised2d, "2d"}};
    return table;
}

const ChoiceTable<FluidRestDensitySource>& choiceTable(FluidRestDensitySource) {
    static const ChoiceTable<FluidRestDensitySource> table{
        {FluidRestDensitySource::Value, "value"}, {FluidRestDensitySource::SpawnLattice, "spawn-lattice"}};
    return table;
}

const std::vector<ParamSpec>& FluidParams::describe() {
    static const std::vector<ParamSpec> list = specsOf(fields());
    return list;
}

} // namespace pl
