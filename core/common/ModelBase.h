// What every model shares besides its physics: its parameters, seed and obstacles, preset adoption, the
// clock, the failure and the direction of time (ModelBase); and for scenes with mouse tools, the
// SceneTools contract (SceneModelBase): obstacle edits with one rule for clamping, index checks and
// placement while time stands still, bounded-speed drives, heat / cool, and the lazy CPU ↔ GPU hand-over
// of the particle state. A model derives from one of them and keeps only its physics.
#pragma once

#include "KinematicDrive.h"
#include "MemoryBudget.h"
#include "Model.h"
#include "Obstacle.h"
#include "ThreadGovernor.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pl {

// Non-template helpers of the bases (ModelBase.cpp).
namespace model_base {
// A rectangle of the world [L]: where obstacle centres and drag targets may be.
struct Area {
    double left = 0, bottom = 0, right = 0, top = 0;
};
// Throws std::invalid_argument unless direction is ±1, std::logic_error for −1 when !reversible.
void requireTimeDirection(int direction, bool reversible);
// Throws std::out_of_range unless index < count.
void requireObstacleIndex(std::size_t index, std::size_t count);
// Throws PresetError ("obstacles[i]") for the first obstacle whose centre lies outside the area.
void requireCentresInside(const Area& area, const std::vector<Obstacle>& obstacles);
// Throws PresetError ("obstacles") when the obstacles together cover the whole area, so no particle
// could be placed or enter: judged on a kRoomProbes × kRoomProbes grid of points, one at each grid
// cell's centre, of which at least one must lie outside every obstacle.
void requireRoomOutside(const Area& area, const std::vector<Obstacle>& obstacles);
// Throws PresetError ("obstacles") when there are any: the scene `kind` has none.
void refuseObstacles(const std::string& kind, const std::vector<Obstacle>& obstacles);
// Throws std::logic_error: the scene has no piston (or it is switched off).
[[noreturn]] void refuseMissingPiston(const std::string& why);
// v → √factor v for every particle: kinetic energy × factor. Throws std::invalid_argument unless
// factor is positive and finite (nothing is changed then).
void scaleVelocities(std::vector<double>& vx, std::vector<double>& vy, double factor);
void checkKineticFactor(double factor);
} // namespace model_base

// A kind's parameters checked as the base checks them: validate()'s cross-field checks, then the most
// memory the state can come to hold against what the machine can give (MemoryBudget.h). Every Params has
// both, so a kind cannot leave the memory check out (a Params without memoryNeed() does not compile).
// Throws ParamError naming the key.
template <class Params> void validateParams(const Params& params) {
    params.validate();
    requireMemory(params.memoryNeed());
}

