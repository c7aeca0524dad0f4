// The DSMC cell's dynamic state for snapshots: every velocity and origin, the clock, the NTC remainder,
// the running (σ c_r)_max and the collision counters. The random streams are keyed by the step, so the
// restored cell draws the same numbers.
#include "DsmcModel.h"

namespace pl {

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
    restoreClock(r);
    stateTable().restore(*this, r);
    state_ = std::move(s);
}

} // namespace pl
