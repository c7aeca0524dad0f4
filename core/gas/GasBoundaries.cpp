// Walls, piston and obstacles: mirror reflection of disk centres, thermal walls, wall impulses.
#include "GasBoundaries.h"
#include "GasDrift.h"

#include "GasModel.h"
#include "common/Philox.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

namespace pl {

namespace {

// Velocity of a disk leaving a thermal wall: the normal component follows the flux-weighted
// distribution p(v_n) ∝ v_n exp(−m v_n² / 2kT) (a Rayleigh variate), the tangential one is Gaussian.
struct WallVelocity {
    double normal, tangential;
};

WallVelocity thermalWallVelocity(double kT, double mass, const Philox4x32& words) {
    const double sigma = std::sqrt(kT / mass);
    const double normal = sigma * std::sqrt(-2.0 * std::log(unitOpen(words[0], words[1])));
    const double gaussian = std::sqrt(-2.0 * std::log(unitOpen32(words[2]))) *
                            std::cos(2.0 * std::numbers::pi * unitOpen32(words[3]));
    return {normal, sigma * gaussian};
}

// Where the straight path p0 → p0 + Δ enters an obstacle grown by radius: path fraction s ∈ [0, 1] and
// the outward normal there. False when p0 is inside or the path misses.
bool pathEntry(const Obstacle& o, double radius, double x0, double y0, double dx, double dy, double& s,
               double& nx, double& ny) {
    if (o.shape == Obstacle::Shape::Disc) {
        const double grown = o.radius + radius;
        const double rx = x0 - o.x, ry = y0 - o.y;
        const double a = dx * dx + dy * dy, b = 2.0 * (dx * rx + dy * ry),
                     c = rx * rx + ry * ry - grown * grown;
        const double discriminant = b * b - 4.0 * a * c;
        if (a == 0.0 || c < 0.0 || discriminant < 0.0) return false;
        s = (-b - std::sqrt(discriminant)) / (2.0 * a);
        nx = (rx + s * dx) / grown;
        ny = (ry + s * dy) / grown;
    } else {
        // Slab method: the entry is the latest of the per-axis entries into the grown rectangle.
        const double halfW = o.halfWidth + radius, halfH = o.halfHeight + radius;
        double sx = -1.0, sy = -1.0;
        if (x0 < o.x - halfW && dx > 0) sx = (o.x - halfW - x0) / dx;
        if (x0 > o.x + halfW && dx < 0) sx = (o.x + halfW - x0) / dx;
        if (y0 < o.y - halfH && dy > 0) sy = (o.y - halfH - y0) / dy;
        if (y0 > o.y + halfH && dy < 0) sy = (o.y + halfH - y0) / dy;
        if (sx < 0 && sy < 0) return false;
        s = std::max(sx, sy);
        nx = s == sx ? (dx > 0 ? -1.0 : 1.0) : 0.0;
        ny = s == sx ? 0.0 : (dy > 0 ? -1.0 : 1.0);
    }
    return s >= 0.0 && s <= 1.0;
}

// Reflects the velocity relative to the obstacle's own (a moving obstacle imparts its motion) when the
// disk approaches the surface in the drift's direction of time.
void reflectOffObstacle(const Obstacle& o, double nx, double ny, double timeSign, double& vx, double& vy) {
    const double wn = (vx - o.vx) * nx + (vy - o.vy) * ny;
    if (wn * timeSign < 0) {
        vx -= 2.0 * wn * nx;
        vy -= 2.0 * wn * ny;
    }
}

// A disk centre that ended a drift of length h inside an obstacle: reflect it where its path entered
// and let it travel the rest of the drift with the new velocity. Reflecting at the true entry point
// (rather than mirroring the end point) retraces exactly under −h. A disk that was already inside,
// because the obstacle was dragged onto it, is pushed out the shortest way.
void collideObstacle(const Obstacle& o, double radius, double h, double& x, double& y, double& vx,
                     double& vy) {
    if (!o.contains(x, y, radius)) return;
    const double timeSign = h >= 0 ? 1.0 : -1.0;
    const double dx = h * vx, dy = h * vy;
    double s = 0, nx = 0, ny = 0;
    if (pathEntry(o, radius, x - dx, y - dy, dx, dy, s, nx, ny)) {
        const double hitX = x - dx + s * dx, hitY = y - dy + s * dy;
        reflectOffObstacle(o, nx, ny, timeSign, vx, vy);
        x = hitX + (1.0 - s) * h * vx;
        y = hitY + (1.0 - s) * h * vy;
        return;
    }
    double depth = 0;
    const double rx = x - o.x, ry = y - o.y;
    if (o.shape == Obstacle::Shape::Disc) {
        const double dist = std::hypot(rx, ry);
        nx = dist > 0 ? rx / dist : 1.0;
        ny = dist > 0 ? ry / dist : 0.0;
        depth = o.radius + radius - dist;
    } else {
        const double penX = o.halfWidth + radius - std::abs(rx), penY = o.halfHeight + radius - std::abs(ry);
        if (penX < penY)
            nx = rx >= 0 ? 1.0 : -1.0, depth = penX;
        else
            ny = ry >= 0 ? 1.0 : -1.0, depth = penY;
    }
    x += 2.0 * depth * nx;
    y += 2.0 * depth * ny;
    reflectOffObstacle(o, nx, ny, 1.0, vx, vy);
}

} // namespace

namespace gas {

bool Boundaries::reflectOffWalls(double& x, double& y, double& vx, double& vy, int species, std::uint32_t id,
                                 double& impulse) const {
    const double m = mass[species];
    const double vxIn = vx, vyIn = vy;
    const double hitLeft = reflectPlane(x, vx, left, -1.0, 0.0, timeSign);
    const double hitRight = reflectPlane(x, vx, right, 1.0, pistonVelocity, timeSign);
    const double hitBottom = reflectPlane(y, vy, bottom, -1.0, 0.0, timeSign);
    const double hitTop = reflectPlane(y, vy, top, 1.0, 0.0, timeSign);
    if (thermal && (hitLeft != 0 || (thermalRight && hitRight != 0) || hitBottom != 0 || hitTop != 0)) {
        const auto v =
            thermalWallVelocity(wallKT, m, randomWords(seed, RngPurpose::ThermalWall, id, drawIndex));
        if (hitLeft != 0 || hitRight != 0) {
            vx = (hitLeft != 0 ? 1.0 : -1.0) * v.normal;
            vy = v.tangential;
        } else {
            vy = (hitBottom != 0 ? 1.0 : -1.0) * v.normal;
            vx = v.tangential;
        }
    }
    // Normal momentum handed to the walls: m |Δv_n| for every wall crossed, signed by the time direction.
    double given = 0.0;
    if (hitLeft != 0 || hitRight != 0) given += std::abs(vx - vxIn);
    if (hitBottom != 0 || hitTop != 0) given += std::abs(vy - vyIn);
    impulse += timeSign * m * given;
    // Still outside after one mirror: the disk moved farther than the box in one step (or is NaN).
    const bool ok = x >= left && x <= right && y >= bottom && y <= top;
    if (!ok) {
        x = std::isfinite(x) ? std::clamp(x, left, right) : 0.0;
        y = std::isfinite(y) ? std::clamp(y, bottom, top) : 0.0;
    }
    return ok;
}

void Boundaries::collideWithObstacles(double& x, double& y, double& vx, double& vy, int species) const {
    for (const auto& o : *obstacles) collideObstacle(o, radius[species], h, x, y, vx, vy);
    // An obstacle touching a wall may push a disk against it: keep the centre in the box.
    x = std::clamp(x, left, right);
    y = std::clamp(y, bottom, top);
}

namespace {

// Two doubles per operation (GCC/Clang vector extensions; SSE2 on the x86-64 baseline, which is also
// the width of this CPU's vector units). Element-wise IEEE arithmetic, so each lane equals the scalar.
using Double2 = double __attribute__((vector_size(16)));
using Mask2 = std::int64_t __attribute__((vector_size(16)));

Double2 load2(const double* p) {
    Double2 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

void store2(double* p, Double2 v) {
    std::memcpy(p, &v, sizeof v);
}

// The larger of a and b per lane, a where b is not greater (so NaN never wins, as with std::max(a, b)).
Double2 max2(Double2 a, Double2 b) {
    const Mask2 bWins = b > a;
    return reinterpret_cast<Double2>((reinterpret_cast<Mask2>(b) & bWins) |
                                     (reinterpret_cast<Mask2>(a) & ~bWins));
}

// Disks per sweep: ten arrays of this many doubles stay in L1 between the sweeps.
constexpr std::size_t kDriftChunk = 64;

} // namespace

void driftBlock(const Boundaries& wallsIn, const DriftStep& stepIn, const DriftArrays& arrays,
                ParticleRange range, bool& escaped, double& worst) {
    // Own copies: the caller's stack lines are written by its thread (false sharing, see driftStage).
    const Boundaries walls = wallsIn;
    const DriftStep step = stepIn;
    const DriftArrays a = arrays;
    const double kickBefore = step.kickBefore, h = step.h, kickAfter = step.kickAfter;
    bool anyEscaped = false;
    double largest = worst;
    if (!walls.obstacles->empty()) {
        // Every disk may meet an obstacle: one disk at a time.
        for (std::size_t i = range.begin; i < range.end; ++i) {
            double vx = a.vx[i] + kickBefore * a.ax[i];
            double vy = a.vy[i] + kickBefore * a.ay[i];
            double x = a.x[i] + h * vx;
            double y = a.y[i] + h * vy;
            double impulse = 0.0;
            if (!walls.apply(x, y, vx, vy, a.species[i], a.id[i], impulse)) anyEscaped = true;
            if (impulse != 0.0) a.wallImpulse[i] += impulse;
            a.x[i] = x;
            a.y[i] = y;
            a.vx[i] = vx + kickAfter * a.ax[i];
            a.vy[i] = vy + kickAfter * a.ay[i];
            if (step.track) {
                const double dx = x - a.builtX[i], dy = y - a.builtY[i];
                largest = std::max(largest, dx * dx + dy * dy);
            }
        }
    } else {
        // Walls only: three sweeps per chunk, the first and last in SIMD. Sweep 1 kicks and drifts and
        // notes whether any disk left the box; sweep 2 (rare) mirrors those disks exactly as apply does;
        // sweep 3 adds the second kick and the displacement. Each disk sees the same operations in the
        // same order as in the one-disk loop above.
        const double left = walls.left, right = walls.right, bottom = walls.bottom, top = walls.top;
        Double2 largest2 = {largest, largest};
        for (std::size_t first = range.begin; first < range.end; first += kDriftChunk) {
            const std::size_t last = std::min(first + kDriftChunk, range.end);
            std::size_t i = first;
            Mask2 outside2 = {0, 0};
            for (; i + 2 <= last; i += 2) {
                const Double2 vx = load2(a.vx + i) + kickBefore * load2(a.ax + i);
                const Double2 vy = load2(a.vy + i) + kickBefore * load2(a.ay + i);
                const Double2 x = load2(a.x + i) + h * vx;
                const Double2 y = load2(a.y + i) + h * vy;
                store2(a.vx + i, vx);
                store2(a.vy + i, vy);
                store2(a.x + i, x);
                store2(a.y + i, y);
                outside2 |= ~((x > left) & (x < right) & (y > bottom) & (y < top)); // NaN counts as outside
            }
            bool outside = (outside2[0] | outside2[1]) != 0;
            for (; i < last; ++i) {
                a.vx[i] += kickBefore * a.ax[i];
                a.vy[i] += kickBefore * a.ay[i];
                a.x[i] += h * a.vx[i];
                a.y[i] += h * a.vy[i];
                outside = outside || !(a.x[i] > left && a.x[i] < right && a.y[i] > bottom && a.y[i] < top);
            }
            if (outside) {
                for (i = first; i < last; ++i) {
                    double impulse = 0.0;
                    if (!walls.apply(a.x[i], a.y[i], a.vx[i], a.vy[i], a.species[i], a.id[i], impulse))
                        anyEscaped = true;
                    if (impulse != 0.0) a.wallImpulse[i] += impulse;
                }
            }
            for (i = first; i + 2 <= last; i += 2) {
                store2(a.vx + i, load2(a.vx + i) + kickAfter * load2(a.ax + i));
                store2(a.vy + i, load2(a.vy + i) + kickAfter * load2(a.ay + i));
                if (step.track) {
                    const Double2 dx = load2(a.x + i) - load2(a.builtX + i);
                    const Double2 dy = load2(a.y + i) - load2(a.builtY + i);
                    largest2 = max2(largest2, dx * dx + dy * dy);
                }
            }
            for (; i < last; ++i) {
                a.vx[i] += kickAfter * a.ax[i];
                a.vy[i] += kickAfter * a.ay[i];
                if (step.track) {
                    const double dx = a.x[i] - a.builtX[i], dy = a.y[i] - a.builtY[i];
                    largest = std::max(largest, dx * dx + dy * dy);
                }
            }
        }
        largest = std::max({largest, largest2[0], largest2[1]});
    }
    escaped = escaped || anyEscaped;
    worst = largest;
}

} // namespace gas

gas::Boundaries GasModel::boundaries(double h) const {
    gas::Boundaries b;
    b.left = params_.left();
    b.right = rightWall();
    b.bottom = params_.bottom();
    b.top = params_.top();
    b.pistonVelocity = params_.pistonEnabled ? pistonVelocity_ : 0.0;
    b.h = h;
    b.timeSign = h >= 0 ? 1.0 : -1.0;
    b.thermal = params_.wallMode == GasWallMode::Thermal;
    b.thermalRight = b.thermal && !params_.pistonEnabled;
    b.wallKT = params_.wallKT;
    b.mass[0] = params_.a.mass;
    b.mass[1] = params_.b.mass;
    b.radius[0] = 0.5 * params_.a.diameter;
    b.radius[1] = 0.5 * params_.b.diameter;
    b.seed = seed_;
    b.drawIndex = static_cast<std::uint64_t>(stepCount()) * 8 + driftIndex_;
    b.obstacles = &obstacles_;
    return b;
}

} // namespace pl
