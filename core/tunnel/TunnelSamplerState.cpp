// The sampler's part of a tunnel snapshot: the fields window (its step count and the seven sums of every
// cell, and a moving window's older half), the surface sums of the window, the last step's forces and the
// series' open interval. Without them a resumed run showed empty fields, restarted drag_avg at 0 and reopened
// the window only sample_start steps later (docs/wind-tunnel.md#snapshots).
#include "TunnelSampler.h"

#include <algorithm>
#include <string>

namespace pl {

namespace {

// The cell sums in the order they are saved, each as one array of one entry per cell.
constexpr struct {
    const char* key;
    double TunnelSampler::CellSums::*member;
} kCellSums[] = {
    {"sampling_count", &TunnelSampler::CellSums::count}, {"sampling_vx", &TunnelSampler::CellSums::mx},
    {"sampling_vy", &TunnelSampler::CellSums::my},       {"sampling_vz", &TunnelSampler::CellSums::mz},
    {"sampling_vx2", &TunnelSampler::CellSums::ex},      {"sampling_vy2", &TunnelSampler::CellSums::ey},
    {"sampling_vz2", &TunnelSampler::CellSums::ez},
};

std::vector<double> component(const std::vector<BodyForce>& forces, double BodyForce::*member) {
    std::vector<double> values;
    values.reserve(forces.size());
    for (const BodyForce& f : forces) values.push_back(f.*member);
    return values;
}

// One force per body, as many as there were bodies at the last step (none before the first).
std::vector<BodyForce> forcesOf(const StateRecord& record, const std::string& key) {
    const std::vector<double> drag = record.array<double>(key + "_drag");
    const std::vector<double> lift = record.array<double>(key + "_lift", drag.size());
    std::vector<BodyForce> forces(drag.size());
    for (std::size_t b = 0; b < forces.size(); ++b) forces[b] = {drag[b], lift[b]};
    return forces;
}

} // namespace

bool TunnelSampler::savedIn(const StateRecord& record) {
    return record.has("sampling_steps");
}

void TunnelSampler::save(StateRecord& r) const {
    r.put("sampling_steps", static_cast<double>(steps_));
    for (const auto& sum : kCellSums) {
        std::vector<double> values(cells_.size());
        for (std::size_t c = 0; c < cells_.size(); ++c) values[c] = cells_[c].*sum.member;
        r.put(sum.key, values);
    }
    r.put("force_window_steps", static_cast<double>(forceSteps_));
    r.put("force_window_drag", sumForceX_);
    r.put("force_window_lift", sumForceY_);
    r.put("force_last_drag", component(last_, &BodyForce::drag));
    r.put("force_last_lift", component(last_, &BodyForce::lift));
    r.put("force_interval_steps", static_cast<double>(intervalSteps_));
    r.put("force_interval_drag", intervalForceX_);
    r.put("force_interval_lift", intervalForceY_);
    r.put("force_previous_interval_drag", component(previousInterval_, &BodyForce::drag));
    r.put("force_previous_interval_lift", component(previousInterval_, &BodyForce::lift));
    if (previousSteps_ == 0 && previousForceSteps_ == 0) return; // a window over the whole run
    // A moving window's older half, under the same names with "_older".
    r.put("sampling_steps_older", static_cast<double>(previousSteps_));
    for (const auto& sum : kCellSums) {
        std::vector<double> values(previous_.size());
        for (std::size_t c = 0; c < previous_.size(); ++c) values[c] = previous_[c].*sum.member;
        r.put(std::string(sum.key) + "_older", values);
    }
    r.put("force_window_steps_older", static_cast<double>(previousForceSteps_));
    r.put("force_window_older_drag", previousForceX_);
    r.put("force_window_older_lift", previousForceY_);
}

void TunnelSampler::restore(const StateRecord& r) {
    TunnelSampler next = *this; // filled first, so a field that does not fit changes nothing
    next.steps_ = r.count("sampling_steps");
    for (const auto& sum : kCellSums) {
        const std::vector<double> values = r.array<double>(sum.key, cells_.size());
        for (std::size_t c = 0; c < cells_.size(); ++c) next.cells_[c].*sum.member = values[c];
    }
    for (std::size_t c = 0; c < cells_.size(); ++c)
        if (!(next.cells_[c].count >= 0))
            throw PresetError("state.sampling_count",
                              "state.sampling_count[" + std::to_string(c) + "] must not be negative");
    next.forceSteps_ = r.count("force_window_steps");
    const std::vector<BodyForce> window = forcesOf(r, "force_window");
    next.sumForceX_ = component(window, &BodyForce::drag);
    next.sumForceY_ = component(window, &BodyForce::lift);
    next.last_ = forcesOf(r, "force_last");
    next.intervalSteps_ = r.count("force_interval_steps");
    const std::vector<BodyForce> interval = forcesOf(r, "force_interval");
    next.intervalForceX_ = component(interval, &BodyForce::drag);
    next.intervalForceY_ = component(interval, &BodyForce::lift);
    next.previousInterval_ = forcesOf(r, "force_previous_interval");
    next.previous_.clear();
    next.previousSteps_ = 0;
    next.previousForceX_.clear();
    next.previousForceY_.clear();
    next.previousForceSteps_ = 0;
    if (r.has("sampling_steps_older")) {
        next.previousSteps_ = r.count("sampling_steps_older");
        next.previous_.assign(cells_.size(), CellSums{});
        for (const auto& sum : kCellSums) {
            const std::vector<double> values =
                r.array<double>(std::string(sum.key) + "_older", cells_.size());
            for (std::size_t c = 0; c < cells_.size(); ++c) next.previous_[c].*sum.member = values[c];
        }
        for (std::size_t c = 0; c < cells_.size(); ++c)
            if (!(next.previous_[c].count >= 0))
                throw PresetError("state.sampling_count_older", "state.sampling_count_older[" +
                                                                    std::to_string(c) +
                                                                    "] must not be negative");
        next.previousForceSteps_ = r.count("force_window_steps_older");
        const std::vector<BodyForce> older = forcesOf(r, "force_window_older");
        next.previousForceX_ = component(older, &BodyForce::drag);
        next.previousForceY_ = component(older, &BodyForce::lift);
    }
    // Between steps every impulse has gone into the sums.
    std::fill(next.impulseX_.begin(), next.impulseX_.end(), 0.0);
    std::fill(next.impulseY_.begin(), next.impulseY_.end(), 0.0);
    *this = std::move(next);
}

} // namespace pl
