// Adding and removing disks between steps: rectangles on a lattice, single points, overlap and cap checks,
// and the disks a body put down on them moves out of the way.
#include "GasModel.h"
#include "common/Philox.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace pl {

namespace {
constexpr double kSpawnSpacing = 1.05; // lattice spacing of a spawned rectangle, in diameters
// A disk under a new body is tried at the body's surface first, then on rings around that place this
// far apart (in the disk's diameters), out to kMaxRings rings (20 diameters, about 5000 places).
constexpr double kRingSpacing = 0.5;
constexpr int kMaxRings = 40;
// Put down this much beyond a body's grown surface, relative, so the disk is outside it in every rounding.
constexpr double kSurfaceClearance = 1e-9;

// Disk indices in square cells one largest diameter wide, over the part of the box where covered disks
// may go: the disks that may touch a place are in its 3 × 3 cells.
class DiskGrid {
public:
    DiskGrid(double left, double bottom, double right, double top, double cell)
        : left_(left), bottom_(bottom), cell_(cell),
          nx_(std::max<long long>(1, static_cast<long long>(std::ceil((right - left) / cell)))),
          ny_(std::max<long long>(1, static_cast<long long>(std::ceil((top - bottom) / cell)))),
          cells_(static_cast<std::size_t>(nx_ * ny_)) {}
    bool covers(double x, double y) const {
        return x >= left_ && y >= bottom_ && x < left_ + nx_ * cell_ && y < bottom_ + ny_ * cell_;
    }
    void insert(std::size_t disk, double x, double y) {
        if (covers(x, y)) cells_[index(column(x), row(y))].push_back(disk);
    }
    template <class Visit> void forNear(double x, double y, Visit visit) const {
        const long long c = column(x), r = row(y);
        for (long long j = std::max(0LL, r - 1); j <= std::min(ny_ - 1, r + 1); ++j)
            for (long long i = std::max(0LL, c - 1); i <= std::min(nx_ - 1, c + 1); ++i)
                for (const std::size_t disk : cells_[index(i, j)]) visit(disk);
    }

private:
    long long column(double x) const {
        return std::clamp(static_cast<long long>(std::floor((x - left_) / cell_)), 0LL, nx_ - 1);
    }
    long long row(double y) const {
        return std::clamp(static_cast<long long>(std::floor((y - bottom_) / cell_)), 0LL, ny_ - 1);
    }
    std::size_t index(long long i, long long j) const { return static_cast<std::size_t>(j * nx_ + i); }

    double left_, bottom_, cell_;
    long long nx_, ny_;
    std::vector<std::vector<std::size_t>> cells_;
};

// The nearest place outside the body for a disk centre of radius r inside it: pushed out along the
// shortest way to the grown surface. Also the outward direction there.
void pushedOut(const Obstacle& o, double r, double& x, double& y, double& nx, double& ny) {
    const double rx = x - o.x, ry = y - o.y;
    nx = 1.0, ny = 0.0;
    if (o.shape == Obstacle::Shape::Disc) {
        const double dist = std::hypot(rx, ry);
        if (dist > 0) nx = rx / dist, ny = ry / dist;
        const double reach = (o.radius + r) * (1 + kSurfaceClearance);
        x = o.x + reach * nx;
        y = o.y + reach * ny;
    } else if (o.halfWidth + r - std::abs(rx) < o.halfHeight + r - std::abs(ry)) {
        nx = rx >= 0 ? 1.0 : -1.0;
        x = o.x + nx * (o.halfWidth + r) * (1 + kSurfaceClearance);
    } else {
        nx = 0.0, ny = ry >= 0 ? 1.0 : -1.0;
        y = o.y + ny * (o.halfHeight + r) * (1 + kSurfaceClearance);
    }
}
} // namespace

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

