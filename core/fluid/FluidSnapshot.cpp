// The fluid's dynamic state for snapshots: positions, velocities, the clock, the drain's count and the
// last step's per-iteration errors. Neighbours are found anew every step, so nothing else carries over.
#include "FluidModel.h"

namespace pl {

StateRecord FluidModel::saveState() const {
    pullState();
    StateRecord r;
    saveClock(r);
    r.put("drained", static_cast<double>(drained_));
    r.put("x", state_.x);
    r.put("y", state_.y);
    r.put("vx", state_.vx);
    r.put("vy", state_.vy);
    r.put("error_mean", errorMean_);
    r.put("error_max", errorMax_);
    return r;
}

void FluidModel::restoreState(const StateRecord& r) {
    FluidState s;
    s.x = r.array<double>("x");
    const std::size_t n = s.x.size();
    if (static_cast<long long>(n) > params_.maxParticles)
        throw PresetError("state.x", "the snapshot holds " + std::to_string(n) +
                                         " particles, more than its max_particles");
    s.y = r.array<double>("y", n);
    s.vx = r.array<double>("vx", n);
    s.vy = r.array<double>("vy", n);
    std::vector<double> errorMean = r.array<double>("error_mean"), errorMax = r.array<double>("error_max");
    restoreClock(r);
    drained_ = static_cast<long long>(r.scalar("drained"));
    state_ = std::move(s);
    errorMean_ = std::move(errorMean);
    errorMax_ = std::move(errorMax);
    obstacleDrive_.clear();
    stateEdited();
}

} // namespace pl
