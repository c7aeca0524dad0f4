// Accuracy against cost for the gas's integrators (the methods lab): each scheme over a range of dt for
// the same physical time, with its error, its force evaluations and its wall time per unit of time,
// and the order of convergence measured from the errors.
#pragma once

#include "common/Preset.h"

#include <string>
#include <vector>

namespace pl {
class GasModel;
struct GasParticle;
} // namespace pl

namespace pl::gas {

struct SweepPoint {
    std::string integrator;
    double dt = 0;
    double trajectoryError = 0; // at the horizon [L]: the pair's max |x − x_exact|, the gas's rms distance
    double energyError = 0;     // max |E − E₀| / E₀ over the steps
    double forcesPerTime = 0;   // force evaluations per unit of simulated time [1/T]
    double secondsPerTime = 0;  // wall time per unit of simulated time
    std::string failure;        // why the run stopped early (a blow-up); its errors are then not plotted
};

struct SweepOrder {
    std::string integrator;
    double measured = 0; // least-squares slope of log error against log dt
    int theory = 0;
};

struct SweepResult {
    std::vector<SweepPoint> points;
    std::vector<SweepOrder> orders;
};

// Two equal disks (m = 1, d = 0.1) pressed together by an overlap of 0.02 and released: the gap
// follows r(t) = d − δ cos ωt exactly while they touch, ω = √(2k). The horizon is 80 % of the quarter
// period after which they part, so every scheme integrates one smooth contact and its error converges
// at its theoretical order. stepsList: steps over the horizon (dt = horizon / steps).
SweepResult sweepHarmonicPair(const std::vector<std::string>& integrators, const std::vector<int>& stepsList,
                              double stiffness = 1000.0);

// The user's gas as a sweep's start: its parameters, obstacles and particles now, and where each disk
// is after the horizon by Forest–Ruth at a step far below every swept one (the reference trajectory).
struct GasReference {
    Preset preset;
    std::vector<GasParticle> start;
    double horizon = 0;
    double referenceDt = 0;
    std::vector<double> x, y; // reference positions at the horizon, by disk (start order)
};

// The gas as it is now (parameters, obstacles, particles): cheap, so a UI takes it on its own thread
// while the gas runs on, and hands it to a worker for the reference run.
GasReference captureGas(const GasModel& source);
// Runs the reference: horizon is simulated time, short enough that chaos has not yet amplified
// round-off (a few dozen of the user's steps); referenceDt its step. Both positive whatever the sign
// of the gas's dt.
void runReference(GasReference& reference, double horizon, double referenceDt);
// captureGas, then runReference.
GasReference gasReference(const GasModel& source, double horizon, double referenceDt);
// One point of the sweep from the user's gas: rms position error against the reference at the horizon,
// max relative energy error, cost. A blow-up fills failure instead of throwing.
SweepPoint sweepFromState(const GasReference& reference, const std::string& integrator, double dt);
// Each integrator at dt = horizon / steps for each of stepsList, with its measured order.
SweepResult sweepFromReference(const GasReference& reference, const std::vector<std::string>& integrators,
                               const std::vector<int>& stepsList);

// Slope of log(error) against log(dt), fitted over the points whose error is above noiseFloor.
double fitOrder(const std::vector<double>& dts, const std::vector<double>& errors, double noiseFloor = 1e-12);

} // namespace pl::gas
