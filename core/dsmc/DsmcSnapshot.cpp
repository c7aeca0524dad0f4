// The DSMC cell's dynamic state for snapshots: every velocity and origin, the clock, the NTC remainder,
// the running (σ c_r)_max and the collision counters. The random streams are keyed by the step, so the
// restored cell draws the same numbers.
#include "DsmcModel.h"

#include <algorithm>

namespace pl {

namespace {
// Far above what the ν·Δt bound lets a cell reach (10 collisions per particle and step, each candidate
// accepted with probability σ c_r / (σ c_r)_max), far below a step that cannot end.
constexpr double kMostCandidatesPerParticle = 1000.0;
} // namespace

const StateTable<DsmcModel, DsmcState>& DsmcModel::stateTable() {
    static const StateTable<DsmcModel, DsmcState> table = [] {
        StateTable<DsmcModel, DsmcState> t;
        t.scalar("sigma_cr_max", &DsmcModel::sigmaCrMax_)
            .scalar("remainder", &DsmcModel::remainder_)
            .scalar("candidates", &DsmcModel::candidates_)
            .scalar("collisions_this_step", &DsmcModel::collisionsThisStep_)
            .scalar("collisions_total", &DsmcModel::collisionsTotal_);
        t.perParticle("vx", &DsmcState::vx)
            .perParticle("vy", &DsmcState::vy)
            .perParticle("vz", &DsmcState::vz)
            .perParticle("origin", &DsmcState::origin);
        return t;
    }();
    return table;
}

StateRecord DsmcModel::saveState() const {
    StateRecord r;
    saveClock(r);
    stateTable().save(*this, state_, r);
    return r;
}

void DsmcModel::restoreState(const StateRecord& r) {
    const std::size_t n = stateTable().particlesIn(r);
    if (n != state_.size())
        throw PresetError("state.vx", "the snapshot holds " + std::to_string(n) + " particles, its preset " +
                                          std::to_string(state_.size()));
    DsmcState s = stateTable().read(*this, r, n);
    // The NTC numbers decide how many pairs a step tests: a remainder outside [0, 1) or a (σ c_r)_max far
    // beyond any the gas reaches would make a step of billions of candidates.
    const double remainder = r.scalar("remainder"), sigmaCrMax = r.scalar("sigma_cr_max");
    if (!(remainder >= 0 && remainder < 1))
        throw PresetError("state.remainder", "state.remainder must lie in [0, 1)");
    const double candidatesPerParticle =
        0.5 * std::max(0.0, double(n) - 1.0) * params_.fn * sigmaCrMax * params_.dt / params_.cellVolume;
    if (!(sigmaCrMax >= 0 && candidatesPerParticle <= kMostCandidatesPerParticle))
        throw PresetError("state.sigma_cr_max", "state.sigma_cr_max = " + formatNumber(sigmaCrMax, 3) +
                                                    " m³/s would test " +
                                                    formatNumber(candidatesPerParticle, 3) +
                                                    " pairs per particle and step (at most " +
                                                    formatNumber(kMostCandidatesPerParticle, 3) + ")");
    restoreClock(r);
    stateTable().restore(*this, r);
    state_ = std::move(s);
}

} // namespace pl
