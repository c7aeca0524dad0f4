// How the machine benchmark scales the wind tunnel (ModelDescriptor::benchmark, core/gl/MachineBenchmark.h).
#pragma once

#include "catalog/ModelDescriptor.h"

namespace pl {

// The `tunnel-cylinder` preset (hypersonic argon past a cylinder, collisions on) scaled to about n
// simulated molecules: F_N shrinks and the cell grid refines by √ of the ratio along each side, so the
// flow (density, Kn, Δt) and the molecules per cell stay the preset's and only the resolution grows.
BenchmarkScale tunnelBenchmarkScale();

} // namespace pl
