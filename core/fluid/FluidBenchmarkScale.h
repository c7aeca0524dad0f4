// How the machine benchmark scales the fluid (ModelDescriptor::benchmark, core/gl/MachineBenchmark.h).
#pragma once

#include "catalog/ModelDescriptor.h"

namespace pl {

// The dam break's fluid (2D kernels, ε = 1, h = 0.8, spacing 0.4) with about n particles in one block at
// most 64 rows tall (square below 4096 particles) in a tank twice as wide and 1.5 times as high,
// 5 iterations: a column five iterations hold at its rest density at every n.
BenchmarkScale fluidBenchmarkScale();

} // namespace pl
