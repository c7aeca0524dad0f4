// GasModel: parameters, reset, the step's table of contents, obstacles and the piston.
#include "GasModel.h"

#include "common/Parallel.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pl {

GasModel::GasModel() {
    reset();
}

void GasModel::paramsChanged(const GasParams& before) {
    integrator_ = params_.integrator;
    if (params_.pistonEnabled != before.pistonEnabled || params_.pistonX != before.pistonX) {
        pistonX_ = params_.pistonX; // a position typed in puts the piston there
        pistonVelocity_ = 0.0;
        pistonDrive_.stop();
    }
    if (params_.maxDiameter() != before.maxDiameter()) neighbours_.invalidate();
    forcesValid_ = false; // stiffness, gravity or the force method may have changed
    ensureForces();
    stateEdited();
    rebaseEnergy();
}

void GasModel::reset() {
    integrator_ = params_.integrator;
    restartClock();
    lastSampleTime_ = 0.0;
    lastCollisionRate_ = 0.0;
    lastSortStep_ = -1;
    spawnEvents_ = 0;
    pistonX_ = params_.pistonX; // the box as set, whatever the piston did in the last run
    pistonVelocity_ = 0.0;
    escaped_ = false;
    wallWindow_.clear();
    restBodies();
    pistonDrive_.stop();
    buildInitialState();
    neighbours_.invalidate();
    forcesValid_ = false;
    ensureForces();
    stateEdited();
    energyBaseline_ = referenceEnergy_ = totalEnergy();
}

void GasModel::advance(double h) {
    ensureForces();
    constexpr std::int64_t kSortInterval = 100; // disks move about one diameter in this many steps
    if (static_cast<long long>(state_.size()) >= kParallelMinParticles &&
        params_.forceMethod != GasForceMethod::AllPairs &&
        (lastSortStep_ < 0 || stepCount() - lastSortStep_ >= kSortInterval))
        sortBySpace();
    if (params_.forceMethod ==
        GasForceMethod::AllPairs) { // contacts begun are found against the previous positions
        xPrev_ = state_.x;
        yPrev_ = state_.y;
    }
    driftIndex_ = 0;
    advanceBodies(h);
    runPasses(gasIntegrator(integrator_).passes, h); // the integrator table's stages, fused
}

void GasModel::afterStep() {
    constexpr std::int64_t kEnergyCheckInterval = 64; // an O(N) serial sum: cheap at this rate
    checkHealth(stepCount() % kEnergyCheckInterval == 0);
}

void GasModel::stateChangedOnDevice() const {
    neighbours_.invalidate();
    forcesValid_ = false;
    energiesValid_ = false;
    maxDisplacement2_ = -1.0;
}

void GasModel::sortBySpace() {
    // Each thread then works on a contiguous region of the box: its neighbour reads rarely touch cache
    // lines that the other core writes (without this, two threads ran slower per disk than one).
    const double d = params_.maxDiameter();
    sortCells_.configure(params_.left(), params_.bottom(), 0.5 * params_.boxWidth, params_.top(), 2.0 * d);
    sortCells_.build(state_.x.data(), state_.y.data(), state_.size());
    const std::vector<std::uint32_t>& newToOld = sortCells_.order();
    state_.permute(newToOld);
    neighbours_.permute(newToOld);
    lastSortStep_ = stepCount();
}

void GasModel::ensureForces() {
    if (forcesValid_) return;
    if (params_.forceMethod == GasForceMethod::AllPairs) { // no contact begins "during" a recomputation
        xPrev_ = state_.x;
        yPrev_ = state_.y;
    }
    computeForces(Contacts::Initialise, 0.0, true);
}

GasModel::Area GasModel::areaOf(const GasParams& p) const {
    // The tools work in the box as it stands (the piston where it moved to); a preset's obstacles are
    // checked in the box that preset builds.
    return {p.left(), p.bottom(), &p == &params_ ? rightWall() : p.right(), p.top()};
}

