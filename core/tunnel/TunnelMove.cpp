// The move of Bird's method (1994 §11.1): each molecule flies straight for the step; where the flight
// meets a side, a body or the piston, the interaction is applied at the exact time of the hit and the
// rest of the flight continues. Bodies are met in their own frame (they move at the drive's velocity);
// diffuse reflection is Bird §12.4 (flux-weighted normal speed, Maxwellian tangential components).
#include "TunnelModel.h"

#include "common/Parallel.h"
#include "common/StopRequest.h"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {

// Interactions one flight may have in a step; beyond it the molecule waits where it is (a molecule in
// a corner pocket between a body and a side bounces back and forth at most a few times per step).
constexpr int kMaxEvents = 32;
// Particles per chunk of the move: each chunk sums its body impulses in particle order and the chunks
// are added in order, so the forces do not depend on the thread count.
constexpr std::size_t kChunk = 4096;
// A reflected molecule is put this fraction of the body's size outside its surface, so rounding never
// leaves it inside.
constexpr double kSurfaceNudge = 1e-12;
// The cell index of a molecule that left the domain: the sort drops it.
constexpr std::uint32_t kGone = 0xffffffffu;

enum Side { Left = 0, Right = 1, Bottom = 2, Top = 3 };

} // namespace

std::uint32_t TunnelModel::cellOf(double x, double y) const {
    // The same arithmetic as the move's fast path, so a molecule's cell never depends on the path.
    const double cellsPerX = double(params_.cellsX) / params_.boxWidth;
    const double cellsPerY = double(params_.cellsY) / params_.boxHeight;
    const auto i = std::min(static_cast<std::uint32_t>(std::max(x * cellsPerX, 0.0)),
                            static_cast<std::uint32_t>(params_.cellsX - 1));
    const auto j = std::min(static_cast<std::uint32_t>(std::max(y * cellsPerY, 0.0)),
                            static_cast<std::uint32_t>(params_.cellsY - 1));
    return j * static_cast<std::uint32_t>(params_.cellsX) + i;
}

void TunnelModel::pushOutOfBodies(std::size_t i) {
    // A body dragged or placed onto the molecule: to the nearest point of its surface, moving outward
    // in the body's frame. Bodies pushed into each other may hand it on: a few passes settle it.
    constexpr int kPasses = 4;
    for (int pass = 0; pass < kPasses; ++pass) {
        bool moved = false;
        for (const tunnel::BodyFrame& b : frames_) {
            const double rx = state_.x[i] - b.x0, ry = state_.y[i] - b.y0;
            double nx, ny, px, py;
            if (b.disc) {
                const double r2 = rx * rx + ry * ry;
                if (r2 >= b.radius * b.radius) continue;
                const double r = std::sqrt(r2);
                nx = r > 0 ? rx / r : 1.0;
                ny = r > 0 ? ry / r : 0.0;
                const double out = b.radius * (1.0 + kSurfaceNudge);
                px = nx * out;
                py = ny * out;
            } else {
                const double gapX = b.halfWidth - std::abs(rx), gapY = b.halfHeight - std::abs(ry);
                if (gapX <= 0 || gapY <= 0) continue;
                px = rx, py = ry;
                nx = ny = 0;
                if (gapX < gapY) {
                    nx = rx >= 0 ? 1.0 : -1.0;
                    px = nx * b.halfWidth * (1.0 + kSurfaceNudge);
                } else {
                    ny = ry >= 0 ? 1.0 : -1.0;
                    py = ny * b.halfHeight * (1.0 + kSurfaceNudge);
                }
            }
            state_.x[i] = b.x0 + px;
            state_.y[i] = b.y0 + py;
            const double wn = (state_.vx[i] - b.vx) * nx + (state_.vy[i] - b.vy) * ny;
            if (wn < 0) {
                state_.vx[i] -= 2.0 * wn * nx;
                state_.vy[i] -= 2.0 * wn * ny;
            }
            moved = true;
        }
        if (!moved) return;
    }
}

