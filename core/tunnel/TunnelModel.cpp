// TunnelModel: reset, the step in the order of the method (Bird 1994 §11.1: move, enter, index,
// collide, sample), the parameters' and bodies' edits and the piston.
#include "TunnelModel.h"

#include "common/StopRequest.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace pl {

namespace {
// The piston travels at most this fraction of the box: the compressed gas keeps some cells.
constexpr double kPistonTravel = 0.9;
// Refused above this many free-stream collisions per molecule and step (as the DSMC cell refuses).
constexpr double kRefusedNuDt = 10.0;
// Refused above this many molecule–body tests per step: every flight is tested against every body, at
// about 15 ns a test on one core, so this bound keeps a step under a second (docs/wind-tunnel.md#limits).
constexpr double kMaxBodyTestsPerStep = 5e7;
} // namespace

TunnelModel::TunnelModel() {
    reset();
}

model_base::Area TunnelModel::areaOf(const TunnelParams& p) const {
    return {0.0, 0.0, p.boxWidth, p.boxHeight};
}

void TunnelModel::checkObstacles(const TunnelParams& next, const std::vector<Obstacle>& obstacles) const {
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
        const Obstacle& o = obstacles[k];
        const std::string key = "obstacles[" + std::to_string(k) + "]";
        const double size = o.shape == Obstacle::Shape::Disc ? o.radius : std::min(o.halfWidth, o.halfHeight);
        if (!(size > 0) || !std::isfinite(size))
            throw PresetError(key, "a body needs a positive size (radius or half extents)");
        // A centre on a side is allowed: a half body on a symmetry plane (a specular bottom side).
        if (!(o.x >= 0 && o.x <= next.boxWidth && o.y >= 0 && o.y <= next.boxHeight))
            throw PresetError(key, "the body's centre (" + formatNumber(o.x, 4) + ", " +
                                       formatNumber(o.y, 4) + ") m lies outside the tunnel [0, " +
                                       formatNumber(next.boxWidth, 4) + "] × [0, " +
                                       formatNumber(next.boxHeight, 4) + "] m");
    }
    model_base::requireRoomOutside(areaOf(next), obstacles); // molecules would be born inside a solid
    // The cost of a step grows with molecules × bodies; the free stream's fill is the molecule count the
    // run settles at.
    const double molecules = std::max(1.0, next.streamDensity * next.boxWidth * next.boxHeight / next.fn);
    const double tests = molecules * static_cast<double>(obstacles.size());
    if (tests > kMaxBodyTestsPerStep)
        throw PresetError("obstacles",
                          std::to_string(obstacles.size()) + " bodies in a stream of " +
                              formatNumber(molecules, 3) + " molecules make " + formatNumber(tests, 3) +
                              " body tests a step, more than a step can do (" +
                              formatNumber(kMaxBodyTestsPerStep, 2) + "); use at most " +
                              std::to_string(static_cast<long long>(kMaxBodyTestsPerStep / molecules)) +
                              " bodies, or raise fn to at least " +
                              formatNumber(next.fn * tests / kMaxBodyTestsPerStep, 3));
}

void TunnelModel::refuseParams(const TunnelParams& next) const {
    // The DSMC cell's bound (DsmcModel): beyond ~10 collisions per molecule and step the step costs
    // N ν Δt / 2 candidates and no result is worth it.
    const double nuDt = next.dt / collisionTimeOf(next);
    if (!(nuDt <= kRefusedNuDt))
        throw ParamError("dt", "the free stream collides " + formatNumber(nuDt, 3) +
                                   " times per molecule and step, more than a step can do (" +
                                   formatNumber(kRefusedNuDt, 2) + "); use {dt} ≤ " +
                                   formatNumber(0.25 * next.dt / nuDt, 3) + " s");
}

void TunnelModel::refuseBeforeBuilding(const TunnelParams& next, std::uint64_t /*seed*/) const {
    // A preset (and the CLI's --set, which edits the preset) comes through reset, not setParams: the
    // same bound, before the molecules are made.
    try {
        refuseParams(next);
    } catch (const ParamError& e) {
        throw PresetError("params." + e.key(), withKeys(e.what()));
    }
}

void TunnelModel::refreshCollisionModel() {
    collisions_ = collisionModelOf(params_);
}

double TunnelModel::initialSigmaCrMax() const {
    // Bird's practice: a generous first value that the running maximum of each cell corrects. σ c_r at
    // three most probable relative speeds √(4kT/m) of the hottest temperature the scene sets; the shock
    // layer's cells raise theirs within a few steps.
    const double hottest =
        std::max({params_.streamTemperature, params_.wallTemperature, params_.bodyTemperature});
    return collisions_.sigmaCr(3.0 * std::sqrt(4.0 * kBoltzmann * hottest / params_.mass()));
}