// Params: the model's plain parameter struct with describe(), fields(), validate(), memoryNeed() and a dt
// [T].
template <class Params> class ModelBase : public Model {
public:
    const std::vector<ParamSpec>& paramSpecs() const override { return Params::describe(); }
    ParamValues params() const override { return valuesOf(params_, Params::fields()); }
    const Params& parameters() const { return params_; }

    // Validates every value (ParamError, nothing applied), then adopts them; paramsChanged() says what
    // the change means for the state.
    void setParams(const ParamValues& values) override {
        Params next = withValues(params_, Params::fields(), values);
        validateParams(next);
        refuseParams(next);
        pullState();
        const Params before = params_;
        params_ = next;
        paramsChanged(before);
    }

    // Adopts a preset's parameters, seed and obstacles and resets. A preset refused during or after the
    // reset (PresetError) leaves the model as its previous parameters build it.
    void reset(const Preset& preset) final {
        if (preset.model != kind())
            throw PresetError("model",
                              "the preset is for the scene '" + preset.model + "', not '" + kind() + "'");
        Params next;
        try {
            next = withValues(Params{}, Params::fields(), preset.params);
            validateParams(next);
        } catch (const ParamError& e) {
            throw PresetError("params." + e.key(), e.what());
        }
        checkObstacles(next, preset.obstacles);
        refuseBeforeBuilding(next, preset.seed);
        Params previous = params_;
        const std::uint64_t previousSeed = seed_;
        std::vector<Obstacle> previousObstacles = obstacles_;
        params_ = next;
        seed_ = preset.seed;
        obstacles_ = preset.obstacles;
        try {
            reset();
            checkBuiltState();
        } catch (const PresetError&) {
            params_ = previous;
            seed_ = previousSeed;
            obstacles_ = std::move(previousObstacles);
            reset();
            throw;
        }
    }
    using Model::reset;

    Preset toPreset() const override {
        Preset p;
        p.model = kind();
        p.seed = seed_;
        p.params = params();
        p.obstacles = obstacles_;
        return p;
    }

    // One step of dt in the direction of time, the same for every model, CPU and GPU: refused once the
    // model failed; the model's advance(h) on the team of threads the policy gives (ThreadGovernor.h);
    // the clock, unless advance() refused the step (it failed before changing the state); then what
    // follows a step (afterStep(): health checks, limits).
    void step() final {
        if (failure_) return;
        const double h = signedStep();
        if (h != segmentStepSize_) startClockSegment(h);
        stepThreads_.beginStep(backend() == "cpu");
        try {
            advance(h);
        } catch (...) { // a step abandoned half way (StopRequest.h): the clock stands, the caller restores
            stepThreads_.endStep();
            throw;
        }
        stepThreads_.endStep();
        if (failure_) return;
        ++step_;
        time_ = segmentTime_ + static_cast<double>(step_ - segmentStep_) * h;
        afterStep();
    }
    std::int64_t stepCount() const final { return step_; }
    double time() const final { return time_; }
    std::optional<ModelFailure> failure() const override { return failure_; }
    void setTimeDirection(int direction) override {
        model_base::requireTimeDirection(direction, reversible());
        timeDirection_ = direction;
    }
    int timeDirection() const override { return timeDirection_; }

protected:
    // Construction leaves the state empty for a derived constructor (a GPU model's) that resets once
    // itself, after its buffers exist.
    struct DeferReset {};

    // Cross-field checks of next beyond each value's range; throw ParamError naming the key.
    virtual void refuseParams(const Params& /*next*/) const {}
    // After params_ became the new values (before: the old ones): what they change in the state.
    virtual void paramsChanged(const Params& /*before*/) {}
    // A preset's obstacles against its parameters; throw PresetError naming the entry. A kind without
    // tools has no obstacles, so the base refuses any; SceneModelBase checks them against its area.
    virtual void checkObstacles(const Params& /*next*/, const std::vector<Obstacle>& obstacles) const {
        model_base::refuseObstacles(kind(), obstacles);
    }
    // A preset's refusals that its parameters and seed decide, before reset() builds the state (a state
    // of 1e7 particles takes seconds and gigabytes to build); throw PresetError naming the entry.
    virtual void refuseBeforeBuilding(const Params& /*next*/, std::uint64_t /*seed*/) const {}
    // After a preset's reset: throw PresetError where the built state makes the preset unusable.
    virtual void checkBuiltState() const {}
    // A backend that keeps the state elsewhere (the GPU) brings the CPU state up to date here before the
    // CPU code reads it, and learns through stateEdited() that the CPU code changed it.
    virtual void pullState() const {}
    virtual void stateEdited() {}

    // The physics of one step of h [T] (signedStep()): the clock still reads the step's start. A model
    // that cannot take the step calls fail() and leaves the state as it was.
    virtual void advance(double h) = 0;
    // After the clock moved on: the checks of the state the step left (the clock reads its end).
    virtual void afterStep() {}

    // The step this model takes [T]: dt with the direction of time (exact: a sign flip).
    double signedStep() const { return timeDirection_ * params_.dt; }
    // Records the failure at the present step and time; step() refuses from then on, until a reset.
    void fail(std::string what, std::string hint) {
        failure_ = ModelFailure{std::move(what), step_, time_, std::move(hint)};
    }
    bool failed() const { return failure_.has_value(); }
    void restartClock() {
        step_ = 0;
        time_ = 0.0;
        segmentStepSize_ = kNoSegment;
        failure_.reset();
    }
    // Snapshots: the clock goes with every model's state (core/common/Snapshot.h), with its segment, so a
    // run continued from a snapshot reads the same times as one never stopped. An older snapshot, without
    // the segment, starts one at its time.
    void saveClock(StateRecord& record) const {
        record.put("step", static_cast<double>(step_));
        record.put("time", time_);
        if (segmentStepSize_ == kNoSegment) return;
        record.put("segment_step", static_cast<double>(segmentStep_));
        record.put("segment_time", segmentTime_);
        record.put("segment_step_size", segmentStepSize_);
    }
    void restoreClock(const StateRecord& record) {
        step_ = record.count("step"); // a whole number from 0 to 2⁵³, refused otherwise
        time_ = record.scalar("time");
        segmentStepSize_ = kNoSegment;
        if (record.has("segment_step_size")) {
            const std::int64_t first = record.count("segment_step");
            if (first > step_)
                throw PresetError(
                    "state.segment_step",
                    "the clock's segment cannot start after the step the snapshot was taken at");
            segmentStep_ = first;
            segmentTime_ = record.scalar("segment_time");
            segmentStepSize_ = record.scalar("segment_step_size");
        }
        failure_.reset();
    }

    Params params_;
    std::uint64_t seed_ = 1;
    std::vector<Obstacle> obstacles_;

private:
    // The clock counts steps and derives the time from the count, t = t₀ + (n − n₀) h, within a segment of
    // constant h (dt and the direction of time), as LAMMPS keeps atime and atimestep: a running sum
    // t += h drifts (t = 4.9999999999999902 at step 100 at dt = 0.05) where this gives t = 5.
    static constexpr double kNoSegment = 0.0; // no step taken since the clock (re)started
    void startClockSegment(double h) {
        segmentStep_ = step_;
        segmentTime_ = time_;
        segmentStepSize_ = h;
    }

    std::int64_t step_ = 0;
    double time_ = 0.0;
    std::int64_t segmentStep_ = 0;
    double segmentTime_ = 0.0, segmentStepSize_ = kNoSegment;
    std::optional<ModelFailure> failure_;
    int timeDirection_ = 1;
    StepThreads stepThreads_;
};

