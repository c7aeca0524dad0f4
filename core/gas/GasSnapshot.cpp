// The gas's dynamic state for snapshots: every particle array, the clocks and counters (stateTable()),
// the wall window, and the neighbour list as it stands (a permuted list sums forces in another order than a
// fresh one, and the last bit of a force decides a chaotic trajectory).
#include "GasModel.h"

#include <algorithm>

namespace pl {

// The plain fields: numbers of the model and one array entry per disk.
const StateTable<GasModel, GasState>& GasModel::stateTable() {
    static const StateTable<GasModel, GasState> table = [] {
        StateTable<GasModel, GasState> t;
        t.scalar("next_id", &GasModel::nextId_)
            .scalar("spawn_events", &GasModel::spawnEvents_)
            .scalar("last_sort_step", &GasModel::lastSortStep_)
            .scalar("last_sample_time", &GasModel::lastSampleTime_)
            .scalar("energy_baseline", &GasModel::energyBaseline_)
            .scalar("reference_energy", &GasModel::referenceEnergy_)
            .scalar("piston_velocity", &GasModel::pistonVelocity_)
            .scalar("max_displacement2", &GasModel::maxDisplacement2_)
            .scalar("forces_valid", &GasModel::forcesValid_)
            .scalar("energies_valid", &GasModel::energiesValid_);
        t.perParticle("x", &GasState::x)
            .perParticle("y", &GasState::y)
            .perParticle("vx", &GasState::vx)
            .perParticle("vy", &GasState::vy)
            .perParticle("ax", &GasState::ax)
            .perParticle("ay", &GasState::ay)
            .perParticle("species", &GasState::species)
            .perParticle("id", &GasState::id)
            .perParticle("potential", &GasState::potential)
            .perParticle("virial", &GasState::virial)
            .perParticle("wall_impulse", &GasState::wallImpulse)
            .perParticle("contacts_begun", &GasState::contactsBegun);
        return t;
    }();
    return table;
}

StateRecord GasModel::saveState() const {
    pullState();
    StateRecord r;
    saveClock(r);
    stateTable().save(*this, state_, r);
    std::vector<double> window;
    for (const WallSample& w : wallWindow_)
        window.insert(window.end(), {w.impulse, w.duration, w.perimeterTime});
    r.put("wall_window", window);
    r.put("last_collision_rate", lastCollisionRate_);
    r.put("piston_x", pistonX_);
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
    GasState s = stateTable().read(*this, r, n);
    const auto counted = [&](int species) {
        return static_cast<long long>(std::count(s.species.begin(), s.species.end(), species));
    };
    if (counted(0) != params_.a.count || counted(1) != params_.b.count)
        throw PresetError("state.species", "state.species does not hold count_a disks of A and count_b of B");
    // A contact's energy ½ k δ² is never negative; the cache is read as it is while energies_valid says so.
    for (std::size_t i = 0; i < n; ++i)
        if (s.potential[i] < 0)
            throw PresetError("state.potential", "state.potential[" + std::to_string(i) +
                                                     "] is negative; a contact's energy never is");
    NeighbourList::Contents list;
    list.valid = r.scalar("neighbours_valid") != 0.0;
    list.skin = r.scalar("neighbours_skin");
    list.offsets = r.array<std::uint32_t>("neighbours_offsets");
    list.entries = r.array<std::uint32_t>("neighbours_entries");
    list.payload = r.array<std::uint8_t>("neighbours_payload", list.entries.size());
    list.builtX = r.array<double>("neighbours_built_x");
    list.builtY = r.array<double>("neighbours_built_y", list.builtX.size());
    if (list.valid && (list.offsets.size() != n + 1 || list.builtX.size() != n))
        throw PresetError("state.neighbours_offsets",
                          "the snapshot's neighbour list does not fit its particles");
    // Rows are read from the offsets even in a list waiting to be rebuilt: each row must lie in entries.
    if (!list.offsets.empty() && (list.offsets.front() != 0 || list.offsets.back() != list.entries.size() ||
                                  !std::is_sorted(list.offsets.begin(), list.offsets.end())))
        throw PresetError("state.neighbours_offsets",
                          "state.neighbours_offsets must rise from 0 to the number of entries");
    // An invalid list (all-pairs forces never rebuild it) is rebuilt before use: stale entries are harmless.
    for (const std::uint32_t j : list.entries)
        if (list.valid && j >= n)
            throw PresetError("state.neighbours_entries",
                              "the snapshot's neighbour list names a missing disk");
    const std::vector<double> window = r.array<double>("wall_window");
    if (window.size() % 3 != 0) throw PresetError("state.wall_window", "state.wall_window must hold triples");
    // Absent from snapshots of earlier builds: their first resumed row showed no collisions.
    const double collisionRate = r.scalarOr("last_collision_rate", 0.0);
    if (collisionRate < 0)
        throw PresetError("state.last_collision_rate", "state.last_collision_rate must not be negative");
    // Where the piston is. Snapshots of earlier builds have it in the preset's piston_x, which the
    // moving piston overwrote then.
    const double piston = r.scalarOr("piston_x", params_.pistonX);
    if (params_.pistonEnabled && !(piston > params_.left() && piston <= 0.5 * params_.boxWidth))
        throw PresetError("state.piston_x", "state.piston_x must lie inside the box");

    restoreClock(r);
    stateTable().restore(*this, r);
    state_ = std::move(s);
    neighbours_.restore(std::move(list));
    wallWindow_.clear();
    for (std::size_t k = 0; k < window.size(); k += 3)
        wallWindow_.push_back({window[k], window[k + 1], window[k + 2]});
    lastCollisionRate_ = collisionRate;
    pistonX_ = piston;
    escaped_ = false;
    obstacleDrive_.clear();
    pistonDrive_.stop();
    stateEdited();
    ensureForces();
}

} // namespace pl
