// The DSMC cell's dynamic state for snapshots: every velocity and origin, the clock, the NTC remainder,
// the running (σ c_r)_max and the collision counters. The random streams are keyed by the step, so the
// restored cell draws the same numbers.
#include "DsmcModel.h"

namespace pl {

StateRecord DsmcModel::saveState() const {
    StateRecord r;
    saveClock(r);
    r.put("sigma_cr_max", sigmaCrMax_);
    r.put("remainder", remainder_);
    r.put("candidates", static_cast<double>(candidates_));
    r.put("collisions_this_step", static_cast<double>(collisionsThisStep_));
    r.put("collisions_total", static_cast<double>(collisionsTotal_));
    r.put("vx", state_.vx);
    r.put("vy", state_.vy);
    r.put("vz", state_.vz);
    r.put("origin", state_.origin);
    return r;
}

void DsmcModel::restoreState(const StateRecord& r) {
    DsmcState s;
    s.vx = r.array<double>("vx");
    const std::size_t n = s.vx.size();
    if (n != state_.size())
        throw PresetError("state.vx", "the snapshot holds " + std::to_string(n) + " particles, its preset " +
                                          std::to_string(state_.size()));
    s.vy = r.array<double>("vy", n);
    s.vz = r.array<double>("vz", n);
    s.origin = r.array<std::uint8_t>("origin", n);
    restoreClock(r);
    sigmaCrMax_ = r.scalar("sigma_cr_max");
    remainder_ = r.scalar("remainder");
    candidates_ = static_cast<long long>(r.scalar("candidates"));
    collisionsThisStep_ = static_cast<long long>(r.scalar("collisions_this_step"));
    collisionsTotal_ = static_cast<long long>(r.scalar("collisions_total"));
    state_ = std::move(s);
}

} // namespace pl