void TunnelModel::configureGrid() {
    const auto cells = static_cast<std::size_t>(params_.cellsX * params_.cellsY);
    SamplingGrid grid;
    grid.nx = static_cast<int>(params_.cellsX);
    grid.ny = static_cast<int>(params_.cellsY);
    grid.left = 0.0;
    grid.bottom = 0.0;
    grid.right = params_.boxWidth;
    grid.top = params_.boxHeight;
    grid.fn = params_.fn;
    grid.mass = params_.mass();
    grid.openFraction = openFractions(params_, obstacles_);
    openFraction_ = grid.openFraction;
    sampler_.configure(grid);
    // NTC's fractional candidates start uniform in [0, 1), not at 0: floor(w + U) has the mean w exactly,
    // so a cell of thin gas (w ≪ 1 candidate per step) collides at the kinetic rate from the first step
    // instead of waiting ~1/w steps; with 0, an empty tunnel at n = 3e18 m⁻³ collided at 57 % of the
    // rate over 1500 steps. The same for the molecules entering through each side.
    remainder_.resize(cells);
    for (std::size_t c = 0; c < cells; ++c) remainder_[c] = startingRemainder(RngPurpose::TunnelCollision, c);
    cellSigmaCrMax_.assign(cells, initialSigmaCrMax());
    cellStart_.assign(cells + 1, 0);
    inflowRemainder_.resize(4);
    for (std::size_t side = 0; side < 4; ++side)
        inflowRemainder_[side] = startingRemainder(RngPurpose::TunnelInflow, side);
}

double TunnelModel::startingRemainder(RngPurpose purpose, std::size_t subject) const {
    // Sequence 2⁶⁴ − 1: the per-step draws key their sequence by the step (TunnelKernels.h) and never
    // reach it.
    const Philox4x32 w = randomWords(seed_, purpose, static_cast<std::uint32_t>(subject), ~std::uint64_t{0});
    return unitOpen(w[0], w[1]);
}

void TunnelModel::refreshOpenFraction() {
    openFraction_ = openFractions(params_, obstacles_);
    sampler_.setOpenFraction(openFraction_);
}

void TunnelModel::reset() {
    moleculeLimit_ = params_.moleculeLimit();
    refreshCollisionModel();
    restartClock();
    restBodies();
    pistonDrive_.stop();
    pistonX_ = 0.0;
    pistonVelocity_ = 0.0;
    pistonExperiment_ = params_.pistonOn && params_.pistonSpeed > 0;
    if (pistonExperiment_) pistonDrive_.drive(+1);
    streamCounter_ = 0;
    collisionsThisStep_ = 0;
    state_.clear();
    configureGrid();
    if (params_.initial != TunnelInitial::Empty)
        fillRectangle(0.0, 0.0, params_.boxWidth, params_.boxHeight, params_.initial == TunnelInitial::Stream,
                      streamCounter_++);
    sortIntoCells(true);
    sigmaCrMax_ = cellSigmaCrMax_.empty() ? 0.0 : cellSigmaCrMax_.front();
    restartSampling();
    stateEdited();
}

void TunnelModel::restartSampling() {
    sampleFrom_ = stepCount() + params_.sampleStart;
    sampler_.setWindow(params_.sampleWindow); // empties it
}

void TunnelModel::paramsChanged(const TunnelParams& before) {
    const CollisionModel previous = collisions_;
    refreshCollisionModel();
    // Another cross-section: the running maxima of the old one mean nothing for it.
    if (collisions_.kind != previous.kind || collisions_.prefactor != previous.prefactor ||
        collisions_.omega != previous.omega)
        std::fill(cellSigmaCrMax_.begin(), cellSigmaCrMax_.end(), initialSigmaCrMax());
    if (params_.pistonOn != before.pistonOn) {
        pistonDrive_.stop();
        pistonVelocity_ = 0.0;
        pistonExperiment_ = false;
    }
    // Switching the view changes nothing the gas does; everything else starts a new window.
    TunnelParams viewOnly = before;
    viewOnly.view = params_.view;
    const auto same = [](const TunnelParams& a, const TunnelParams& b) {
        return valuesOf(a, TunnelParams::fields()) == valuesOf(b, TunnelParams::fields());
    };
    if (!same(viewOnly, params_)) restartSampling();
    stateEdited();
}

void TunnelModel::bodiesEdited(BodyEdit /*edit*/) {
    refreshOpenFraction();
    restartSampling();
    stateEdited();
}

void TunnelModel::advancePiston(double h) {
    if (!params_.pistonOn) {
        pistonVelocity_ = 0.0;
        return;
    }
    const bool userMove = pistonDrive_.moving() && !pistonExperiment_;
    pistonVelocity_ =
        pistonDrive_.advance(pistonX_, 0.0, kPistonTravel * params_.boxWidth, params_.toolSpeed,
                             params_.pistonSpeed > 0 ? params_.pistonSpeed : params_.toolSpeed, h);
    if (!pistonDrive_.moving()) pistonExperiment_ = false;
    if (userMove) restartSampling();
}