bool TunnelModel::fly(std::size_t i, double tau0, double h, tunnel::CounterRng& rng, double* impulse) {
    const TunnelParams& p = params_;
    const double m = p.mass();
    const double width = p.boxWidth, height = p.boxHeight;
    const double pistonStart = pistonX_ - pistonVelocity_ * h; // the piston at τ = 0
    const TunnelBoundary sides[4] = {p.left, p.right, p.bottom, p.top};
    double x = state_.x[i], y = state_.y[i];
    double vx = state_.vx[i], vy = state_.vy[i], vz = state_.vz[i];
    double tau = tau0;
    bool inside = true;
    for (int event = 0; event < kMaxEvents; ++event) {
        const double left = h - tau;
        double first = left;
        int what = -1; // a side (0..3), 4 the piston, 5 + b body b
        double hitNx = 0, hitNy = 0;
        if (p.pistonOn) {
            // x + v_x t = X(τ) + u t: the piston is a wall moving at u.
            const double gap = x - (pistonStart + pistonVelocity_ * tau);
            if (vx < pistonVelocity_) {
                const double t = std::max(gap, 0.0) / (pistonVelocity_ - vx);
                if (t < first) first = t, what = 4;
            }
        } else if (vx < 0) {
            const double t = std::max(x, 0.0) / -vx;
            if (t < first) first = t, what = Left;
        }
        if (vx > 0) {
            const double t = std::max(width - x, 0.0) / vx;
            if (t < first) first = t, what = Right;
        }
        if (vy < 0) {
            const double t = std::max(y, 0.0) / -vy;
            if (t < first) first = t, what = Bottom;
        }
        if (vy > 0) {
            const double t = std::max(height - y, 0.0) / vy;
            if (t < first) first = t, what = Top;
        }
        for (std::size_t b = 0; b < frames_.size(); ++b) {
            const tunnel::BodyFrame& f = frames_[b];
            const double rx = x - (f.x0 + f.vx * tau), ry = y - (f.y0 + f.vy * tau);
            const double wx = vx - f.vx, wy = vy - f.vy;
            double nx = 0, ny = 0;
            double t;
            if (f.disc) {
                t = tunnel::discHitTime(rx, ry, wx, wy, f.radius);
            } else {
                t = tunnel::boxHitTime(rx, ry, wx, wy, f.halfWidth, f.halfHeight, nx, ny);
            }
            if (t < first) {
                first = t, what = 5 + static_cast<int>(b);
                if (f.disc) {
                    const double hx = rx + wx * t, hy = ry + wy * t, r = std::hypot(hx, hy);
                    hitNx = r > 0 ? hx / r : 1.0, hitNy = r > 0 ? hy / r : 0.0;
                } else {
                    hitNx = nx, hitNy = ny;
                }
            }
        }
        x += vx * first;
        y += vy * first;
        tau += first;
        if (what < 0) break; // the flight ends inside the domain
        if (what == 4) {
            x = pistonStart + pistonVelocity_ * tau;
            vx = 2.0 * pistonVelocity_ - vx; // a mirror in the piston's frame
            continue;
        }
        if (what < 4) {
            const int side = what;
            const TunnelBoundary kind = sides[side];
            const bool alongX = side == Left || side == Right;
            // Exactly on the side it reached.
            if (side == Left) x = 0.0;
            if (side == Right) x = width;
            if (side == Bottom) y = 0.0;
            if (side == Top) y = height;
            if (kind == TunnelBoundary::Inflow || kind == TunnelBoundary::Outflow) {
                inside = false;
                break;
            }
            if (kind == TunnelBoundary::Periodic) {
                if (side == Left) x = width;
                if (side == Right) x = 0.0;
                if (side == Bottom) y = height;
                if (side == Top) y = 0.0;
                continue;
            }
            if (kind == TunnelBoundary::Specular) {
                (alongX ? vx : vy) = -(alongX ? vx : vy);
                continue;
            }
            // Diffuse: full accommodation to the wall (Bird 1994 §12.4), the wall moving along itself.
            const double sigma = std::sqrt(kBoltzmann * p.wallTemperature / m);
            const double inward = side == Left || side == Bottom ? 1.0 : -1.0;
            const double normal = inward * tunnel::fluxWeightedNormalSpeed(sigma, rng.uniform());
            if (alongX) {
                vx = normal;
                vy = sigma * rng.normal();
            } else {
                vy = normal;
                vx = sigma * rng.normal() + (side == Bottom ? p.bottomWallSpeed : p.topWallSpeed);
            }
            vz = sigma * rng.normal();
            continue;
        }
        // A body: reflect in its frame, the gas's momentum change to the body's sums.
        const std::size_t b = static_cast<std::size_t>(what - 5);
        const tunnel::BodyFrame& f = frames_[b];
        const double cx = f.x0 + f.vx * tau, cy = f.y0 + f.vy * tau;
        const double inX = vx, inY = vy;
        double wx = vx - f.vx, wy = vy - f.vy;
        if (p.surface == TunnelSurface::Specular) {
            const double wn = wx * hitNx + wy * hitNy;
            wx -= 2.0 * wn * hitNx;
            wy -= 2.0 * wn * hitNy;
        } else {
            const double sigma = std::sqrt(kBoltzmann * p.bodyTemperature / m);
            const double normal = tunnel::fluxWeightedNormalSpeed(sigma, rng.uniform());
            const double tangential = sigma * rng.normal();
            wx = normal * hitNx - tangential * hitNy;
            wy = normal * hitNy + tangential * hitNx;
            vz = sigma * rng.normal();
        }
        vx = wx + f.vx;
        vy = wy + f.vy;
        impulse[2 * b] += m * (vx - inX);
        impulse[2 * b + 1] += m * (vy - inY);
        // On the surface, a hair outside.
        if (f.disc) {
            const double out = f.radius * (1.0 + kSurfaceNudge);
            x = cx + hitNx * out;
            y = cy + hitNy * out;
        } else {
            if (hitNx != 0) x = cx + hitNx * f.halfWidth * (1.0 + kSurfaceNudge);
            if (hitNy != 0) y = cy + hitNy * f.halfHeight * (1.0 + kSurfaceNudge);
        }
    }
    state_.x[i] = std::clamp(x, 0.0, width);
    state_.y[i] = std::clamp(y, 0.0, height);
    state_.vx[i] = vx;
    state_.vy[i] = vy;
    state_.vz[i] = vz;
    state_.cell[i] = inside ? cellOf(state_.x[i], state_.y[i]) : kGone;
    return inside;
}

