// MdModel: parameters, reset, the step's table of contents, obstacles and the piston.
#include "MdModel.h"

#include "common/Parallel.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pl {

MdIntegrator integratorFromName(const std::string& name) {
    if (name == "velocity-verlet") return MdIntegrator::VelocityVerlet;
    if (name == "symplectic-euler") return MdIntegrator::SymplecticEuler;
    if (name == "explicit-euler") return MdIntegrator::ExplicitEuler;
    if (name == "rk4") return MdIntegrator::RungeKutta4;
    if (name == "forest-ruth") return MdIntegrator::ForestRuth;
    throw std::invalid_argument("unknown integrator '" + name + "'");
}

MdModel::MdModel() {
    reset();
}

ParamValues MdModel::params() const {
    return valuesOf(params_, MdParams::fields());
}

void MdModel::setParams(const ParamValues& values) {
    MdParams next = withValues(params_, MdParams::fields(), values);
    next.validate();
    pullState();
    const MdParams before = params_;
    params_ = next;
    integrator_ = integratorFromName(params_.integrator);
    if (params_.pistonEnabled != before.pistonEnabled || params_.pistonX != before.pistonX) {
        pistonVelocity_ = 0.0;
        pistonDrive_.stop();
    }
    if (params_.maxDiameter() != before.maxDiameter()) neighbours_.invalidate();
    forcesValid_ = false; // stiffness, gravity or the force method may have changed
    ensureForces();
    stateEdited();
    rebaseEnergy();
}

void MdModel::reset(const Preset& preset) {
    if (preset.model != kind())
        throw PresetError("model", "preset is for model '" + preset.model + "', not gas");
    MdParams next;
    try {
        next = withValues(MdParams{}, MdParams::fields(), preset.params);
        next.validate();
    } catch (const ParamError& e) {
        throw PresetError("params." + e.key(), e.what());
    }
    for (std::size_t i = 0; i < preset.obstacles.size(); ++i) {
        const auto& o = preset.obstacles[i];
        if (o.x < next.left() || o.x > next.right() || o.y < next.bottom() || o.y > next.top())
            throw PresetError("obstacles[" + std::to_string(i) + "]",
                              "obstacles[" + std::to_string(i) + "] has its centre outside the box");
    }
    params_ = next;
    seed_ = preset.seed;
    obstacles_ = preset.obstacles;
    reset();
}

void MdModel::reset() {
    integrator_ = integratorFromName(params_.integrator);
    step_ = 0;
    time_ = 0.0;
    lastSampleTime_ = 0.0;
    lastSortStep_ = -1;
    spawnEvents_ = 0;
    pistonVelocity_ = 0.0;
    escaped_ = false;
    failure_.reset();
    wallWindow_.clear();
    for (auto& o : obstacles_) o.vx = o.vy = 0.0;
    obstacleDrive_.clear();
    pistonDrive_.stop();
    buildInitialState();
    neighbours_.invalidate();
    forcesValid_ = false;
    ensureForces();
    stateEdited();
    energyBaseline_ = referenceEnergy_ = totalEnergy();
}

Preset MdModel::toPreset() const {
    Preset p;
    p.model = kind();
    p.seed = seed_;
    p.params = params();
    p.obstacles = obstacles_;
    return p;
}

void MdModel::step() {
    if (failure_) return;
    ensureForces();
    constexpr std::int64_t kSortInterval = 100; // disks move about one diameter in this many steps
    if (static_cast<long long>(state_.size()) >= kParallelMinParticles &&
        params_.forceMethod != "all-pairs" && (lastSortStep_ < 0 || step_ - lastSortStep_ >= kSortInterval))
        sortBySpace();
    if (params_.forceMethod == "all-pairs") { // contacts begun are found against the previous positions
        xPrev_ = state_.x;
        yPrev_ = state_.y;
    }
    driftIndex_ = 0;
    const double h = params_.dt;
    advanceBodies(h);
    switch (integrator_) {
    case MdIntegrator::VelocityVerlet:
        stepVelocityVerlet(h);
        break;
    case MdIntegrator::SymplecticEuler:
        stepSymplecticEuler(h);
        break;
    case MdIntegrator::ExplicitEuler:
        stepExplicitEuler(h);
        break;
    case MdIntegrator::RungeKutta4:
        stepRungeKutta4(h);
        break;
    case MdIntegrator::ForestRuth:
        stepForestRuth(h);
        break;
    }
    ++step_;
    time_ += h;
    constexpr std::int64_t kEnergyCheckInterval = 64; // an O(N) serial sum: cheap at this rate
    checkHealth(step_ % kEnergyCheckInterval == 0);
}

void MdModel::sortBySpace() {
    // Each thread then works on a contiguous region of the box: its neighbour reads rarely touch cache
    // lines that the other core writes (without this, two threads ran slower per disk than one).
    const double d = params_.maxDiameter();
    sortCells_.configure(params_.left(), params_.bottom(), 0.5 * params_.boxWidth, params_.top(), 2.0 * d);
    sortCells_.build(state_.x.data(), state_.y.data(), state_.size());
    const std::vector<std::uint32_t>& newToOld = sortCells_.order();
    state_.permute(newToOld);
    neighbours_.permute(newToOld);
    lastSortStep_ = step_;
}

void MdModel::ensureForces() {
    if (forcesValid_) return;
    if (params_.forceMethod == "all-pairs") { // no contact begins "during" a recomputation
        xPrev_ = state_.x;
        yPrev_ = state_.y;
    }
    computeForces(Contacts::Initialise, 0.0, true);
}