double TunnelModel::advanceBodies(double h) {
    const bool bodiesWereMoving = obstacleDrive_.moving();
    advanceObstacles(h);
    if (bodiesWereMoving) {
        refreshOpenFraction();
        restartSampling();
    }
    advancePiston(h);
    return pistonVelocity_;
}

void TunnelModel::sampleStep(double h) {
    if (stepCount() >= sampleFrom_) sampler_.addState(state_);
    sampler_.endStep(obstacles_.size(), h);
}

// The random streams (common/Philox.h), each keyed so no two draws share numbers and no draw depends on
// the thread that makes it: the move's wall and body re-emission TunnelSurface (particle index, step
// << 32 + k); the inflow TunnelInflow (side << 28 | entering index, step << 32 + k); NTC
// TunnelCollision (cell, step << 32 + 2³¹ + 2 · candidate (+1 for the angles)); the initial gas and
// spawned rectangles TunnelFill (cell, call << 32 + k).
// A stop request may end the step between phases, and the move and the collisions skip what is left of
// their loops (common/StopRequest.h): a step of 67 M molecules takes minutes.
void TunnelModel::advance(double h) {
    advanceBodies(h);
    moveParticles(h);
    leaveIfAbandoning();
    admitInflow(h);
    leaveIfAbandoning();
    constexpr std::int64_t kReorderInterval = 16;
    sortIntoCells(stepCount() % kReorderInterval == 0);
    leaveIfAbandoning();
    collide(h);
    leaveIfAbandoning();
    sampleStep(h);
    stepStart_.keeping = false; // the step is whole: nothing to undo
}

void TunnelModel::afterStep() {
    stateEdited();
    if (static_cast<double>(state_.size()) > moleculeLimit_) failTooManyMolecules(state_.size());
}

void TunnelModel::adoptDeviceCells(const std::vector<std::uint32_t>& cellStart,
                                   const std::vector<float>& remainders,
                                   const std::vector<float>& sigmaCrMax) const {
    cellStart_ = cellStart;
    order_.resize(state_.size());
    std::iota(order_.begin(), order_.end(), 0u); // the device keeps no earlier order
    remainder_.assign(remainders.begin(), remainders.end());
    cellSigmaCrMax_.assign(sigmaCrMax.begin(), sigmaCrMax.end());
    sigmaCrMax_ = sigmaCrMax.empty() ? 0.0 : *std::max_element(sigmaCrMax.begin(), sigmaCrMax.end());
}

void TunnelModel::failTooManyMolecules(std::size_t count) {
    const bool memory = moleculeLimit_ < TunnelParams::maxParticles();
    fail(std::to_string(count) + " molecules exceed the limit of " + formatNumber(moleculeLimit_, 3) +
             (memory ? ", what this machine's memory held at the start" : ""),
         withKeys("the inflow and the bodies packed more gas into the tunnel than it can hold: raise {fn}"));
}

void TunnelModel::scaleKineticEnergy(double factor) {
    model_base::checkKineticFactor(factor);
    pullState();
    const double scale = std::sqrt(factor);
    for (std::vector<double>* v : {&state_.vx, &state_.vy, &state_.vz})
        for (double& c : *v) c *= scale;
    restartSampling();
    stateEdited();
}

void TunnelModel::dragPiston(double x) {
    if (!params_.pistonOn) model_base::refuseMissingPiston("the piston is off (piston_on = false)");
    pistonExperiment_ = false;
    pistonDrive_.dragTo(x);
}

// The SceneTools convention: −1 compresses. The tunnel's piston is its left side, so compressing moves
// it to the right (+x).
void TunnelModel::drivePiston(int direction) {
    if (!params_.pistonOn) model_base::refuseMissingPiston("the piston is off (piston_on = false)");
    if (direction < -1 || direction > 1) throw std::invalid_argument("the piston's direction is −1, 0 or +1");
    pistonExperiment_ = false;
    pistonDrive_.drive(-direction);
}

int TunnelModel::pistonDirection() const {
    return -pistonDrive_.direction();
}

void TunnelModel::placePiston(double x) {
    if (!params_.pistonOn) model_base::refuseMissingPiston("the piston is off (piston_on = false)");
    pullState();
    pistonX_ = std::clamp(x, 0.0, kPistonTravel * params_.boxWidth);
    pistonDrive_.stop();
    pistonExperiment_ = false;
    pistonVelocity_ = 0.0;
    // The gas the piston was put onto is pushed in front of it, moving away from it.
    for (std::size_t i = 0; i < state_.size(); ++i)
        if (state_.x[i] < pistonX_) {
            state_.x[i] = std::nextafter(pistonX_, params_.boxWidth);
            state_.vx[i] = std::abs(state_.vx[i]);
        }
    sortIntoCells();
    restartSampling();
    stateEdited();
}

} // namespace pl
