// The fluid's accuracy, cost and stability against dt × solver iterations (the methods lab). Each cell
// runs one experiment for the same physical time; its time-averaged and worst density error are the
// accuracy, its wall time per unit of simulated time the cost, and it is classified stable,
// over-compressed (mean density error above the tolerance) or exploded (diverged, or more kinetic
// energy than the fall through the box can release).
#pragma once

#include "common/Preset.h"
#include "common/sweep/CellOutcome.h"

namespace pl::fluid {

struct FluidSweepSetup {
    double duration = 1.0;      // simulated time of every cell [s]
    double tolerance = 0.01;    // time-averaged mean compression that counts as over-compressed
    double explosionFactor = 1; // mean ½v² above factor × g H_box cannot come from the fall
};

struct FluidCell {
    double dt = 0;
    int iterations = 0;
    double densityErrorMean = 0; // mean over steps of the mean compression after the last iteration
    double densityErrorMax = 0;  // largest compression of any particle at any step
    double stepSeconds = 0;      // wall time of the steps (not of setting the cell up)
    double secondsPerTime = 0;   // stepSeconds per unit of simulated time
    double maxSpeed = 0;         // largest speed seen [L/s]
    methods::CellStatus status;
};

// A quarter of the dam break (5 × 10 block, about 300 particles): the map's default experiment.
Preset smallDamBreak();

FluidCell runFluidCell(const Preset& base, double dt, int iterations, const FluidSweepSetup& setup = {});

} // namespace pl::fluid
