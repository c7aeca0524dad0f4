// The soft-disk gas: OpenMP CPU reference model. step() reads like the integrator's table of contents.
#pragma once

#include "MdBoundaries.h"
#include "MdParams.h"
#include "MdState.h"
#include "common/CellList.h"
#include "common/KinematicDrive.h"
#include "common/Model.h"
#include "common/NeighbourList.h"
#include "common/Obstacle.h"

#include <array>
#include <deque>
#include <optional>

namespace pl {

enum class MdIntegrator { VelocityVerlet, SymplecticEuler, ExplicitEuler, RungeKutta4, ForestRuth };
MdIntegrator integratorFromName(const std::string& name);
// Largest ω·dt for which the scheme is stable on x'' = −ω² x (physics.md §1); 0 for explicit Euler.
double stabilityLimit(MdIntegrator integrator);

struct MdObservables {
    std::int64_t step = 0;
    double time = 0;
    std::size_t particles = 0;
    double kinetic = 0, potential = 0, total = 0; // [energy]; potential includes gravity
    double kT = 0;                                // kinetic energy per disk (2 degrees of freedom)
    std::array<double, 2> kTSpecies{};            // NaN for an absent species
    double px = 0, py = 0;                        // total momentum [M·L/T]
    double pressureVirial = 0;                    // (N kT + ½ Σ r·f) / A, instantaneous [energy/L²]
    double pressureWall = 0; // wall impulse / (perimeter × time) over the window; NaN before any time passed
    double pressureIdeal = 0;           // N kT / A
    std::array<double, 2> ksDistance{}; // KS distance of speeds to 2D Maxwell–Boltzmann at measured kT
    double collisionRate = 0;           // contacts begun per unit time since the last sample
    double energyDrift = 0;             // |E − E₀| / |E₀| since the last reset or user change
};

// Raw sums behind one sample of observables; CPU loops or GPU reductions fill it.
struct MdSums {
    std::array<long long, 2> count{};
    std::array<double, 2> kinetic{};
    double px = 0, py = 0;
    double potential = 0; // pair and gravity
    double virial = 0;    // ½ Σ_{i<j} r_ij·f_ij
    double impulse = 0;   // given to the walls since the last sample
    long long contactsBegun = 0;
};

struct MdParticle {
    double x, y, vx, vy;
    int species = 0;
};

struct SpawnResult {
    long long added = 0;
    long long refusedOverlap = 0; // would overlap an existing disk beyond spawn_max_overlap
    long long refusedOutside = 0; // outside the box or inside an obstacle
    long long refusedCap = 0;     // beyond max_particles
    std::string message() const;
};

class MdModel : public Model, public SceneTools {
public:
    MdModel();
    ~MdModel() override = default;

    // Model interface
    std::string kind() const override { return "gas"; }
    const std::vector<ParamSpec>& paramSpecs() const override { return MdParams::describe(); }
    ParamValues params() const override;
    void setParams(const ParamValues& values) override;
    void reset(const Preset& preset) override;
    void reset() override;
    Preset toPreset() const override;
    void step() override;
    std::int64_t stepCount() const override { return step_; }
    double time() const override { return time_; }
    std::size_t particleCount() const override { return state_.size(); }
    std::optional<ModelFailure> failure() const override { return failure_; }
    void checkHealthNow() override { checkHealth(true); }
    std::vector<std::string> seriesColumns() const override;
    std::vector<double> sampleSeries() override;
    std::vector<NamedHistogram> histograms() const override;
    void writeParticles(std::ostream& out) const override;
    SceneView sceneView() const override;
    SceneTools* tools() override { return this; }
    StateRecord saveState() const override; // MdSnapshot.cpp
    void restoreState(const StateRecord& state) override;

    // SceneTools interface (the obstacle and piston functions below belong to it too)
    bool hasPiston() const override { return params_.pistonEnabled; }
    double pistonX() const override { return params_.pistonX; }
    double toolSpeed() const override;
    bool bodiesMoving() const override { return obstacleDrive_.moving() || pistonDrive_.moving(); }
    std::string spawnInRectangle(double x0, double y0, double x1, double y1) override;
    void scaleKineticEnergy(double factor) override;

    // Gas-specific API
    const MdParams& parameters() const { return params_; }
    const MdState& state() const {
        pullState();
        return state_;
    }
    virtual MdObservables observe(); // closes the wall-impulse and contact windows
    virtual double totalEnergy();    // kinetic + pair + gravity energy of the current state
    NamedHistogram speedHistogram(int species) const;

    const std::vector<Obstacle>& obstacles() const override { return obstacles_; }
    void addObstacle(const Obstacle& obstacle) override;
    void removeObstacle(std::size_t index) override;
    // Kinematic bodies (targets are clamped into the box): the step moves them at bounded speed.
    void dragObstacle(std::size_t index, double x, double y) override;
    void releaseObstacle(std::size_t index) override;
    void placeObstacle(std::size_t index, double x, double y) override;
    void dragPiston(double x) override;
    void drivePiston(int direction) override;
    int pistonDirection() const override { return pistonDrive_.direction(); }
    void placePiston(double x) override;
    // The initial rms speed of species A [L/T]: the scale of tool_speed, piston_speed and the colours.
    double initialRmsSpeed() const;

