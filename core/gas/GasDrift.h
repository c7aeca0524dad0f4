// The drift pass over one block of disks: kick, drift, walls and obstacles, kick, and the largest
// displacement since the neighbour-list build (defined in GasBoundaries.cpp, beside the walls it applies).
#pragma once

#include "GasBoundaries.h"
#include "GasThreadRange.h"

#include <cstdint>

namespace pl::gas {

struct DriftArrays {
    double* x;
    double* y;
    double* vx;
    double* vy;
    const double* ax;
    const double* ay;
    double* wallImpulse;
    const std::uint8_t* species;
    const std::uint32_t* id;
    const double* builtX; // positions at the list build; read only when tracking
    const double* builtY;
};

struct DriftStep {
    double kickBefore, h, kickAfter;
    bool track; // measure the displacement since the list build
};

// v += kickBefore a; x += h v; walls and obstacles; v += kickAfter a, for the disks of range. Sets
// escaped when a disk is still outside the box after one mirror, and raises worst to the largest squared
// displacement since the build. Bit-identical to doing each disk in turn with Boundaries::apply.
void driftBlock(const Boundaries& walls, const DriftStep& step, const DriftArrays& arrays,
                ParticleRange range, bool& escaped, double& worst);

} // namespace pl::gas
