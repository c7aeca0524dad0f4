// The fluid's dynamic state for snapshots: positions, velocities, the clock, the drain's count and the
// last step's per-iteration errors. Neighbours are found anew every step, so nothing else carries over.
#include "FluidModel.h"

namespace pl {

const StateTable<FluidModel, FluidState>& FluidModel::stateTable() {
    static const StateTable<FluidModel, FluidState> table = [] {
        StateTable<FluidModel, FluidState> t;
        t.scalar("drained", &FluidModel::drained_)
            .array("error_mean", &FluidModel::errorMean_)
            .array("error_max", &FluidModel::errorMax_);
        t.perParticle("x", &FluidState::x)
            .perParticle("y", &FluidState::y)
            .perParticle("vx", &FluidState::vx)
            .perParticle("vy", &FluidState::vy);
        return t;
    }();
    return table;
}

StateRecord FluidModel::saveState() const {
    pullState();
    StateRecord r;
    saveClock(r);
    stateTable().save(*this, state_, r);
    return r;
}

void FluidModel::restoreState(const StateRecord& r) {
    const std::size_t n = stateTable().particlesIn(r);
    if (static_cast<long long>(n) > params_.maxParticles)
        throw PresetError("state.x", "the snapshot holds " + std::to_string(n) +
                                         " particles, more than its max_particles");
    FluidState s = stateTable().read(*this, r, n);
    restoreClock(r);
    stateTable().restore(*this, r);
    state_ = std::move(s);
    obstacleDrive_.clear();
    stateEdited();
}

} // namespace pl