// A scene of particles in a world rectangle with draggable obstacles. State: structure of arrays with
// size(), vx and vy [L/T].
template <class Params, class State> class SceneModelBase : public ModelBase<Params>, public SceneTools {
public:
    SceneTools* tools() override { return this; }
    std::size_t particleCount() const override { return state_.size(); }
    const State& state() const {
        this->pullState();
        return state_;
    }

    // SceneTools, one rule for every scene: centres and targets are clamped into toolArea(); an index
    // that names no obstacle throws std::out_of_range; a placed body rests at once.
    const std::vector<Obstacle>& obstacles() const override { return this->obstacles_; }
    void addObstacle(const Obstacle& obstacle) override {
        this->pullState();
        Obstacle added = obstacle;
        clampIntoArea(added.x, added.y);
        added.vx = added.vy = 0.0;
        this->obstacles_.push_back(added);
        bodiesEdited(BodyEdit::Added);
    }
    void removeObstacle(std::size_t index) override {
        model_base::requireObstacleIndex(index, this->obstacles_.size());
        this->pullState();
        this->obstacles_.erase(this->obstacles_.begin() + static_cast<std::ptrdiff_t>(index));
        obstacleDrive_.erase(index);
        bodiesEdited(BodyEdit::Removed);
    }
    void dragObstacle(std::size_t index, double x, double y) override {
        model_base::requireObstacleIndex(index, this->obstacles_.size());
        clampIntoArea(x, y);
        obstacleDrive_.drag(index, x, y);
    }
    void releaseObstacle(std::size_t index) override {
        model_base::requireObstacleIndex(index, this->obstacles_.size());
        obstacleDrive_.release(index);
    }
    void placeObstacle(std::size_t index, double x, double y) override {
        model_base::requireObstacleIndex(index, this->obstacles_.size());
        this->pullState();
        Obstacle& o = this->obstacles_[index];
        clampIntoArea(x, y);
        o.x = x;
        o.y = y;
        o.vx = o.vy = 0.0;
        obstacleDrive_.stop(index);
        bodiesEdited(BodyEdit::Placed);
    }
    bool bodiesMoving() const override { return obstacleDrive_.moving() || pistonMoving(); }

    // Scenes without a piston refuse its tools alike (the viewport asks hasPiston() first).
    void dragPiston(double /*x*/) override { model_base::refuseMissingPiston("this scene has no piston"); }
    void drivePiston(int /*direction*/) override {
        model_base::refuseMissingPiston("this scene has no piston");
    }
    void placePiston(double /*x*/) override { model_base::refuseMissingPiston("this scene has no piston"); }

    void scaleKineticEnergy(double factor) override {
        model_base::checkKineticFactor(factor);
        this->pullState();
        model_base::scaleVelocities(state_.vx, state_.vy, factor);
        this->stateEdited();
        energyEdited();
    }

protected:
    using Area = model_base::Area;
    enum class BodyEdit { Added, Removed, Placed };

    // Where obstacle centres and drag targets may be for these parameters.
    virtual Area areaOf(const Params& params) const = 0;
    // A preset's obstacles have their centres where the tools may put them (PresetError naming the
    // entry otherwise); a scene with more rules (the tunnel's body sizes) overrides this.
    void checkObstacles(const Params& next, const std::vector<Obstacle>& obstacles) const override {
        model_base::requireCentresInside(areaOf(next), obstacles);
        model_base::requireRoomOutside(areaOf(next), obstacles);
    }
    Area toolArea() const { return areaOf(this->params_); }
    // After an obstacle was added, removed or placed by hand (the state is pulled).
    virtual void bodiesEdited(BodyEdit /*edit*/) {}
    // After heat / cool changed the kinetic energy on purpose.
    virtual void energyEdited() {}
    virtual bool pistonMoving() const { return false; }

    // A reset's bodies: at rest where the preset puts them, no drive.
    void restBodies() {
        for (Obstacle& o : this->obstacles_) o.vx = o.vy = 0.0;
        obstacleDrive_.clear();
    }
    // Moves the dragged obstacles one step of h [T] at up to toolSpeed() (KinematicDrive.h); true when
    // a released body came to rest this step.
    bool advanceObstacles(double h) {
        return obstacleDrive_.moving() && obstacleDrive_.advance(this->obstacles_, toolSpeed(), h);
    }
    void clampIntoArea(double& x, double& y) const {
        const Area a = toolArea();
        x = std::clamp(x, a.left, a.right);
        y = std::clamp(y, a.bottom, a.top);
    }

    mutable State state_; // mutable: a GPU backend fills it lazily in pullState()
    ObstacleDrive obstacleDrive_;
};

} // namespace pl
