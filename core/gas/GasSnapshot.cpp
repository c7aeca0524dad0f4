// The gas's dynamic state for snapshots: every particle array, the clocks and counters, the wall window,
// and the neighbour list as it stands (a permuted list sums forces in another order than a fresh one,
// and the last bit of a force decides a chaotic trajectory).
#include "GasModel.h"

#include <algorithm>

namespace pl {

StateRecord GasModel::saveState() const {
    pullState();
    StateRecord r;
    saveClock(r);
    r.put("next_id", nextId_);
    r.put("spawn_events", static_cast<double>(spawnEvents_));
    r.put("last_sort_step", static_cast<double>(lastSortStep_));
    r.put("last_sample_time", lastSampleTime_);
    r.put("energy_baseline", energyBaseline_);
    r.put("reference_energy", referenceEnergy_);
    r.put("piston_velocity", pistonVelocity_);
    r.put("max_displacement2", maxDisplacement2_);
    r.put("forces_valid", forcesValid_ ? 1.0 : 0.0);
    r.put("energies_valid", energiesValid_ ? 1.0 : 0.0);
    r.put("x", state_.x);
    r.put("y", state_.y);
    r.put("vx", state_.vx);
    r.put("vy", state_.vy);
    r.put("ax", state_.ax);
    r.put("ay", state_.ay);
    r.put("species", state_.species);
    r.put("id", state_.id);
    r.put("potential", state_.potential);
    r.put("virial", state_.virial);
    r.put("wall_impulse", state_.wallImpulse);
    r.put("contacts_begun", state_.contactsBegun);
    std::vector<double> window;
    for (const WallSample& w : wallWindow_)
        window.insert(window.end(), {w.impulse, w.duration, w.perimeterTime});
    r.put("wall_window", window);
    const NeighbourList::Contents list = neighbours_.contents();
    r.put("neighbours_valid", list.valid ? 1.0 : 0.0);
    r.put("neighbours_skin", list.skin);
    r.put("neighbours_offsets", list.offsets);
    r.put("neighbours_entries", list.entries);
    r.put("neighbours_payload", list.payload);
    r.put("neighbours_built_x", list.builtX);
    r.put("neighbours_built_y", list.builtY);
    return r;
}

void GasModel::restoreState(const StateRecord& r) {
    const auto n = static_cast<std::size_t>(params_.totalCount());
    GasState s;
    s.x = r.array<double>("x", n);
    s.y = r.array<double>("y", n);
    s.vx = r.array<double>("vx", n);
    s.vy = r.array<double>("vy", n);
    s.ax = r.array<double>("ax", n);
    s.ay = r.array<double>("ay", n);
    s.species = r.array<std::uint8_t>("species", n);
    s.id = r.array<std::uint32_t>("id", n);
    s.potential = r.array<double>("potential", n);
    s.virial = r.array<double>("virial", n);
    s.wallImpulse = r.array<double>("wall_impulse", n);
    s.contactsBegun = r.array<std::uint32_t>("contacts_begun", n);
    const auto counted = [&](int species) {
        return static_cast<long long>(std::count(s.species.begin(), s.species.end(), species));
    };
    if (counted(0) != params_.a.count || counted(1) != params_.b.count)
        throw PresetError("state.species", "state.species does not hold count_a disks of A and count_b of B");
    NeighbourList::Contents list;
    list.valid = r.scalar("neighbours_valid") != 0.0;
    list.skin = r.scalar("neighbours_skin");
    list.offsets = r.array<std::uint32_t>("neighbours_offsets");
    list.entries = r.array<std::uint32_t>("neighbours_entries");
    list.payload = r.array<std::uint8_t>("neighbours_payload", list.entries.size());
    list.builtX = r.array<double>("neighbours_built_x");
    list.builtY = r.array<double>("neighbours_built_y", list.builtX.size());
    if (list.valid && (list.offsets.size() != n + 1 || list.builtX.size() != n ||
                       list.offsets.back() != list.entries.size()))
        throw PresetError("state.neighbours_offsets",
                          "the snapshot's neighbour list does not fit its particles");
    // An invalid list (all-pairs forces never rebuild it) is rebuilt before use: stale entries are harmless.
    for (const std::uint32_t j : list.entries)
        if (list.valid && j >= n)
            throw PresetError("state.neighbours_entries",
                              "the snapshot's neighbour list names a missing disk");
    const std::vector<double> window = r.array<double>("wall_window");
    if (window.size() % 3 != 0) throw PresetError("state.wall_window", "state.wall_window must hold triples");

    restoreClock(r);
    nextId_ = static_cast<std::uint32_t>(r.scalar("next_id"));
    spawnEvents_ = static_cast<std::uint64_t>(r.scalar("spawn_events"));
    lastSortStep_ = static_cast<std::int64_t>(r.scalar("last_sort_step"));
    lastSampleTime_ = r.scalar("last_sample_time");
    energyBaseline_ = r.scalar("energy_baseline");
    referenceEnergy_ = r.scalar("reference_energy");
    pistonVelocity_ = r.scalar("piston_velocity");
    maxDisplacement2_ = r.scalar("max_displacement2");
    forcesValid_ = r.scalar("forces_valid") != 0.0;
    energiesValid_ = r.scalar("energies_valid") != 0.0;
    state_ = std::move(s);
    neighbours_.restore(std::move(list));
    wallWindow_.clear();
    for (std::size_t k = 0; k < window.size(); k += 3)
        wallWindow_.push_back({window[k], window[k + 1], window[k + 2]});
    escaped_ = false;
    obstacleDrive_.clear();
    pistonDrive_.stop();
    stateEdited();
    ensureForces();
}

} // namespace pl
