// The wind tunnel's benchmark scale (ModelDescriptor::benchmark): tunnel-cylinder at n molecules, and the
// traffic its GPU step moves.
#include "TunnelBenchmarkScale.h"

#include "TunnelModel.h"
#include "TunnelParams.h"
#include "catalog/ModelCatalog.h"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {
Preset scaledPreset(std::size_t n) {
    Preset p = loadPreset("tunnel-cylinder");
    TunnelParams params;
    params = withValues(params, TunnelParams::fields(), p.params);
    const double preset = static_cast<double>(TunnelModel::initialFillCount(params, p.obstacles));
    const double ratio = static_cast<double>(std::max<std::size_t>(n, 1)) / std::max(preset, 1.0);
    // The grid refines with √ratio (the molecules per cell stay), up to the tunnel's cell limit.
    const double cells = static_cast<double>(params.cellsX) * static_cast<double>(params.cellsY);
    const double refine = std::min(std::sqrt(ratio), std::sqrt(TunnelParams::maxCells() / cells));
    // The free stream over the whole domain must fit the molecule limit (TunnelParams::validate), which the
    // body's share of the domain leaves room for below the top of the range only.
    const double fullStream = params.streamDensity * params.boxWidth * params.boxHeight;
    p.params["fn"] = std::max(params.fn / ratio, fullStream / TunnelParams::maxParticles() * (1.0 + 1e-12));
    const double cellsX = std::max(1.0, std::round(static_cast<double>(params.cellsX) * refine));
    const double cellsY = std::max(1.0, std::round(static_cast<double>(params.cellsY) * refine));
    p.params["cells_x"] = cellsX;
    p.params["cells_y"] = std::min(cellsY, std::floor(TunnelParams::maxCells() / cellsX)); // rounding up
    p.params["run_steps"] = 0.0;
    return p;
}

std::size_t largest() {
    return static_cast<std::size_t>(TunnelParams::maxParticles());
}
} // namespace

BenchmarkScale tunnelBenchmarkScale() {
    return {
        .scaledPreset = scaledPreset,
        .largest = largest,
        .limit = "the tunnel's molecule limit",
        .benchSizes = {100000, 1000000, 10000000},
        .sizesHelp =
            "Wind-tunnel sizes (molecules): tunnel-cylinder with collisions, F_N and the cell grid scaled",
        // TunnelModelGL, collisions on: the move reads a molecule (position 8, velocity 8 + 4) and writes it
        // moved with its (cell, slot) (28) plus a 4-byte atomic; the scatter reads that and a cell start
        // (32) and writes the sorted molecule (20); the collide-and-sample pass reads each velocity once
        // for the sums (12; pair reads hit the cache within a cell, about one accepted pair per molecule
        // writes 12 more). The scan and the per-cell arrays are ~1/40 of a word per molecule.
        .gpuBytesPerParticleStep = 52 + 52 + 24,
        .goalParticleStepsPerSecond = 2e9, // at 10 M molecules on an H200
        .colour = {200, 110, 40}};
}

} // namespace pl
