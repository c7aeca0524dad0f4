// Model no more than the scene needs: the 2D disk gas (every contact resolved) and planar DSMC (collisions
// sampled) start from the same two-beam velocities and relax; both curves of the kurtosis of v_x against
// collisions per particle, the wall time each needed, and a KS test that they end at one Maxwellian.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace pl::methods {

struct TwoBeamSetup {
    long long particles = 1024;
    double beamKT = 0.01;                // thermal spread of each beam, in units of m u² (u = beam speed)
    double collisionsPerParticle = 10;   // both run until each particle collided this often on average
    double areaFraction = 0.08;          // of the disk gas: dilute, so its collisions are binary
    double depthOverDiameter = 0.05;     // deepest overlap of a head-on beam contact (sets k)
    double omegaDt = 0.1;                // of the disk gas's contacts (velocity Verlet)
    double dsmcCollisionsPerStep = 0.02; // per particle: DSMC's dt, as a fraction of the collision time
    unsigned long long seed = 1;
};

struct RelaxationSample {
    double collisionsPerParticle = 0;
    double kurtosisVx = 0; // ⟨δv_x⁴⟩/⟨δv_x²⟩²: 1 for two cold beams, 3 for a Maxwellian
    double seconds = 0;    // wall time so far
};

struct RelaxationRun {
    std::string method; // "md" or "dsmc"
    std::vector<RelaxationSample> curve;
    std::vector<double> finalVx; // v_x / u of every particle at the end (the MD pools its last samples)
    double seconds = 0;          // wall time to reach the target collisions per particle
    long long steps = 0;
    long long particleSteps = 0;
};

struct GasVsDsmcResult {
    RelaxationRun md, dsmc;
    double ksDistance = 0, ksPValue = 0; // two-sample KS of the final v_x of the two
    double costRatio = 0;                // MD seconds / DSMC seconds
};

// The shared start: count velocities (v_x, v_y) in units of the beam speed, half at +1 and half at −1
// along x, each beam Maxwellian at beamKT, with zero total momentum.
std::vector<std::pair<double, double>> twoBeamVelocities(const TwoBeamSetup& setup);

// Each run reports its samples through onSample (may be empty); a true stop ends it early.
RelaxationRun relaxWithMd(const TwoBeamSetup& setup,
                          const std::function<void(const RelaxationSample&)>& onSample = {},
                          const std::atomic<bool>* stop = nullptr);
RelaxationRun relaxWithDsmc(const TwoBeamSetup& setup,
                            const std::function<void(const RelaxationSample&)>& onSample = {},
                            const std::atomic<bool>* stop = nullptr);
GasVsDsmcResult compareRelaxations(RelaxationRun md, RelaxationRun dsmc);

} // namespace pl::methods
