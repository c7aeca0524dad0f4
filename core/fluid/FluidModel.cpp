// FluidModel: parameters, reset, the step in the order of the paper's Algorithm 1, and the drain.
#include "FluidModel.h"
#include "FluidSpawnGrid.h"

#include "common/StopRequest.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace pl {

FluidModel::FluidModel() {
    reset();
}

void FluidModel::paramsChanged(const FluidParams& /*before*/) {
    refreshDerived();
    stateEdited();
}

void FluidModel::reset() {
    refreshDerived();
    restartClock();
    drained_ = 0;
    restBodies();
    errorMean_.clear();
    errorMax_.clear();
    state_.clear();
    if (params_.hasFill()) spawnLattice(params_.fillX0, params_.fillY0, params_.fillX1, params_.fillY1);
    stateEdited();
}

void FluidModel::refreshDerived() {
    kernels_ = fluid::Kernels::make(params_.h, params_.kernel, params_.selfDensity);
    if (params_.restDensitySource == FluidRestDensitySource::SpawnLattice) {
        // The density of a particle deep inside the square spawn grid: what freshly spawned fluid has.
        const double d = params_.spacing();
        const int reach = static_cast<int>(std::ceil(params_.h / d));
        double rho = kernels_.selfWeight();
        for (int a = -reach; a <= reach; ++a)
            for (int b = -reach; b <= reach; ++b)
                if (a != 0 || b != 0) rho += kernels_.w(d * d * (a * a + b * b));
        restDensity_ = rho;
    } else {
        restDensity_ = params_.restDensity;
    }
    scorr_.k = params_.scorrK;
    scorr_.n = static_cast<int>(params_.scorrN);
    const double dq = params_.scorrDq * params_.h;
    const double wRef = kernels_.w(dq * dq);
    scorr_.inverseReference = wRef > 0 ? 1.0 / wRef : 0.0;
}

fluid::Box FluidModel::confinementBox() const {
    return fluid::confinementBox(params_);
}

fluid::WallJitter FluidModel::wallJitter() const {
    constexpr double kJitterOverH = 1e-5; // Taichi's 1e-5 at h = 1.1
    return {seed_, static_cast<std::uint64_t>(stepCount()), kJitterOverH * params_.h};
}

// A stop request may end the step between the solver's passes (common/StopRequest.h): a step of
// millions of particles takes seconds.
void FluidModel::advance(double /*h*/) { // h = dt: the fluid runs forwards only
    advanceBodies();
    applyExternalForcesAndPredict();
    findNeighbours();
    const auto iterations = static_cast<std::size_t>(params_.iterations);
    errorMean_.assign(iterations, 0.0);
    errorMax_.assign(iterations, 0.0);
    const bool limited = params_.releaseLimit > 0;
    if (limited) solveNewCompression(); // the velocity's share of the correction (FluidSolver.cpp)
    for (std::size_t k = 0; k < iterations; ++k) {
        leaveIfAbandoning();
        computeLambdas(k);
        applyPositionCorrections();
    }
    if (limited) limitRelease();
    leaveSolverNumbers();
    updateVelocities();
    if (params_.vorticity > 0) applyVorticityConfinement();
    if (params_.cohesion > 0 || params_.adhesion > 0) applySurfaceForces();
    if (params_.xsph > 0) applyXsphViscosity();
    commitPositions();
}

void FluidModel::afterStep() {
    drainOverCap();

    for (std::size_t i = 0; i < state_.size(); ++i) {
        if (std::isfinite(state_.vx[i]) && std::isfinite(state_.vy[i])) continue;
        std::ostringstream hint;
        hint << "the solver diverged at dt = " << params_.dt << " with " << params_.iterations
             << " iterations and ε = " << params_.epsilon
             << ": use a smaller dt, more iterations or a larger ε";
        fail("particle " + std::to_string(i) + " has a non-finite velocity", hint.str());
        break;
    }
}

void FluidModel::drainOverCap() {
    const auto n = static_cast<long long>(state_.size());
    if (!params_.drain || n <= params_.maxParticles) return;
    // The write-up's drain: the excess leaves through the bottom, lowest particles first (ties by index, so
    // the choice is deterministic).
    std::vector<std::size_t> lowest(state_.size());
    std::iota(lowest.begin(), lowest.end(), 0);
    const auto excess = static_cast<std::size_t>(n - params_.maxParticles);
    std::nth_element(lowest.begin(), lowest.begin() + static_cast<long long>(excess) - 1, lowest.end(),
                     [this](std::size_t a, std::size_t b) {
                         return state_.y[a] != state_.y[b] ? state_.y[a] < state_.y[b] : a < b;
                     });
    std::vector<char> keep(state_.size(), 1);
    for (std::size_t k = 0; k < excess; ++k) keep[lowest[k]] = 0;
    state_.compact(keep);
    drained_ += static_cast<long long>(excess);
}

double FluidModel::toolSpeed() const {
    return params_.toolSpeed * params_.waveSpeed();
}

} // namespace pl
