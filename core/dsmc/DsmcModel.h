// Bird's No-Time-Counter DSMC in one collision cell (the write-up): the NTC loop once, the collision model
// an interchangeable CollisionModel. step() reads like the method: candidates, selection, acceptance,
// scattering.
#pragma once

#include "DsmcCollisionModel.h"
#include "DsmcParams.h"
#include "DsmcState.h"
#include "common/Model.h"
#include "common/ModelBase.h"
#include "common/StateTable.h"

namespace pl {

struct DsmcObservables {
    std::int64_t step = 0;
    double time = 0;
    std::size_t particles = 0;
    double ux = 0, uy = 0, uz = 0;                   // mean velocity [m/s]
    double tx = 0, ty = 0, tz = 0, t = 0, tPerp = 0; // temperatures [K] about the mean velocity
    double kurtosisVx = 0;                           // ⟨δv_x⁴⟩ / ⟨δv_x²⟩²: 3 for a Maxwellian
    double m4 = 0, m6 = 0, m8 = 0;          // ⟨c^2k⟩ / M_2k^eq at the sampled energy: 1 at equilibrium
    double m4Bkw = 0, m6Bkw = 0, m8Bkw = 0; // the exact BKW values now (NaN unless BKW + Maxwell)
    double klDivergence = 0; // of the peculiar-speed histogram from Maxwell–Boltzmann at T [nats]
    double collisionsPerParticle = 0;
};

// Parameters, presets and the clock come from ModelBase (common/ModelBase.h); this class holds the NTC
// method.
class DsmcModel : public ModelBase<DsmcParams> {
public:
    DsmcModel();

    std::string kind() const override { return "dsmc"; }
    using ModelBase::reset;
    void reset() override;
    std::size_t particleCount() const override { return state_.size(); }
    std::string accuracyWarning() const override;
    std::int64_t plannedSteps() const override { return params_.runSteps; }
    bool reversible() const override { return false; }
    std::vector<std::string> seriesColumns() const override;
    std::vector<double> sampleSeries() override;
    std::vector<NamedHistogram> histograms() const override;
    void writeParticles(std::ostream& out) const override;
    SceneView sceneView() const override;
    StateRecord saveState() const override; // DsmcSnapshot.cpp
    void restoreState(const StateRecord& state) override;

    // DSMC-specific API
    const DsmcState& state() const { return state_; }
    DsmcObservables observe() const;
    const CollisionModel& collisionModel() const { return collisions_; }
    double numberDensity() const; // real molecules per m³
    long long lastCollisions() const { return collisionsThisStep_; }

private:
    // The snapshot's plain fields (DsmcSnapshot.cpp).
    static const StateTable<DsmcModel, DsmcState>& stateTable();
    void advance(double h) override; // one NTC collision step (no motion: the cell is homogeneous)
    // ModelBase's hooks: ν Δt bounds the parameters and presets (refused above kRefusedNuDt).
    void refuseParams(const DsmcParams& next) const override;
    void paramsChanged(const DsmcParams& before) override;
    void refuseBeforeBuilding(const DsmcParams& next, std::uint64_t seed) const override;
    void checkBuiltState() const override;

    void buildInitialState();
    // The velocity particle k of a population (stream) or of the BKW gas draws before its moments are
    // matched (DsmcInitialState.cpp), and that of particle i of the whole initial state: what
    // refuseBeforeBuilding() predicts (σ c_r)_max from without building the state.
    static dsmc::Velocity drawnVelocity(const DsmcParams& p, std::uint64_t seed, long long k,
                                        std::uint32_t stream);
    static dsmc::Velocity drawnBkwVelocity(const DsmcParams& p, std::uint64_t seed, long long k);
    static dsmc::Velocity drawnInitialVelocity(const DsmcParams& p, std::uint64_t seed, long long i);
    void addPopulation(long long count, double drift, std::uint8_t origin, std::uint32_t stream);
    void addBkwPopulation(long long count);
    void estimateSigmaCrMax();
    // ν_max Δt = (N − 1) F_N (σ c_r)_max Δt / V_c: collisions per particle and step at most (twice the
    // NTC candidates per particle), for p with the current state and (σ c_r)_max.
    double nuDtBound(const DsmcParams& p) const;
    // Empty when p keeps ν_max Δt within what a step can do, else why not and what to change.
    std::string nuDtRefusal(const DsmcParams& p) const;
    // The same for n particles and a (σ c_r)_max [m³/s].
    static std::string nuDtRefusal(const DsmcParams& p, double n, double sigmaCrMax);
    // The pairs estimateSigmaCrMax() samples, drawn from the initial state's pairs and the same random
    // numbers; sampleVelocity(i) gives particle i's velocity.
    template <class Velocity>
    static double sampledSigmaCrMax(const CollisionModel& collisions, std::uint64_t seed, std::uint32_t n,
                                    Velocity sampleVelocity);

    CollisionModel collisions_;
    DsmcState state_;
    double sigmaCrMax_ = 0.0;
    double remainder_ = 0.0; // fractional candidate carried to the next step (NTC)
    long long candidates_ = 0, collisionsThisStep_ = 0, collisionsTotal_ = 0;
};

} // namespace pl
