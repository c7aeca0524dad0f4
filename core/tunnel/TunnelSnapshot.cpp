// The tunnel's dynamic state for snapshots: every molecule, the clock, the NTC remainders and running
// (σ c_r)_max of each cell, the inflow remainders, the piston and the spawn counter. The random streams
// are keyed by step, particle and cell, so the restored run draws the same numbers and continues bit
// for bit. The sampler's window, surface sums and series interval travel too (TunnelSamplerState.cpp),
// so a resumed run's fields, forces and first row are those of the run that never stopped.
#include "TunnelModel.h"

#include <algorithm>

namespace pl {

namespace {
// A cell's running (σ c_r)_max grows past the first estimate in a shock, never by this factor.
constexpr double kMostSigmaCrMaxFactor = 1000.0;
} // namespace

const StateTable<TunnelModel, TunnelState>& TunnelModel::stateTable() {
    static const StateTable<TunnelModel, TunnelState> table = [] {
        constexpr auto cells = [](const TunnelModel& m) { return m.openFraction_.size(); };
        constexpr auto sides = [](const TunnelModel&) { return std::size_t(4); }; // left, right, bottom, top
        StateTable<TunnelModel, TunnelState> t;
        t.array("remainder", &TunnelModel::remainder_, cells)
            .array("cell_sigma_cr_max", &TunnelModel::cellSigmaCrMax_, cells)
            .array("inflow_remainder", &TunnelModel::inflowRemainder_, sides)
            .scalar("piston_x", &TunnelModel::pistonX_)
            .scalar("piston_velocity", &TunnelModel::pistonVelocity_)
            .scalar("piston_experiment", &TunnelModel::pistonExperiment_)
            .scalar("stream_counter", &TunnelModel::streamCounter_)
            .scalar("collisions_this_step", &TunnelModel::collisionsThisStep_);
        t.perParticle("x", &TunnelState::x)
            .perParticle("y", &TunnelState::y)
            .perParticle("vx", &TunnelState::vx)
            .perParticle("vy", &TunnelState::vy)
            .perParticle("vz", &TunnelState::vz);
        return t;
    }();
    return table;
}

StateRecord TunnelModel::saveState() const {
    pullState();
    StateRecord r;
    saveClock(r);
    stateTable().save(*this, state_, r);
    r.put("piston_direction", static_cast<double>(pistonDrive_.direction()));
    r.put("sample_from", static_cast<double>(sampleFrom_));
    sampler_.save(r);
    return r;
}

void TunnelModel::restoreState(const StateRecord& r) {
    const std::size_t n = stateTable().particlesIn(r);
    TunnelState s = stateTable().read(*this, r, n);
    for (std::size_t i = 0; i < n; ++i)
        if (!(s.x[i] >= 0 && s.x[i] <= params_.boxWidth && s.y[i] >= 0 && s.y[i] <= params_.boxHeight))
            throw PresetError("state.x", "molecule " + std::to_string(i) + " lies outside the tunnel");
    const double pistonDirection = r.scalar("piston_direction");
    if (pistonDirection != -1.0 && pistonDirection != 0.0 && pistonDirection != 1.0)
        throw PresetError("state.piston_direction", "state.piston_direction must be −1, 0 or 1");
    const int direction = static_cast<int>(pistonDirection);
    // The NTC and inflow remainders are fractions of a molecule or pair; a (σ c_r)_max far beyond any
    // the gas reaches would make a step of billions of candidates.
    for (const char* key : {"remainder", "inflow_remainder"})
        for (const double fraction : r.array<double>(key))
            if (!(fraction >= 0 && fraction < 1))
                throw PresetError(std::string("state.") + key,
                                  std::string("state.") + key + " must lie in [0, 1)");
    const double mostSigmaCr = kMostSigmaCrMaxFactor * initialSigmaCrMax();
    for (const double sigmaCr : r.array<double>("cell_sigma_cr_max"))
        if (!(sigmaCr >= 0 && sigmaCr <= mostSigmaCr))
            throw PresetError("state.cell_sigma_cr_max",
                              "state.cell_sigma_cr_max holds " + formatNumber(sigmaCr, 3) + " m³/s, beyond " +
                                  formatNumber(mostSigmaCr, 3) + " (1000 × the first estimate of this gas)");
    // Snapshots of earlier builds hold no sampler: their window starts again, as it did then.
    const bool sampled = TunnelSampler::savedIn(r);
    TunnelSampler sampler = sampler_;
    std::int64_t sampleFrom = 0;
    if (sampled) {
        sampler.restore(r);
        sampleFrom = r.count("sample_from");
    }
    restoreClock(r);
    stateTable().restore(*this, r);
    s.cell.resize(n);
    state_ = std::move(s);
    for (std::size_t i = 0; i < n; ++i) state_.cell[i] = cellOf(state_.x[i], state_.y[i]);
    pistonDrive_.drive(direction);
    if (sampled) sampler_ = std::move(sampler), sampleFrom_ = sampleFrom;
    restBodies();
    refreshOpenFraction();
    // The molecules keep their saved order, so the next steps index them as the saved run did.
    sortIntoCells();
    sigmaCrMax_ =
        cellSigmaCrMax_.empty() ? 0.0 : *std::max_element(cellSigmaCrMax_.begin(), cellSigmaCrMax_.end());
    if (!sampled) restartSampling();
    stateEdited();
}

} // namespace pl
