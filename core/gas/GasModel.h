// The soft-disk gas: OpenMP CPU reference model. step() reads like the integrator's table of contents.
#pragma once

#include "GasBoundaries.h"
#include "GasIntegratorTable.h"
#include "GasParams.h"
#include "GasState.h"
#include "common/CellList.h"
#include "common/KinematicDrive.h"
#include "common/Model.h"
#include "common/ModelBase.h"
#include "common/NeighbourList.h"
#include "common/Obstacle.h"
#include "common/StateTable.h"

#include <array>
#include <deque>
#include <optional>

namespace pl {

struct GasObservables {
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
struct GasSums {
    std::array<long long, 2> count{};
    std::array<double, 2> kinetic{};
    double px = 0, py = 0;
    double potential = 0; // pair and gravity
    double virial = 0;    // ½ Σ_{i<j} r_ij·f_ij
    double impulse = 0;   // given to the walls since the last sample
    long long contactsBegun = 0;
};

struct GasParticle {
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

// Parameters, presets, the clock, obstacles and the tools' rules come from SceneModelBase
// (common/ModelBase.h); this class holds the gas's physics.
class GasModel : public SceneModelBase<GasParams, GasState> {
public:
    GasModel();
    ~GasModel() override = default;

    // Model interface
    std::string kind() const override { return "gas"; }
    using ModelBase::reset;
    void reset() override;
    void checkHealthNow() override { checkHealth(true); }
    std::string stabilityRefusal() const override; // GasStability.cpp
    std::vector<std::string> seriesColumns() const override;
    std::vector<double> sampleSeries() override;
    std::vector<NamedHistogram> histograms() const override;
    void writeParticles(std::ostream& out) const override;
    SceneView sceneView() const override;
    StateRecord saveState() const override; // GasSnapshot.cpp
    void restoreState(const StateRecord& state) override;

    // SceneTools interface: the obstacles' tools are SceneModelBase's; the piston is the gas's own. Where
    // the piston is now is state: piston_x is where a reset puts it, and the drive never writes it.
    bool hasPiston() const override { return params_.pistonEnabled; }
    double pistonX() const override { return pistonX_; }
    double toolSpeed() const override;
    std::string spawnInRectangle(double x0, double y0, double x1, double y1) override;

    // Gas-specific API
    virtual GasObservables observe(); // closes the wall-impulse and contact windows
    virtual double totalEnergy();     // kinetic + pair + gravity energy of the current state
    NamedHistogram speedHistogram(int species) const;
    // Force evaluations of the CPU model since it was built (steps, observables, edits): the cost the
    // integrator table states per step, counted where it happens.
    std::int64_t forceEvaluations() const { return forceEvaluations_; }

    // The piston is a kinematic body too: the step moves it at bounded speed.
    void dragPiston(double x) override;
    void drivePiston(int direction) override;
    int pistonDirection() const override { return pistonDrive_.direction(); }
    void placePiston(double x) override;
    // The initial rms speed of species A [L/T]: the scale of tool_speed_factor, piston_speed_factor and the
    // colours.
    double initialRmsSpeed() const;

    SpawnResult spawnRectangle(double x0, double y0, double x1, double y1, int species, double kT);
    SpawnResult spawnAt(double x, double y, int species, double kT);
    // Replaces the whole population (analytic set-ups, shared initial states); time and counters restart.
    void placeParticles(const std::vector<GasParticle>& particles);
    long long removeInRectangle(double x0, double y0, double x1, double y1);
    long long removeNear(double x, double y, double radius);

protected:
    // The bases' hooks: what a change of parameters, obstacles or energy means for the gas.
    explicit GasModel(DeferReset) {}
    void advance(double h) override; // the integrator table's passes (GasModel.cpp)
    void afterStep() override;       // the health checks
    void paramsChanged(const GasParams& before) override;
    Area areaOf(const GasParams& p) const override;
    // The right wall as it stands [L]: the piston where it moved, or the box's right side.
    double rightWall() const { return params_.pistonEnabled ? pistonX_ : 0.5 * params_.boxWidth; }
    void bodiesEdited(BodyEdit edit) override;
    void energyEdited() override { rebaseEnergy(); } // a deliberate change of energy is not drift
    bool pistonMoving() const override { return pistonDrive_.moving(); }
    // observe() after the sums: kT, pressures, wall window, contact rate, energy drift (not KS).
    GasObservables summarise(const GasSums& sums);
    // A speed histogram with its theory curve and summary line, from counts made elsewhere.
    NamedHistogram describeSpeedHistogram(int species, double kT, double ks, Histogram counts) const;
    double histogramRange(double kT, double mass) const; // the plotted speed range [L/T]
    SceneView sceneFrame() const;                        // the scene without its particles

    // Integrators (GasIntegrators.cpp): the integrator table's passes for one step, ending with forces
    // at the new positions; RK4's own stepper is the table's RungeKutta4 stage.
    void runPasses(const std::vector<GasPass>& passes, double h);
    void stepRungeKutta4(double h);