void MdModel::addObstacle(const Obstacle& obstacle) {
    pullState();
    obstacles_.push_back(obstacle);
    forcesValid_ = false;
    ensureForces();
    rebaseEnergy();
}

void MdModel::removeObstacle(std::size_t index) {
    if (index >= obstacles_.size()) throw std::out_of_range("no obstacle " + std::to_string(index));
    obstacles_.erase(obstacles_.begin() + static_cast<std::ptrdiff_t>(index));
    obstacleDrive_.erase(index);
    rebaseEnergy();
}

double MdModel::initialRmsSpeed() const {
    const double rms = params_.initVelocity == "maxwell-boltzmann"
                           ? std::sqrt(2.0 * params_.initKT / params_.a.mass)
                           : params_.initSpeed;
    return rms > 0 ? rms : 1.0;
}

double MdModel::toolSpeed() const {
    return params_.toolSpeed * initialRmsSpeed();
}

void MdModel::dragObstacle(std::size_t index, double x, double y) {
    if (index >= obstacles_.size()) throw std::out_of_range("no obstacle " + std::to_string(index));
    obstacleDrive_.drag(index, std::clamp(x, params_.left(), params_.right()),
                        std::clamp(y, params_.bottom(), params_.top()));
}

void MdModel::releaseObstacle(std::size_t index) {
    obstacleDrive_.release(index);
}

void MdModel::placeObstacle(std::size_t index, double x, double y) {
    if (index >= obstacles_.size()) throw std::out_of_range("no obstacle " + std::to_string(index));
    pullState();
    auto& o = obstacles_[index];
    o.x = std::clamp(x, params_.left(), params_.right());
    o.y = std::clamp(y, params_.bottom(), params_.top());
    o.vx = o.vy = 0.0;
    obstacleDrive_.stop(index);
    rebaseEnergy();
}

void MdModel::dragPiston(double x) {
    if (!params_.pistonEnabled) throw std::logic_error("the piston is not enabled (piston_enabled = false)");
    pistonDrive_.dragTo(x);
}

void MdModel::drivePiston(int direction) {
    if (!params_.pistonEnabled) throw std::logic_error("the piston is not enabled (piston_enabled = false)");
    pistonDrive_.drive(direction);
}

void MdModel::placePiston(double x) {
    if (!params_.pistonEnabled) throw std::logic_error("the piston is not enabled (piston_enabled = false)");
    pullState();
    params_.pistonX = std::clamp(x, pistonLower(), 0.5 * params_.boxWidth);
    pistonDrive_.stop();
    pistonVelocity_ = 0.0;
    rebaseEnergy();
}

double MdModel::pistonLower() const {
    // Denser than this the soft disks overlap ever more deeply as the piston pushes: the gas becomes a
    // jammed solid storing unbounded energy, so Compress stops at a dense liquid instead.
    constexpr double kPistonMaxAreaFraction = 0.7;
    const double covered = std::numbers::pi / 4 *
                           (static_cast<double>(params_.a.count) * params_.a.diameter * params_.a.diameter +
                            static_cast<double>(params_.b.count) * params_.b.diameter * params_.b.diameter);
    return params_.left() +
           std::max(params_.maxDiameter(), covered / (kPistonMaxAreaFraction * params_.boxHeight));
}

void MdModel::advanceBodies(double h) {
    bool settled = false;
    if (obstacleDrive_.moving()) settled = obstacleDrive_.advance(obstacles_, toolSpeed(), h);
    if (params_.pistonEnabled) {
        const bool wasMoving = pistonDrive_.moving();
        pistonVelocity_ = pistonDrive_.advance(params_.pistonX, pistonLower(), 0.5 * params_.boxWidth,
                                               toolSpeed(), params_.pistonSpeed * initialRmsSpeed(), h);
        settled = settled || (wasMoving && !pistonDrive_.moving());
    }
    // The work a body did is now the system's energy, not integration drift.
    if (settled) rebaseEnergy();
}

std::vector<std::string> MdModel::seriesColumns() const {
    return {"step",
            "time",
            "particles",
            "kinetic",
            "potential",
            "total",
            "kT",
            "kT_a",
            "kT_b",
            "px",
            "py",
            "pressure_virial",
            "pressure_wall",
            "pressure_ideal",
            "ks_a",
            "ks_b",
            "collision_rate",
            "energy_drift"};
}

std::vector<double> MdModel::sampleSeries() {
    const MdObservables o = observe();
    return {static_cast<double>(o.step),
            o.time,
            static_cast<double>(o.particles),
            o.kinetic,
            o.potential,
            o.total,
            o.kT,
            o.kTSpecies[0],
            o.kTSpecies[1],
            o.px,
            o.py,
            o.pressureVirial,
            o.pressureWall,
            o.pressureIdeal,
            o.ksDistance[0],
            o.ksDistance[1],
            o.collisionRate,
            o.energyDrift};
}

std::vector<NamedHistogram> MdModel::histograms() const {
    pullState();
    std::vector<NamedHistogram> list;
    for (int species : {0, 1})
        if (std::count(state_.species.begin(), state_.species.end(), species) > 0)
            list.push_back(speedHistogram(species));
    return list;
}

void MdModel::writeParticles(std::ostream& out) const {
    pullState();
    const auto precision = out.precision(17);
    out << "id,species,x,y,vx,vy\n";
    for (std::size_t i = 0; i < state_.size(); ++i)
        out << state_.id[i] << ',' << int(state_.species[i]) << ',' << state_.x[i] << ',' << state_.y[i]
            << ',' << state_.vx[i] << ',' << state_.vy[i] << '\n';
    out.precision(precision);
}

} // namespace pl