bool GasModel::moveDisksOutOfBodies() {
    const double dA = params_.a.diameter, dB = params_.b.diameter;
    const auto diameterOf = [&](std::size_t i) { return state_.species[i] == 0 ? dA : dB; };
    const auto coveringBody = [&](std::size_t i) -> const Obstacle* {
        for (const Obstacle& o : obstacles_)
            if (o.contains(state_.x[i], state_.y[i], 0.5 * diameterOf(i))) return &o;
        return nullptr;
    };
    // The covered disks, and the part of the box they may go to: around each body that covers one, as far
    // as the rings reach beyond its surface.
    std::vector<std::size_t> covered;
    const double dMax = params_.maxDiameter(), reach = (kMaxRings * kRingSpacing + 2.0) * dMax;
    double left = rightWall(), bottom = params_.top(), right = params_.left(), top = params_.bottom();
    for (std::size_t i = 0; i < state_.size(); ++i) {
        const Obstacle* o = coveringBody(i);
        if (!o) continue;
        covered.push_back(i);
        const double half =
            reach + (o->shape == Obstacle::Shape::Disc ? o->radius : std::max(o->halfWidth, o->halfHeight));
        left = std::min(left, o->x - half);
        right = std::max(right, o->x + half);
        bottom = std::min(bottom, o->y - half);
        top = std::max(top, o->y + half);
    }
    if (covered.empty()) return false;
    DiskGrid grid(std::max(left, params_.left()), std::max(bottom, params_.bottom()),
                  std::min(right, rightWall()), std::min(top, params_.top()), dMax);
    std::vector<bool> moving(state_.size(), false);
    for (const std::size_t i : covered) moving[i] = true;
    for (std::size_t j = 0; j < state_.size(); ++j)
        if (!moving[j]) grid.insert(j, state_.x[j], state_.y[j]);

    // The deepest overlap a disk of diameter d at (x, y) would have, as a fraction of the contact distance
    // (≤ 0: it touches nothing).
    const auto overlapAt = [&](double x, double y, double d) {
        double worst = -1.0;
        grid.forNear(x, y, [&](std::size_t j) {
            const double dij = 0.5 * (d + diameterOf(j));
            worst = std::max(worst, 1.0 - std::hypot(x - state_.x[j], y - state_.y[j]) / dij);
        });
        return worst;
    };
    std::vector<bool> removed(state_.size(), false);
    long long removedCount = 0;
    for (const std::size_t i : covered) {
        const double d = diameterOf(i), r = 0.5 * d;
        double x0 = state_.x[i], y0 = state_.y[i], nx = 1.0, ny = 0.0;
        pushedOut(*coveringBody(i), r, x0, y0, nx, ny);
        const double outward = std::atan2(ny, nx);
        double bestX = 0, bestY = 0, best = std::numeric_limits<double>::infinity();
        for (int ring = 0; ring <= kMaxRings && best > 0; ++ring) {
            // Around the ring from the outward direction, alternately to either side.
            const int places = ring == 0 ? 1 : static_cast<int>(std::ceil(2 * std::numbers::pi * ring));
            for (int k = 0; k < places && best > 0; ++k) {
                const int side = (k + 1) / 2 * (k % 2 == 1 ? 1 : -1);
                const double angle = outward + 2 * std::numbers::pi * side / places;
                const double x = x0 + ring * kRingSpacing * d * std::cos(angle);
                const double y = y0 + ring * kRingSpacing * d * std::sin(angle);
                if (!insideSpace(x, y, r) || !grid.covers(x, y)) continue;
                const double overlap = overlapAt(x, y, d);
                if (overlap < best) best = overlap, bestX = x, bestY = y;
            }
        }
        if (best <= params_.spawnMaxOverlap) {
            state_.x[i] = bestX;
            state_.y[i] = bestY;
            grid.insert(i, bestX, bestY);
        } else { // no room near the body (a jammed gas): refused, as a spawned disk would be
            removed[i] = true;
            ++removedCount;
        }
    }
    neighbours_.invalidate(); // the moved disks jumped farther than the list's skin
    maxDisplacement2_ = -1.0;
    if (removedCount > 0) {
        state_.retain([&](std::size_t i) { return !removed[i]; });
        populationChanged();
    } else {
        stateEdited();
    }
    return true;
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
