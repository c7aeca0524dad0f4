// DSMC's accuracy against cost (the methods lab): particles per cell × ν dt, each cell's error the rms
// distance of its 4th and 6th normalised moments from the exact BKW curves over the relaxation, its cost
// the wall time. Noise falls as 1/√N, the time-step error with ν dt; the chart shows which one dominates.
#pragma once

#include "common/Preset.h"
#include "common/sweep/CellOutcome.h"

namespace pl::dsmc {

struct DsmcSweepSetup {
    double collisionTimes = 6; // the run: long enough for the moments to settle (BKW's e^(−t/6))
};

struct DsmcCell {
    long long particles = 0;
    double nuDt = 0;        // collision probability per particle and step
    double dt = 0;          // [s]
    double momentError = 0; // rms over the samples of (M4 − M4_BKW, M6 − M6_BKW)
    double seconds = 0;     // wall time of the steps
    methods::CellStatus status;
};

// base: Maxwell molecules from the BKW start (the dsmc-bkw preset). The number density stays that of
// the base: F_N is scaled with 1/N.
DsmcCell runDsmcCell(const Preset& base, long long particles, double nuDt, const DsmcSweepSetup& setup = {});

} // namespace pl::dsmc