void GasModel::bodiesEdited(BodyEdit edit) {
    // A body put down on disks would hold them inside it until the next drift mirrored them out, deep into
    // their neighbours: contact energy the step turns into heat after the energy reference was taken.
    const bool moved = edit != BodyEdit::Removed && moveDisksOutOfBodies();
    if (edit == BodyEdit::Added || moved) { // forces and contact flags start afresh with the new body
        forcesValid_ = false;
        ensureForces();
    }
    rebaseEnergy(); // the energy an edit by hand adds or takes is not integration drift
}

double GasModel::initialRmsSpeed() const {
    const double rms = params_.initVelocity == GasInitVelocity::MaxwellBoltzmann
                           ? std::sqrt(2.0 * params_.initKT / params_.a.mass)
                           : params_.initSpeed;
    return rms > 0 ? rms : 1.0;
}

double GasModel::toolSpeed() const {
    return params_.toolSpeed * initialRmsSpeed();
}

void GasModel::dragPiston(double x) {
    if (!params_.pistonEnabled) throw std::logic_error("the piston is not enabled (piston_enabled = false)");
    pistonDrive_.dragTo(x);
}

void GasModel::drivePiston(int direction) {
    if (!params_.pistonEnabled) throw std::logic_error("the piston is not enabled (piston_enabled = false)");
    const bool wasMoving = pistonDrive_.moving();
    pistonDrive_.drive(direction);
    // Stopped by hand (Compress pressed again): the work it did is the system's energy now, as when it
    // stops by itself (advanceBodies).
    if (wasMoving && !pistonDrive_.moving()) rebaseEnergy();
}

void GasModel::placePiston(double x) {
    if (!params_.pistonEnabled) throw std::logic_error("the piston is not enabled (piston_enabled = false)");
    pullState();
    pistonX_ = std::clamp(x, pistonLower(), 0.5 * params_.boxWidth);
    pistonDrive_.stop();
    pistonVelocity_ = 0.0;
    rebaseEnergy();
}

double GasModel::pistonLower() const {
    // Denser than this the soft disks overlap ever more deeply as the piston pushes: the gas becomes a
    // jammed solid storing unbounded energy, so Compress stops at a dense liquid instead.
    constexpr double kPistonMaxAreaFraction = 0.7;
    const double covered = std::numbers::pi / 4 *
                           (static_cast<double>(params_.a.count) * params_.a.diameter * params_.a.diameter +
                            static_cast<double>(params_.b.count) * params_.b.diameter * params_.b.diameter);
    return params_.left() +
           std::max(params_.maxDiameter(), covered / (kPistonMaxAreaFraction * params_.boxHeight));
}

void GasModel::advanceBodies(double h) {
    bool settled = advanceObstacles(h);
    if (params_.pistonEnabled) {
        const bool wasMoving = pistonDrive_.moving();
        pistonVelocity_ = pistonDrive_.advance(pistonX_, pistonLower(), 0.5 * params_.boxWidth, toolSpeed(),
                                               params_.pistonSpeed * initialRmsSpeed(), h);
        settled = settled || (wasMoving && !pistonDrive_.moving());
    }
    // The work a body did is now the system's energy, not integration drift.
    if (settled) rebaseEnergy();
}

std::vector<NamedHistogram> GasModel::histograms() const {
    pullState();
    std::vector<NamedHistogram> list;
    for (int species : {0, 1})
        if (std::count(state_.species.begin(), state_.species.end(), species) > 0)
            list.push_back(speedHistogram(species));
    return list;
}

void GasModel::writeParticles(std::ostream& out) const {
    pullState();
    const auto precision = out.precision(17);
    out << "id,species,x,y,vx,vy\n";
    for (std::size_t i = 0; i < state_.size(); ++i)
        out << state_.id[i] << ',' << int(state_.species[i]) << ',' << state_.x[i] << ',' << state_.y[i]
            << ',' << state_.vx[i] << ',' << state_.vy[i] << '\n';
    out.precision(precision);
}

} // namespace pl
