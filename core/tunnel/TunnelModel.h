// The rarefied-gas wind tunnel: 2D DSMC on a uniform cell grid with Bird's No-Time-Counter collisions per
// cell (the DSMC cell's collision kernels), Maxwellian inflow, outflow, specular / diffuse / periodic
// sides, discs and boxes the user drags, a piston, and sampled fields and body forces. step() reads like
// the method: move (with boundary and body interactions), inflow, sort into cells, collide, sample.
#pragma once

#include "TunnelKernels.h"
#include "TunnelParams.h"
#include "TunnelSampler.h"
#include "TunnelState.h"
#include "common/Model.h"
#include "common/ModelBase.h"
#include "common/Philox.h"
#include "common/StateTable.h"
#include "dsmc/DsmcCollisionModel.h"

#include <cstdint>
#include <vector>

namespace pl {

// The tunnel's observables for the series: counts, collisions and the force on the bodies (summed over
// all of them) per unit depth.
struct TunnelObservables {
    std::size_t particles = 0;
    long long collisions = 0;  // accepted pairs in the last step
    double drag = 0, lift = 0; // mean over the steps since the previous sample [N/m]
    double dragAverage = 0;    // mean over the fields window [N/m]
    double liftAverage = 0;
    double meanFreeTime = 0; // collisions per particle per second over the last step⁻¹ [s]
    std::int64_t sampledSteps = 0;
};

class TunnelModel : public SceneModelBase<TunnelParams, TunnelState>, public SampledFields {
public:
    TunnelModel();

    std::string kind() const override { return "tunnel"; }
    using ModelBase::reset;
    void reset() override;
    std::int64_t plannedSteps() const override { return params_.runSteps; }
    bool reversible() const override { return false; }
    std::string accuracyWarning() const override;
    std::vector<std::string> seriesColumns() const override;
    std::vector<double> sampleSeries() override;
    std::vector<NamedHistogram> histograms() const override;
    void writeParticles(std::ostream& out) const override;
    SceneView sceneView() const override;
    StateRecord saveState() const override;
    void restoreState(const StateRecord& state) override;
    // A stop request's undo of a step (TunnelStepUndo.cpp): the move copies each chunk of molecules just
    // before it moves it, the rest of what a step changes is small (per cell, per side, the bodies, the
    // sampler); undoing copies back the chunks the move reached, or swaps the whole arrays back once it
    // finished. The GPU twin keeps its state on the device and is kept whole instead.
    bool keepStepStart() override;
    void undoStep() override;
    const SampledFields* sampledFields() const override { return this; }

    // SceneTools beyond the base's obstacle edits
    double toolSpeed() const override { return params_.toolSpeed; }
    std::string spawnInRectangle(double x0, double y0, double x1, double y1) override; // free-stream gas
    bool hasPiston() const override { return params_.pistonOn; }
    double pistonX() const override { return pistonX_; }
    void dragPiston(double x) override;
    void drivePiston(int direction) override;
    int pistonDirection() const override;
    void placePiston(double x) override;
    // Heat / cool scales all three velocity components (the base scales the plane's two).
    void scaleKineticEnergy(double factor) override;

    // SampledFields (forwarded to the sampler, brought up to date first)
    std::vector<FieldChoice> fieldChoices() const override { return sampler_.fieldChoices(); }
    FieldGrid field(const std::string& name) const override { return sampler().field(name); }
    std::vector<FieldValue> probe(double x, double y) const override { return sampler().probe(x, y); }
    std::int64_t sampledSteps() const override { return sampler().sampledSteps(); }
    void writeFieldsCsv(std::ostream& out) const override { sampler().writeFieldsCsv(out); }

