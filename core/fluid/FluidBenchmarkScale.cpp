// The fluid's benchmark scale (ModelDescriptor::benchmark): the dam break's fluid at n particles, and the
// traffic its GPU step moves.
#include "FluidBenchmarkScale.h"

#include "FluidParams.h"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {
constexpr double kFluidRows = 64.0; // the tallest block of the scaled fluid, in particles
constexpr int kIterations = 5;

Preset scaledPreset(std::size_t n) {
    Preset p;
    p.model = "fluid";
    p.seed = 20240501;
    const double h = 0.8, spacing = 0.5 * h;
    // A block at most kFluidRows particles tall, as wide as n needs: five Jacobi iterations hold a column
    // about that tall at its rest density, while a square block of 1M particles (1024 rows) collapses into
    // a layer compressed by 30 % with cells of 300+ particles, whose cost grows 4× as it piles up
    // (BENCHMARKS.md, "GPU backends", "Against the goals").
    const double rows = std::min(std::ceil(std::sqrt(static_cast<double>(n))), kFluidRows);
    const double width = std::ceil(static_cast<double>(n) / rows) * spacing, height = rows * spacing;
    // Room beside the block for it to spread, within what the parameters allow at both ends of the range:
    // at least 4 h across (a smaller box cannot hold the kernel's support), at most the box_width bound.
    const double widest = findSpec(FluidParams::describe(), "box_width")->max;
    const double boxWidth = std::clamp(2.0 * width + 1.0, 4.0 * h + 1.0, widest);
    const double boxHeight = std::max(1.5 * height + 1.0, 4.0 * h + 1.0);
    p.params = {{"kernel", std::string("2d")},
                {"self_density", true},
                {"rest_density_source", std::string("spawn-lattice")},
                {"epsilon", 1.0},
                {"h", h},
                {"spawn_spacing", 0.5},
                {"particle_radius", 0.2},
                {"iterations", double(kIterations)},
                {"dt", 0.01},
                {"box_width", boxWidth},
                {"box_height", boxHeight},
                {"fill_x0", 0.0},
                {"fill_y0", 0.0},
                {"fill_x1", width},
                {"fill_y1", height},
                {"max_particles", static_cast<double>(2 * n + 1024)}};
    return p;
}

// The particle cap, which the scaled preset sets to 2 n + 1024.
std::size_t largest() {
    return (static_cast<std::size_t>(findSpec(FluidParams::describe(), "max_particles")->max) - 1024) / 2;
}
} // namespace

BenchmarkScale fluidBenchmarkScale() {
    return {.scaledPreset = scaledPreset,
            .largest = largest,
            .limit = "the fluid's particle cap, which is 2 N + 1024 here",
            .dialogSizes = {2500, 10000, 40000, 160000},
            .benchSizes = {10000, 40000, 160000, 640000, 1048576},
            .sizesHelp = "Fluid sizes (particles, 5 iterations)",
            // FluidModelGL at 5 iterations: predict count 16 + 12, scatter 28 + 24 (x, v, x*), scan 3, per
            // iteration λ 8 + 4 and Δx 12 + 8, velocity 16 + 8. Neighbour reads hit the cache and are not
            // counted.
            .gpuBytesPerParticleStep = 28 + 52 + 3 + kIterations * (12 + 20) + 24,
            .goalBytesPerParticleStep = 700,
            .colour = {40, 160, 120}};
}

} // namespace pl
