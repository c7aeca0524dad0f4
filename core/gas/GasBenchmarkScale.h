// How the machine benchmark scales the gas (ModelDescriptor::benchmark, core/gl/MachineBenchmark.h).
#pragma once

#include "catalog/ModelDescriptor.h"

namespace pl {

// The write-up's gas (velocity Verlet, d = 0.01, k = 1000, speed 1) with n disks at the write-up's area
// fraction: the box grows as √(n / 4096).
BenchmarkScale gasBenchmarkScale();

} // namespace pl