    // Tunnel-specific API (tests, the GL backend's parity checks). A GPU backend brings what each
    // reads over first (pullSamples(), pullState()).
    TunnelObservables observe() const;
    const TunnelSampler& sampler() const {
        pullSamples();
        return sampler_;
    }
    const CollisionModel& collisionModel() const { return collisions_; }
    double sigmaCrMax() const {
        pullState();
        return sigmaCrMax_;
    }
    long long lastCollisions() const {
        pullSamples();
        return collisionsThisStep_;
    }
    // Mean free path of the free stream [m] (VHS / hard sphere, Bird 1994 eq. 4.65) and the Knudsen
    // number on body 0's diameter (or the box height when there is no body).
    double freeStreamMeanFreePath() const;
    double knudsenNumber() const;
    // Mean collision time of the free stream 1 / (n ⟨σ c_r⟩) [s].
    double freeStreamCollisionTime() const { return collisionTimeOf(params_); }
    static double meanFreePathOf(const TunnelParams& p);
    static double collisionTimeOf(const TunnelParams& p);
    static CollisionModel collisionModelOf(const TunnelParams& p);
    // The piston's velocity over the last step [m/s] (0 when it stands or is off).
    double pistonVelocity() const { return pistonVelocity_; }
    // Per cell, the fraction of its area outside every body (row-major j · cellsX + i).
    const std::vector<double>& openFraction() const { return openFraction_; }
    // (σ c_r)_max of each cell: raised when a pair exceeds it (Bird 1994 §11.1).
    const std::vector<double>& cellSigmaCrMax() const {
        pullState();
        return cellSigmaCrMax_;
    }
    // After each step the molecules of cell c are state indices order()[cellStart()[c] ..
    // cellStart()[c + 1] − 1] (cellStart().size() == cells + 1).
    const std::vector<std::uint32_t>& cellStart() const {
        pullState();
        return cellStart_;
    }
    const std::vector<std::uint32_t>& order() const {
        pullState();
        return order_;
    }

    // The particles reset() makes for these parameters and bodies (the registration's count): the
    // free-stream number n V_c f / F_N of each cell's open area, the fractions carried from cell to cell.
    static std::size_t initialFillCount(const TunnelParams& p, const std::vector<Obstacle>& obstacles);
    // The open fraction of every cell for these bodies (sub-sampled on a grid of points per cell).
    static std::vector<double> openFractions(const TunnelParams& p, const std::vector<Obstacle>& obstacles);

protected:
    void advance(double h) override; // move, inflow, sort, collide, sample (TunnelModel.cpp)
    void afterStep() override;       // the molecule limit
    // Fails the step: count molecules are more than moleculeLimit().
    void failTooManyMolecules(std::size_t count);
    // TunnelParams::moleculeLimit() at the reset: the memory the run planned for.
    double moleculeLimit() const { return moleculeLimit_; }
    // A GPU backend resets once itself, after its buffers exist.
    explicit TunnelModel(DeferReset) {}
    // A backend that samples elsewhere (the GPU) hands its cell sums, body impulses and collision
    // counts to sampler_ here before they are read.
    virtual void pullSamples() const {}
    Area areaOf(const TunnelParams& p) const override;
    void bodiesEdited(BodyEdit edit) override;

    // Protected, not private: the GL backend (gl/TunnelModelGL) steps the same state on the GPU.
    void refuseParams(const TunnelParams& next) const override;
    void refuseBeforeBuilding(const TunnelParams& next, std::uint64_t seed) const override;
    void paramsChanged(const TunnelParams& before) override;
    void checkObstacles(const TunnelParams& next, const std::vector<Obstacle>& obstacles) const override;

    void moveParticles(double h); // TunnelMove.cpp: flight, sides, bodies, the piston
    void admitInflow(double h);   // TunnelInflow.cpp: the free stream through each Inflow side
    // Drops the molecules that left, then a counting sort by cell into cellStart_ / order_; with
    // reorder, the arrays themselves are put in cell order (order_ is then the identity).
    void sortIntoCells(bool reorder = false);
    void collide(double h); // TunnelCollide.cpp: NTC per cell
    void restartSampling(); // the window waits sampleStart steps again, sampleWindow steps long
    // The CPU-only ends of step(), which a GPU step calls in the same order: the obstacles' and the
    // piston's drives (returns the piston's velocity over the step), then the fields and forces' step.
    double advanceBodies(double h);
    void sampleStep(double h);
    // sceneView() without the particles: frame, colours, bodies, piston and the field image.
    SceneView sceneFrame() const;
    bool pistonMoving() const override { return pistonDrive_.moving(); }

