// The tunnel's dynamic state for snapshots: every molecule, the clock, the NTC remainders and running
// (σ c_r)_max of each cell, the inflow remainders, the piston and the spawn counter. The random streams
// are keyed by step, particle and cell, so the restored run draws the same numbers and continues bit
// for bit. The fields window restarts (its sums are a view of the run, not part of its state).
#include "TunnelModel.h"

#include <algorithm>

namespace pl {

StateRecord TunnelModel::saveState() const {
    pullState();
    StateRecord r;
    saveClock(r);
    r.put("x", state_.x);
    r.put("y", state_.y);
    r.put("vx", state_.vx);
    r.put("vy", state_.vy);
    r.put("vz", state_.vz);
    r.put("remainder", remainder_);
    r.put("cell_sigma_cr_max", cellSigmaCrMax_);
    r.put("inflow_remainder", inflowRemainder_);
    r.put("piston_x", pistonX_);
    r.put("piston_velocity", pistonVelocity_);
    r.put("piston_direction", static_cast<double>(pistonDrive_.direction()));
    r.put("piston_experiment", pistonExperiment_ ? 1.0 : 0.0);
    r.put("stream_counter", static_cast<double>(streamCounter_));
    r.put("collisions_this_step", static_cast<double>(collisionsThisStep_));
    return r;
}

void TunnelModel::restoreState(const StateRecord& r) {
    TunnelState s;
    s.x = r.array<double>("x");
    const std::size_t n = s.x.size();
    s.y = r.array<double>("y", n);
    s.vx = r.array<double>("vx", n);
    s.vy = r.array<double>("vy", n);
    s.vz = r.array<double>("vz", n);
    const std::size_t cells = openFraction_.size();
    std::vector<double> remainder = r.array<double>("remainder", cells);
    std::vector<double> sigmaCrMax = r.array<double>("cell_sigma_cr_max", cells);
    std::vector<double> inflow = r.array<double>("inflow_remainder", 4);
    for (std::size_t i = 0; i < n; ++i)
        if (!(s.x[i] >= 0 && s.x[i] <= params_.boxWidth && s.y[i] >= 0 && s.y[i] <= params_.boxHeight))
            throw PresetError("state.x", "molecule " + std::to_string(i) + " lies outside the tunnel");
    restoreClock(r);
    s.cell.resize(n);
    state_ = std::move(s);
    for (std::size_t i = 0; i < n; ++i) state_.cell[i] = cellOf(state_.x[i], state_.y[i]);
    remainder_ = std::move(remainder);
    cellSigmaCrMax_ = std::move(sigmaCrMax);
    inflowRemainder_ = std::move(inflow);
    pistonX_ = r.scalar("piston_x");
    pistonVelocity_ = r.scalar("piston_velocity");
    const int direction = static_cast<int>(r.scalar("piston_direction"));
    pistonDrive_.drive(direction);
    pistonExperiment_ = r.scalar("piston_experiment") != 0.0;
    streamCounter_ = static_cast<std::uint64_t>(r.scalar("stream_counter"));
    collisionsThisStep_ = static_cast<long long>(r.scalar("collisions_this_step"));
    restBodies();
    refreshOpenFraction();
    // The molecules keep their saved order, so the next steps index them as the saved run did.
    sortIntoCells();
    sigmaCrMax_ = cells > 0 ? *std::max_element(cellSigmaCrMax_.begin(), cellSigmaCrMax_.end()) : 0.0;
    restartSampling();
    stateEdited();
}

} // namespace pl