    // Stages. Each loop over particles does as much as it can in one pass (gather form throughout).
    enum class Contacts { Ignore, Count, Initialise };
    // v += kickBefore a; x += h v; walls and obstacles; v += kickAfter a; displacement since the list build.
    void driftStage(double kickBefore, double h, double kickAfter);
    void boundaryStage(double h); // walls and obstacles only (after an RK4 update)
    // a at the current positions, then v += kickAfter a; with energies, also each disk's potential
    // energy and virial (only observables need them, so the steps skip them).
    void computeForces(Contacts contacts, double kickAfter = 0.0, bool energies = false);
    void computeForcesNeighbourList(Contacts contacts, double kickAfter, bool energies);
    // driftStage then computeForces (neighbour list) in one parallel region, the list rebuilt inside it
    // when due: one fork and join fewer per step, the same results.
    void driftThenForces(double kickBefore, double h, double kickAfterDrift, Contacts contacts,
                         double kickAfter);
    void refreshEnergies();
    void computeForcesAllPairs(Contacts contacts, double kickAfter);
    gas::Boundaries boundaries(double h) const;
    // Moves the dragged obstacles and the piston one step of h toward their targets (KinematicDrive.h).
    void advanceBodies(double h);
    // The piston's travel ends where the disks would cover kPistonMaxAreaFraction of the box (or one
    // diameter from the left wall, whichever is further right).
    double pistonLower() const;
    void ensureForces();
    void sortBySpace(); // particles in cell order, so neighbours in space are neighbours in memory

    // State building (GasInitialState.cpp)
    void buildInitialState();
    void placeRandom(long long first, long long count, int species);
    void placeLattice();
    void assignVelocities();

    // Health (GasStability.cpp)
    void checkHealth(bool energyCheck);
    std::string stabilityHint() const;
    double stiffestContactOmega() const; // ω [1/T] of the stiffest contact between the species present
    void rebaseEnergy();                 // after a user change: the new energy is the reference

    void populationChanged(); // after spawning or removing: counts, cells, forces, energy reference
    // After a body was put down on the disks (added, or placed while time stands): each disk it covers
    // goes to the nearest place where it overlaps no other disk beyond spawn_max_overlap, keeping its
    // velocity; one with no such place within reach is removed. Returns true when a disk moved.
    bool moveDisksOutOfBodies();
    bool overlapsTooMuch(double x, double y, double diameter) const;
    bool insideSpace(double x, double y, double radius) const;
    std::uint32_t nextId() { return nextId_++; }

    // What a GPU twin (core/gl/GasModelGL) tells the CPU model; it writes no member of this class.
    // The integrator the running gas was reset with (a change of `integrator` waits for Reset).
    GasIntegrator activeIntegrator() const { return integrator_; }
    // The device moved the disks (the lazy CPU copy was just filled from it): the neighbour list,
    // forces, energies and the displacement since the list build belong to other positions now.
    void stateChangedOnDevice() const;
    // The thermal walls' draws are numbered per drift within a step (boundaries()): a step's first
    // drift is 0, and each drift taken counts one on.
    void beginDrifts() { driftIndex_ = 0; }
    void driftDone() { ++driftIndex_; }
    // The device found a disk that left the box or became NaN: the next checkHealth() fails the step.
    void reportEscape() { escaped_ = true; }

private:
    // The snapshot's plain fields (GasSnapshot.cpp).
    static const StateTable<GasModel, GasState>& stateTable();

    GasIntegrator integrator_ = GasIntegrator::VelocityVerlet;

    // Caches of what the positions imply; mutable: a GPU twin's lazy download (a const pullState())
    // makes them stale (stateChangedOnDevice()).
    mutable NeighbourList neighbours_; // payload byte per pair: in contact at the last counted evaluation
    mutable double maxDisplacement2_ = -1.0; // since the list build, from the last drift; −1 when unknown
    CellList sortCells_;
    std::int64_t lastSortStep_ = -1;
    std::vector<double> xPrev_, yPrev_; // positions at the start of the step (all-pairs contact detection)
    std::vector<double> stageX_, stageY_, stageVX_, stageVY_, sumVX_, sumVY_, sumAX_, sumAY_; // RK4
    mutable bool forcesValid_ = false;
    std::int64_t forceEvaluations_ = 0;
    mutable bool energiesValid_ = false; // potential and virial belong to the current positions
    bool escaped_ = false;
    double pistonX_ = 1.0;        // where the piston is [L]; a reset puts it at piston_x
    double pistonVelocity_ = 0.0; // over the current step [L/T]
    PistonDrive pistonDrive_;

    std::uint32_t nextId_ = 0;
    std::uint64_t spawnEvents_ = 0;
    std::uint32_t driftIndex_ = 0; // distinguishes thermal-wall draws of several drifts in one step

    double energyBaseline_ = 0.0;  // E₀ of energyDrift
    double referenceEnergy_ = 0.0; // blow-up reference
    double lastSampleTime_ = 0.0;
    double lastCollisionRate_ = 0.0; // the previous row's, repeated by a row taken with no time between
    struct WallSample {
        double impulse, duration, perimeterTime;
    };
    std::deque<WallSample> wallWindow_;
};

} // namespace pl
