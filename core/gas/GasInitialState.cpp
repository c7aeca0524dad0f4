// Initial placement and velocities, drawn from the counter-based generator (seed, purpose, particle id).
#include "GasModel.h"
#include "common/Philox.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pl {

namespace {
constexpr int kPlacementTries = 64;          // random draws per disk before giving up on avoiding obstacles
constexpr double kWallMarginDiameters = 1.5; // the write-up keeps centres 1.5 d from the walls
} // namespace

void GasModel::buildInitialState() {
    state_ = GasState{};
    nextId_ = 0;
    const long long total = params_.totalCount();
    state_.resize(static_cast<std::size_t>(total));
    for (long long i = 0; i < total; ++i) {
        state_.species[i] = i < params_.a.count ? 0 : 1;
        state_.id[i] = nextId();
    }
    if (params_.initPlacement == GasInitPlacement::Lattice) {
        placeLattice();
    } else {
        placeRandom(0, params_.a.count, 0);
        placeRandom(params_.a.count, params_.b.count, 1);
    }
    assignVelocities();
}

bool GasModel::insideSpace(double x, double y, double radius) const {
    if (x < params_.left() || x > rightWall() || y < params_.bottom() || y > params_.top()) return false;
    for (const auto& o : obstacles_)
        if (o.contains(x, y, radius)) return false;
    return true;
}

// Uniform positions as in the write-up (overlaps allowed: soft disks push apart); re-drawn inside obstacles.
void GasModel::placeRandom(long long first, long long count, int species) {
    const auto& sp = params_.species(species);
    const double margin = std::min(kWallMarginDiameters * sp.diameter,
                                   0.25 * std::min(params_.right() - params_.left(), params_.boxHeight));
    const double x0 = params_.left() + margin, width = params_.right() - params_.left() - 2 * margin;
    const double y0 = params_.bottom() + margin, height = params_.boxHeight - 2 * margin;
    for (long long i = first; i < first + count; ++i) {
        bool placed = false;
        for (int attempt = 0; attempt < kPlacementTries && !placed; ++attempt) {
            const auto [u, v] =
                uniformPair(randomWords(seed_, RngPurpose::InitialPosition, state_.id[i], attempt));
            state_.x[i] = x0 + u * width;
            state_.y[i] = y0 + v * height;
            placed = insideSpace(state_.x[i], state_.y[i], 0.5 * sp.diameter);
        }
        if (!placed)
            throw PresetError("obstacles",
                              "no room for the disks outside the obstacles: make the obstacles smaller");
    }
}

// A square lattice at the largest spacing that holds every disk, free sites shuffled among species.
void GasModel::placeLattice() {
    const double width = params_.right() - params_.left(), height = params_.boxHeight;
    const long long total = params_.totalCount();
    if (total == 0) return;
    const double dmax = params_.maxDiameter();
    std::vector<std::pair<double, double>> sites;
    // Start from the spacing that tiles the area with `total` sites and shrink until enough are free.
    for (double spacing = std::sqrt(width * height / static_cast<double>(total)); spacing >= 0.5 * dmax;
         spacing *= 0.97) {
        sites.clear();
        const auto nx = static_cast<long long>(std::floor(width / spacing));
        const auto ny = static_cast<long long>(std::floor(height / spacing));
        const double ox = params_.left() + 0.5 * (width - (nx - 1) * spacing);
        const double oy = params_.bottom() + 0.5 * (height - (ny - 1) * spacing);
        for (long long r = 0; r < ny; ++r)
            for (long long c = 0; c < nx; ++c) {
                const double x = ox + c * spacing, y = oy + r * spacing;
                if (insideSpace(x, y, 0.5 * dmax)) sites.emplace_back(x, y);
            }
        if (static_cast<long long>(sites.size()) >= total) break;
    }
    if (static_cast<long long>(sites.size()) < total)
        throw PresetError("params.count_a", "the lattice does not fit " + std::to_string(total) +
                                                " disks in the free space of the box");
    // Fisher–Yates with counter-based draws: reproducible, and mixes species over the lattice.
    for (std::size_t k = sites.size() - 1; k > 0; --k) {
        const auto words = randomWords(seed_, RngPurpose::Shuffle, 0, k);
        const std::size_t j =
            static_cast<std::size_t>(unitOpen(words[0], words[1]) * static_cast<double>(k + 1));
        std::swap(sites[k], sites[std::min(j, k)]);
    }
    for (long long i = 0; i < total; ++i)
        std::tie(state_.x[i], state_.y[i]) = sites[static_cast<std::size_t>(i)];
}

void GasModel::assignVelocities() {
    const bool fixed = params_.initVelocity == GasInitVelocity::FixedSpeed;
    for (std::size_t i = 0; i < state_.size(); ++i) {
        const auto words = randomWords(seed_, RngPurpose::InitialVelocity, state_.id[i], 0);
        if (fixed) {
            // The write-up: speed V0 in a uniformly random direction.
            const double theta = 2.0 * std::numbers::pi * unitOpen(words[0], words[1]);
            state_.vx[i] = params_.initSpeed * std::cos(theta);
            state_.vy[i] = params_.initSpeed * std::sin(theta);
        } else {
            const double sigma = std::sqrt(params_.initKT / params_.species(state_.species[i]).mass);
            const auto [gx, gy] = gaussianPair(words);
            state_.vx[i] = sigma * gx;
            state_.vy[i] = sigma * gy;
        }
    }
}

} // namespace pl
