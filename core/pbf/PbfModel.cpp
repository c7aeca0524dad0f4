// PbfModel: parameters, reset, the step in the order of the paper's Algorithm 1, and the drain.
#include "PbfModel.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace pl {

PbfModel::PbfModel() {
    reset();
}

ParamValues PbfModel::params() const {
    return valuesOf(params_, PbfParams::fields());
}

void PbfModel::setParams(const ParamValues& values) {
    PbfParams next = withValues(params_, PbfParams::fields(), values);
    next.validate();
    pullState();
    params_ = next;
    refreshDerived();
    stateEdited();
}

void PbfModel::reset(const Preset& preset) {
    if (preset.model != kind())
        throw PresetError("model", "preset is for model '" + preset.model + "', not fluid");
    PbfParams next;
    try {
        next = withValues(PbfParams{}, PbfParams::fields(), preset.params);
        next.validate();
    } catch (const ParamError& e) {
        throw PresetError("params." + e.key(), e.what());
    }
    params_ = next;
    seed_ = preset.seed;
    obstacles_ = preset.obstacles;
    reset();
}

void PbfModel::reset() {
    refreshDerived();
    step_ = 0;
    time_ = 0.0;
    drained_ = 0;
    failure_.reset();
    obstacleDrive_.clear();
    for (Obstacle& o : obstacles_) o.vx = o.vy = 0.0;
    errorMean_.clear();
    errorMax_.clear();
    state_.clear();
    if (params_.hasFill()) spawnLattice(params_.fillX0, params_.fillY0, params_.fillX1, params_.fillY1);
    stateEdited();
}

Preset PbfModel::toPreset() const {
    Preset p;
    p.model = kind();
    p.seed = seed_;
    p.params = params();
    p.obstacles = obstacles_;
    return p;
}

void PbfModel::refreshDerived() {
    kernels_ = pbf::Kernels::make(params_.h, params_.kernel, params_.selfDensity);
    if (params_.restDensitySource == "spawn-lattice") {
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

pbf::Box PbfModel::confinementBox() const {
    const double r = params_.particleRadius;
    return {r, r, params_.worldWidth - r, params_.worldHeight - r};
}

pbf::WallJitter PbfModel::wallJitter() const {
    constexpr double kJitterOverH = 1e-5; // Taichi's 1e-5 at h = 1.1
    return {seed_, static_cast<std::uint64_t>(step_), kJitterOverH * params_.h};
}

void PbfModel::step() {
    if (failure_) return;
    advanceBodies();
    applyExternalForcesAndPredict();
    findNeighbours();
    const auto iterations = static_cast<std::size_t>(params_.iterations);
    errorMean_.assign(iterations, 0.0);
    errorMax_.assign(iterations, 0.0);
    for (std::size_t k = 0; k < iterations; ++k) {
        computeLambdas(k);
        applyPositionCorrections();
    }
    updateVelocities();
    if (params_.vorticity > 0) applyVorticityConfinement();
    if (params_.xsph > 0) applyXsphViscosity();
    commitPositions();
    ++step_;
    time_ += params_.dt;
    drainOverCap();

    for (std::size_t i = 0; i < state_.size(); ++i) {
        if (std::isfinite(state_.vx[i]) && std::isfinite(state_.vy[i])) continue;
        std::ostringstream hint;
        hint << "the solver diverged at dt = " << params_.dt << " with " << params_.iterations
             << " iterations and ε = " << params_.epsilon
             << ": use a smaller dt, more iterations or a larger ε";
        failure_ = ModelFailure{"particle " + std::to_string(i) + " has a non-finite velocity", step_, time_,
                                hint.str()};
        break;
    }
}

void PbfModel::drainOverCap() {
    const auto n = static_cast<long long>(state_.size());
    if (!params_.drain || n <= params_.maxParticles) return;
    // The seed's drain: the excess leaves through the bottom, lowest particles first (ties by index, so
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

void PbfModel::addObstacle(const Obstacle& obstacle) {
    obstacles_.push_back(obstacle);
}

void PbfModel::removeObstacle(std::size_t index) {
    if (index >= obstacles_.size()) throw std::out_of_range("no obstacle " + std::to_string(index));
    obstacles_.erase(obstacles_.begin() + static_cast<long>(index));
    obstacleDrive_.erase(index);
}

void PbfModel::dragObstacle(std::size_t index, double x, double y) {
    if (index >= obstacles_.size()) throw std::out_of_range("no obstacle " + std::to_string(index));
    obstacleDrive_.drag(index, std::clamp(x, 0.0, params_.worldWidth),
                        std::clamp(y, 0.0, params_.worldHeight));
}

void PbfModel::releaseObstacle(std::size_t index) {
    obstacleDrive_.release(index);
}

void PbfModel::placeObstacle(std::size_t index, double x, double y) {
    if (index >= obstacles_.size()) throw std::out_of_range("no obstacle " + std::to_string(index));
    Obstacle& o = obstacles_[index];
    o.x = std::clamp(x, 0.0, params_.worldWidth);
    o.y = std::clamp(y, 0.0, params_.worldHeight);
    o.vx = o.vy = 0.0;
    obstacleDrive_.stop(index);
}

double PbfModel::toolSpeed() const {
    return params_.toolSpeed * params_.waveSpeed();
}

void PbfModel::scaleKineticEnergy(double factor) {
    if (!(factor > 0) || !std::isfinite(factor))
        throw std::invalid_argument("kinetic energy factor must be positive and finite");
    pullState();
    const double s = std::sqrt(factor);
    for (std::size_t i = 0; i < state_.size(); ++i) {
        state_.vx[i] *= s;
        state_.vy[i] *= s;
    }
    stateEdited();
}

} // namespace pl
