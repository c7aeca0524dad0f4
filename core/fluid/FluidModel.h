// Position-Based Fluids (Macklin & Müller 2013) in 2D: the write-up's interactive tank. step() reads like the
// paper's Algorithm 1; each pass over the particles is in gather form (it writes only particle i), so the
// GPU backend can mirror it kernel for kernel.
#pragma once

#include "FluidBoundaries.h"
#include "FluidKernels.h"
#include "FluidNeighbours.h"
#include "FluidParams.h"
#include "FluidState.h"
#include "common/KinematicDrive.h"
#include "common/Model.h"
#include "common/ModelBase.h"
#include "common/StateTable.h"

namespace pl {

struct FluidObservables {
    std::int64_t step = 0;
    double time = 0;
    std::size_t particles = 0;
    // Density error: the compression max(ρ/ρ₀ − 1, 0), mean over particles and max. The free surface is
    // always under-dense, so a signed mean would measure the surface rather than the compressibility.
    double densityErrorMean = 0, densityErrorMax = 0;
    double densityRatioMean = 0; // ⟨ρ/ρ₀⟩, signed: the write-up's ρ₀ = 1 shows here
    double kinetic = 0;          // Σ ½ v² (unit masses) [L²/s²]
    double maxSpeed = 0;
    double neighboursMean = 0, neighboursMin = 0, neighboursMax = 0; // within h
    // Dam-break surge front (docs/fluid.md#dam-break-front); NaN without an initial block.
    double frontZ = NAN, frontT = NAN;
    long long drained = 0; // removed by the drain since reset
};

// Parameters, presets, the clock, obstacles and the tools' rules come from SceneModelBase
// (common/ModelBase.h); this class holds the fluid's physics.
class FluidModel : public SceneModelBase<FluidParams, FluidState> {
public:
    FluidModel();
    ~FluidModel() override = default;

    std::string kind() const override { return "fluid"; }
    using ModelBase::reset;
    void reset() override;
    std::int64_t plannedSteps() const override { return params_.runSteps; }
    bool reversible() const override { return false; } // the projections dissipate
    std::vector<std::string> seriesColumns() const override;
    std::vector<double> sampleSeries() override;
    std::vector<NamedHistogram> histograms() const override { return {}; }
    std::vector<NamedProfile> profiles() const override;
    void writeParticles(std::ostream& out) const override;
    SceneView sceneView() const override;
    StateRecord saveState() const override; // FluidSnapshot.cpp
    void restoreState(const StateRecord& state) override;

    // SceneTools: the obstacles' tools and heat / cool are SceneModelBase's.
    double toolSpeed() const override;
    std::string spawnInRectangle(double x0, double y0, double x1, double y1) override;

    // Fluid-specific API
    FluidObservables observe() const;
    double restDensity() const { return restDensity_; }
    // Mean and max density error measured before each iteration of the last step, then after the last one.
    std::vector<double> iterationErrorMean() const;
    std::vector<double> iterationErrorMax() const;

protected:
    void advance(double h) override; // Algorithm 1, lines 1–24 (FluidModel.cpp)
    void afterStep() override;       // the drain over the cap, the divergence check
    // A GPU backend's pullState() also brings the per-iteration errors up to date.
    explicit FluidModel(DeferReset) {}
    void paramsChanged(const FluidParams& before) override;
    Area areaOf(const FluidParams& p) const override { return {0.0, 0.0, p.boxWidth, p.boxHeight}; }
    SceneView sceneFrame() const; // the scene without its particles
    // Moves the dragged obstacles one step toward their targets at bounded speed (KinematicDrive.h).
    void advanceBodies() { advanceObstacles(params_.dt); }

    // Algorithm 1, line by line.
    void applyExternalForcesAndPredict();
    void findNeighbours();
    // The λ pass; `iteration` indexes the density-error profile (kNotProfiled: a position-only iteration);
    // `newOnly` subtracts the old compression measured by measureOldCompression().
    static constexpr std::size_t kNotProfiled = static_cast<std::size_t>(-1);
    void computeLambdas(std::size_t iteration, bool newOnly = false);
    void measureOldCompression();
    void solveNewCompression();
    void limitRelease();
    void applyPositionCorrections();
    void leaveSolverNumbers();
    void updateVelocities();
    void applyVorticityConfinement();
    void applySurfaceForces();
    void applyXsphViscosity();
    void commitPositions();
    void drainOverCap();

    void refreshDerived(); // kernels, ρ₀, s_corr and the confinement box from the parameters
    fluid::Box confinementBox() const;
    fluid::WallJitter wallJitter() const;
    struct Spawned {
        long long added = 0, refusedCap = 0, refusedOutside = 0, refusedOverlap = 0;
        std::string message() const;
    };
    Spawned spawnLattice(double x0, double y0, double x1, double y1);
    // ρ_i/ρ₀ − 1 of every particle at the current positions.
    std::vector<double> densityConstraints(std::vector<int>* neighboursWithinH = nullptr) const;

    fluid::Kernels kernels_;
    fluid::ArtificialPressure scorr_;
    double restDensity_ = 1.0;

    // Per-step work arrays (kept to avoid reallocations).
    std::vector<double> px_, py_;       // predicted, then corrected positions
    std::vector<double> nextX_, nextY_; // Jacobi target of a correction pass
    std::vector<double> lambda_, constraint_;
    // The bounded release (release_limit > 0), in solver numbers: the step's starting positions and their
    // compression max(C_i(x), 0); the prediction x*; the solve of the step's new compression, then the
    // positions the velocity is taken from (in particle numbers after leaveSolverNumbers()).
    std::vector<double> startX_, startY_, oldCompression_, predictedX_, predictedY_, velocityX_, velocityY_;
    std::vector<double> pairGradX_, pairGradY_; // ∇W_ij per neighbour entry, at this iteration's positions
    std::vector<double> gradSumX_, gradSumY_;   // G_i = Σ_j ∇W_ij
    std::vector<double> scorrSumX_, scorrSumY_; // S_i = Σ_j s_corr,ij ∇W_ij
    std::vector<double> omega_, nextVx_, nextVy_;
    fluid::Neighbours neighbours_;

    mutable std::vector<double> errorMean_, errorMax_; // before iteration k of the last step
    long long drained_ = 0;
    // The snapshot's plain fields (FluidSnapshot.cpp).
    static const StateTable<FluidModel, FluidState>& stateTable();
};

} // namespace pl
