// The gas's benchmark scale (ModelDescriptor::benchmark): the write-up's gas at n disks, and the traffic
// its GPU step moves.
#include "GasBenchmarkScale.h"

#include "GasIntegratorTable.h"
#include "GasParams.h"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {
Preset scaledPreset(std::size_t n) {
    Preset p;
    p.model = "gas";
    p.seed = 20240501;
    const double side = 2.0 * std::sqrt(static_cast<double>(n) / 4096.0);
    p.params = {{"box_width", side},
                {"box_height", side},
                {"count_a", static_cast<double>(n)},
                {"count_b", 0.0},
                {"diameter_a", 0.01},
                {"mass_a", 1.0},
                {"stiffness", 1000.0},
                {"init_velocity", std::string("fixed-speed")},
                {"init_speed", 1.0},
                {"init_placement", std::string("random")},
                {"integrator", gasIntegrator(GasIntegrator::VelocityVerlet).name},
                {"dt", 1e-4},
                {"max_particles", static_cast<double>(std::max<std::size_t>(n, 1))}};
    return p;
}

std::size_t largest() {
    return static_cast<std::size_t>(findSpec(GasParams::describe(), "count_a")->max);
}
} // namespace

BenchmarkScale gasBenchmarkScale() {
    return {.scaledPreset = scaledPreset,
            .largest = largest,
            .limit = "the gas's count_a range",
            .dialogSizes = {1024, 4096, 16384, 65536, 262144},
            .benchSizes = {4096, 16384, 65536, 262144, 1048576, 4194304},
            .sizesHelp =
                "Gas sizes (disks), each at most what half the physical memory holds (240 bytes a disk)",
            // Velocity Verlet on the GPU (GasModelGL): the count pass reads pos, vel, acc, tag (28) and
            // writes (cell, slot) (8) plus a 4-byte atomic; the scatter pass reads the same 28 + 8 + a 4-byte
            // cell start and writes pos, vel, tag (20); the scan reads, writes and clears about half a count
            // per disk (6); the force pass reads pos, vel, tag (20) and writes acc (8). Neighbour reads hit
            // the cache in cell order and are not counted.
            .gpuBytesPerParticleStep = 40 + 60 + 6 + 28,
            .goalBytesPerParticleStep = 150,
            .colour = {70, 120, 200}};
}

} // namespace pl