    SpawnResult spawnRectangle(double x0, double y0, double x1, double y1, int species, double kT);
    SpawnResult spawnAt(double x, double y, int species, double kT);
    // Replaces the whole population (analytic set-ups, shared initial states); time and counters restart.
    void placeParticles(const std::vector<MdParticle>& particles);
    long long removeInRectangle(double x0, double y0, double x1, double y1);
    long long removeNear(double x, double y, double radius);

protected:
    // A backend that keeps the particles elsewhere (the GPU) brings state_ up to date here before the
    // CPU code reads it, and learns through stateEdited() that the CPU code changed it.
    virtual void pullState() const {}
    virtual void stateEdited() {}
    // observe() after the sums: kT, pressures, wall window, contact rate, energy drift (not KS).
    MdObservables summarise(const MdSums& sums);
    // A speed histogram with its theory curve and summary line, from counts made elsewhere.
    NamedHistogram describeSpeedHistogram(int species, double kT, double ks, Histogram counts) const;
    double histogramRange(double kT, double mass) const; // the plotted speed range [L/T]
    SceneView sceneFrame() const;                        // the scene without its particles

    // Integrators (MdIntegrators.cpp): one step each, all ending with forces at the new positions.
    void stepVelocityVerlet(double h);
    void stepSymplecticEuler(double h);
    void stepExplicitEuler(double h);
    void stepRungeKutta4(double h);
    void stepForestRuth(double h);

    // Stages. Each loop over particles does as much as it can in one pass (gather form throughout).
    enum class Contacts { Ignore, Count, Initialise };
    // v += kickBefore a; x += h v; walls and obstacles; v += kickAfter a; displacement since the list build.
    void driftStage(double kickBefore, double h, double kickAfter);
    void boundaryStage(double h); // walls and obstacles only (after an RK4 update)
    // a at the current positions, then v += kickAfter a; with energies, also each disk's potential
    // energy and virial (only observables need them, so the steps skip them).
    void computeForces(Contacts contacts, double kickAfter = 0.0, bool energies = false);
    void computeForcesNeighbourList(Contacts contacts, double kickAfter, bool energies);
    void refreshEnergies();
    void computeForcesAllPairs(Contacts contacts, double kickAfter);
    md::Boundaries boundaries(double h) const;
    // Moves the dragged obstacles and the piston one step of h toward their targets (KinematicDrive.h).
    void advanceBodies(double h);
    // The piston's travel ends where the disks would cover kPistonMaxAreaFraction of the box (or one
    // diameter from the left wall, whichever is further right).
    double pistonLower() const;
    void ensureForces();
    void sortBySpace(); // particles in cell order, so neighbours in space are neighbours in memory

    // State building (MdInitialState.cpp)
    void buildInitialState();
    void placeRandom(long long first, long long count, int species);
    void placeLattice();
    void assignVelocities();

    // Health (MdStability.cpp)
    void checkHealth(bool energyCheck);
    void fail(const std::string& what, const std::string& hint);
    std::string stabilityHint() const;
    void rebaseEnergy(); // after a user change: the new energy is the reference

    void populationChanged(); // after spawning or removing: counts, cells, forces, energy reference
    bool overlapsTooMuch(double x, double y, double diameter) const;
    bool insideSpace(double x, double y, double radius) const;
    std::uint32_t nextId() { return nextId_++; }

    MdParams params_;
    std::uint64_t seed_ = 1;
    std::vector<Obstacle> obstacles_;
    MdIntegrator integrator_ = MdIntegrator::VelocityVerlet;

    mutable MdState state_;          // mutable: a GPU backend fills it lazily in pullState()
    NeighbourList neighbours_;       // payload byte per pair: in contact at the last counted evaluation
    double maxDisplacement2_ = -1.0; // since the list build, from the last drift; −1 when unknown
    CellList sortCells_;
    std::int64_t lastSortStep_ = -1;
    std::vector<double> xPrev_, yPrev_; // positions at the start of the step (all-pairs contact detection)
    std::vector<double> stageX_, stageY_, stageVX_, stageVY_, sumVX_, sumVY_, sumAX_, sumAY_; // RK4
    bool forcesValid_ = false;
    bool energiesValid_ = false; // potential and virial belong to the current positions
    bool escaped_ = false;
    double pistonVelocity_ = 0.0; // over the current step [L/T]
    ObstacleDrive obstacleDrive_;
    PistonDrive pistonDrive_;

    std::int64_t step_ = 0;
    double time_ = 0.0;
    std::uint32_t nextId_ = 0;
    std::uint64_t spawnEvents_ = 0;
    std::uint32_t driftIndex_ = 0; // distinguishes thermal-wall draws of several drifts in one step

    double energyBaseline_ = 0.0;  // E₀ of energyDrift
    double referenceEnergy_ = 0.0; // blow-up reference
    double lastSampleTime_ = 0.0;
    struct WallSample {
        double impulse, duration, perimeterTime;
    };
    std::deque<WallSample> wallWindow_;
    std::optional<ModelFailure> failure_;
};

} // namespace pl
