// Adding and removing disks between steps: rectangles on a lattice, single points, overlap and cap checks.
#include "GasModel.h"
#include "common/Philox.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace pl {

namespace {
constexpr double kSpawnSpacing = 1.05; // lattice spacing of a spawned rectangle, in diameters
}

std::string SpawnResult::message() const {
    std::ostringstream out;
    out << "added " << added << (added == 1 ? " disk" : " disks");
    if (refusedCap > 0)
        out << "; " << refusedCap
            << " refused: the particle cap is reached (Parameters → Limits → Particle cap)";
    if (refusedOverlap > 0) out << "; " << refusedOverlap << " refused: they would overlap other disks";
    if (refusedOutside > 0)
        out << "; " << refusedOutside << " refused: outside the box or inside an obstacle";
    return out.str();
}

bool GasModel::overlapsTooMuch(double x, double y, double diameter) const {
    const double limit = params_.spawnMaxOverlap;
    const double dA = params_.a.diameter, dB = params_.b.diameter;
    for (std::size_t j = 0; j < state_.size(); ++j) {
        const double dij = 0.5 * (diameter + (state_.species[j] == 0 ? dA : dB));
        const double dx = x - state_.x[j], dy = y - state_.y[j];
        const double minDistance = (1.0 - limit) * dij;
        if (dx * dx + dy * dy < minDistance * minDistance) return true;
    }
    return false;
}

void GasModel::populationChanged() {
    params_.a.count = std::count(state_.species.begin(), state_.species.end(), 0);
    params_.b.count = static_cast<long long>(state_.size()) - params_.a.count;
    neighbours_.invalidate();
    forcesValid_ = false;
    stateEdited();
    ensureForces(); // also resets the previous positions: a spawned disk begins no contact
    rebaseEnergy();
}

SpawnResult GasModel::spawnRectangle(double x0, double y0, double x1, double y1, int species, double kT) {
    if (x1 < x0) std::swap(x0, x1);
    if (y1 < y0) std::swap(y0, y1);
    pullState();
    const auto& sp = params_.species(species);
    const double spacing = kSpawnSpacing * sp.diameter;
    const auto nx = std::max<long long>(1, static_cast<long long>(std::floor((x1 - x0) / spacing)) + 1);
    const auto ny = std::max<long long>(1, static_cast<long long>(std::floor((y1 - y0) / spacing)) + 1);
    SpawnResult result;
    const std::size_t before = state_.size();
    const double sigma = std::sqrt(std::max(kT, 0.0) / sp.mass);
    for (long long r = 0; r < ny; ++r) {
        for (long long c = 0; c < nx; ++c) {
            const double x = x0 + c * spacing, y = y0 + r * spacing;
            if (static_cast<long long>(state_.size()) >= params_.maxParticles) {
                ++result.refusedCap;
                continue;
            }
            if (!insideSpace(x, y, 0.5 * sp.diameter)) {
                ++result.refusedOutside;
                continue;
            }
            if (overlapsTooMuch(x, y, sp.diameter)) {
                ++result.refusedOverlap;
                continue;
            }
            const std::uint32_t id = nextId();
            const auto [gx, gy] = gaussianPair(randomWords(seed_, RngPurpose::Spawn, id, spawnEvents_));
            state_.append(x, y, sigma * gx, sigma * gy, static_cast<std::uint8_t>(species), id);
            ++result.added;
        }
    }
    ++spawnEvents_;
    if (state_.size() != before) populationChanged();
    return result;
}

SpawnResult GasModel::spawnAt(double x, double y, int species, double kT) {
    return spawnRectangle(x, y, x, y, species, kT);
}

void GasModel::placeParticles(const std::vector<GasParticle>& particles) {
    if (static_cast<long long>(particles.size()) > params_.maxParticles)
        throw std::invalid_argument(std::to_string(particles.size()) + " particles exceed max_particles = " +
                                    std::to_string(params_.maxParticles));
    state_ = GasState{};
    nextId_ = 0;
    for (const auto& p : particles)
        state_.append(p.x, p.y, p.vx, p.vy, static_cast<std::uint8_t>(p.species == 0 ? 0 : 1), nextId());
    restartClock();
    lastSortStep_ = -1;
    lastSampleTime_ = 0.0;
    lastCollisionRate_ = 0.0;
    escaped_ = false;
    wallWindow_.clear();
    referenceEnergy_ = 0.0;
    populationChanged();
}

long long GasModel::removeInRectangle(double x0, double y0, double x1, double y1) {
    if (x1 < x0) std::swap(x0, x1);
    if (y1 < y0) std::swap(y0, y1);
    pullState();
    const auto removed = static_cast<long long>(state_.retain([&](std::size_t i) {
        return !(state_.x[i] >= x0 && state_.x[i] <= x1 && state_.y[i] >= y0 && state_.y[i] <= y1);
    }));
    if (removed > 0) populationChanged();
    return removed;
}

long long GasModel::removeNear(double x, double y, double radius) {
    pullState();
    const double r2 = radius * radius;
    const auto removed = static_cast<long long>(state_.retain([&](std::size_t i) {
        const double dx = state_.x[i] - x, dy = state_.y[i] - y;
        return dx * dx + dy * dy > r2;
    }));
    if (removed > 0) populationChanged();
    return removed;
}

} // namespace pl