void TunnelModel::moveParticles(double h) {
    frames_.clear();
    for (const Obstacle& o : obstacles_)
        frames_.push_back(tunnel::BodyFrame::of(o.shape == Obstacle::Shape::Disc, o.x, o.y, o.vx, o.vy,
                                                o.radius, o.halfWidth, o.halfHeight, h));
    const std::size_t n = state_.size();
    const std::size_t bodies = frames_.size();
    const std::size_t chunks = (n + kChunk - 1) / kChunk;
    impulseChunks_.assign(chunks * 2 * bodies, 0.0);
    const std::uint64_t base = tunnel::stepBase(stepCount());
    const std::uint64_t seed = seed_;
    const bool parallel = static_cast<long long>(n) >= kParallelMinParticles;
    // The fast path: a flight that ends strictly inside the domain (right of the piston's end position,
    // which then held at every moment of the step: both move linearly) and whose bounding box misses
    // every body's swept rectangle meets nothing; it only moves and finds its cell.
    const double left = params_.pistonOn ? pistonX_ : 0.0, right = params_.boxWidth;
    const double top = params_.boxHeight;
    const double cellsPerX = double(params_.cellsX) / params_.boxWidth;
    const double cellsPerY = double(params_.cellsY) / params_.boxHeight;
    const auto lastI = static_cast<std::uint32_t>(params_.cellsX - 1);
    const auto lastJ = static_cast<std::uint32_t>(params_.cellsY - 1);
    const auto nx = static_cast<std::uint32_t>(params_.cellsX);
    double* const px = state_.x.data();
    double* const py = state_.y.data();
    const double* const pvx = state_.vx.data();
    const double* const pvy = state_.vy.data();
    std::uint32_t* const pcell = state_.cell.data();
    const tunnel::BodyFrame* const frames = frames_.data();
    const bool keeping = stepStart_.keeping;
    if (keeping) {
        for (std::vector<double>* column :
             {&stepStart_.molecules.x, &stepStart_.molecules.y, &stepStart_.molecules.vx,
              &stepStart_.molecules.vy, &stepStart_.molecules.vz})
            column->resize(n);
        stepStart_.molecules.cell.resize(n);
        stepStart_.chunkKept.assign(chunks, 0);
        stepStart_.chunkSize = kChunk;
    }
#pragma omp parallel for schedule(static) if (parallel)
    for (std::size_t c = 0; c < chunks; ++c) {
        if (abandoningStep()) continue; // the step is undone: skip the rest (common/StopRequest.h)
        double* impulse = bodies > 0 ? impulseChunks_.data() + c * 2 * bodies : nullptr;
        const std::size_t end = std::min(n, (c + 1) * kChunk);
        if (keeping) keepChunk(c, c * kChunk, end);
        for (std::size_t i = c * kChunk; i < end; ++i) {
            const double x0 = px[i], y0 = py[i];
            const double x1 = x0 + pvx[i] * h, y1 = y0 + pvy[i] * h;
            bool free = x1 > left && x1 < right && y1 > 0.0 && y1 < top;
            for (std::size_t b = 0; b < bodies && free; ++b) free = frames[b].sweepMisses(x0, y0, x1, y1);
            if (free) {
                px[i] = x1;
                py[i] = y1;
                const auto ci = std::min(static_cast<std::uint32_t>(x1 * cellsPerX), lastI);
                const auto cj = std::min(static_cast<std::uint32_t>(y1 * cellsPerY), lastJ);
                pcell[i] = cj * nx + ci;
                continue;
            }
            if (bodies > 0) pushOutOfBodies(i);
            tunnel::CounterRng rng(seed, RngPurpose::TunnelSurface, static_cast<std::uint32_t>(i), base);
            fly(i, 0.0, h, rng, impulse);
        }
    }
    if (keeping && !abandoningStep()) stepStart_.moved = true;
    for (std::size_t c = 0; c < chunks; ++c)
        for (std::size_t b = 0; b < bodies; ++b) {
            const double* sum = impulseChunks_.data() + (c * bodies + b) * 2;
            if (sum[0] != 0.0 || sum[1] != 0.0) sampler_.addSurfaceImpulse(b, sum[0], sum[1]);
        }
}

} // namespace pl