    void configureGrid();       // sampler grid, per-cell arrays, open fractions (after a reset)
    void refreshOpenFraction(); // bodies moved or changed: new open fractions for NTC and the sampler
    // A uniform draw in (0, 1) for the fractional count of `purpose` at `subject` after a reset.
    double startingRemainder(RngPurpose purpose, std::size_t subject) const;
    void refreshCollisionModel();
    double initialSigmaCrMax() const; // a generous first (σ c_r)_max for every cell
    void advancePiston(double h);
    // Fills the open part of [x0, x1] × [y0, y1] with free-stream gas (drifting at the stream speed when
    // drifting); `call` keys the random stream. Returns {added, refused inside bodies}.
    struct Filled {
        long long added = 0, refused = 0;
    };
    Filled fillRectangle(double x0, double y0, double x1, double y1, bool drifting, std::uint64_t call);
    dsmc::Velocity freeStreamVelocity(tunnel::CounterRng& rng, bool drifting) const;
    // One particle's straight flight from τ0 to h within the step (TunnelMove.cpp), with sides, bodies
    // and the piston; the gas's momentum change at body b goes to impulse[2b], impulse[2b + 1].
    // Returns false when the particle left the domain.
    bool fly(std::size_t i, double tau0, double h, tunnel::CounterRng& rng, double* impulse);
    void pushOutOfBodies(std::size_t i);
    std::uint32_t cellOf(double x, double y) const;

    // What a GPU twin hands over while it fills the CPU copy (core/gl/TunnelModelGL: download()): the
    // molecules are in cell order, cell c from cellStart[c]; each cell's NTC remainder and (σ c_r)_max.
    void adoptDeviceCells(const std::vector<std::uint32_t>& cellStart, const std::vector<float>& remainders,
                          const std::vector<float>& sigmaCrMax) const;
    // The sampler, for the samples of the steps a GPU twin took (flushSamples(), also from const readers).
    TunnelSampler& samplerForHandOver() const { return sampler_; }
    // The accepted pairs of the last step a GPU twin took.
    void adoptDeviceCollisions(long long collisions) const { collisionsThisStep_ = collisions; }

    std::vector<tunnel::BodyFrame> frames_; // the bodies as this step's flights see them
    std::vector<double> openFraction_;
    // Mutable, like state_: a GPU twin's lazy download (a const pullState()) fills them with the state
    // (adoptDeviceCells(), samplerForHandOver()).
    mutable std::vector<double> cellSigmaCrMax_;
    std::vector<double> impulseChunks_;     // per chunk of particles and body: (dpx, dpy), summed in order
    std::vector<double> scratch_;           // the sort's gather buffer
    std::vector<std::uint32_t> partCounts_; // the sort's per-thread counts, then slots
    double pistonVelocity_ = 0.0;
    bool pistonExperiment_ = false; // the piston runs the preset's drive (piston_speed > 0 at reset)

    CollisionModel collisions_;
    mutable TunnelSampler sampler_;
    // Cell c holds the molecules order_[cellStart_[c] .. cellStart_[c + 1] − 1].
    mutable std::vector<std::uint32_t> cellStart_, order_;
    mutable std::vector<double> remainder_; // NTC fractional candidates per cell
    std::vector<double> inflowRemainder_;   // fractional entering particles per side
    mutable double sigmaCrMax_ = 0.0;
    double moleculeLimit_ = TunnelParams::maxParticles();
    double pistonX_ = 0.0;
    PistonDrive pistonDrive_;
    std::int64_t sampleFrom_ = 0;              // first step of the window
    mutable long long collisionsThisStep_ = 0; // a GPU twin's hand-over sets it, as the sampler
    std::uint64_t streamCounter_ = 0;          // Philox counter of the model's random stream

    // The start of the step now running, while a stop request may abandon it (keepStepStart()).
    struct StepStart {
        bool keeping = false;                // the step now running keeps its start
        TunnelState molecules;               // the chunks the move reached, as it found them
        std::vector<std::uint8_t> chunkKept; // per chunk of the move: copied (and then moved)
        std::size_t chunkSize = 0;           // molecules per chunk of the move
        bool moved = false;                  // the move finished: molecules holds every one
        bool sorted = false;                 // the sort ran: order holds the step start's order_
        std::vector<std::uint32_t> order, cellStart;
        std::vector<double> remainder, cellSigmaCrMax, inflowRemainder, openFraction;
        std::vector<Obstacle> obstacles;
        ObstacleDrive obstacleDrive;
        PistonDrive pistonDrive;
        double pistonX = 0.0, pistonVelocity = 0.0, sigmaCrMax = 0.0;
        bool pistonExperiment = false;
        std::int64_t sampleFrom = 0;
        long long collisionsThisStep = 0;
        TunnelSampler sampler;
    };
    StepStart stepStart_;
    // The move's copy of chunk c (molecules [first, end)) before it moves them, when the step keeps its
    // start.
    void keepChunk(std::size_t c, std::size_t first, std::size_t end);

private:
    // The snapshot's plain fields (TunnelSnapshot.cpp).
    static const StateTable<TunnelModel, TunnelState>& stateTable();
};

} // namespace pl
