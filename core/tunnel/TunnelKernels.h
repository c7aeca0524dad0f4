// Stateless pieces of the wind tunnel's step: a counter-based random stream, Maxwellian and
// flux-weighted velocity draws, the half-range number flux, and the exact ray–disc and ray–box
// intersections of a straight flight. Kept free of the model so the GL backend can mirror them.
#pragma once

#include "common/Philox.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace pl::tunnel {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

// Uniform and normal deviates from Philox words keyed by (seed, purpose, subject, base + block): the same
// numbers for the same subject and step whatever thread draws them.
class CounterRng {
public:
    CounterRng(std::uint64_t seed, RngPurpose purpose, std::uint32_t subject, std::uint64_t base)
        : seed_(seed), purpose_(purpose), subject_(subject), sequence_(base) {}
    // A uniform deviate in (0, 1).
    double uniform() {
        if (left_ == 0) refill();
        return buffer_[--left_];
    }
    // A standard normal deviate (Box–Muller, both halves used).
    double normal() {
        if (hasSpare_) {
            hasSpare_ = false;
            return spare_;
        }
        const double r = std::sqrt(-2.0 * std::log(uniform()));
        const double phi = 2.0 * std::numbers::pi * uniform();
        spare_ = r * std::sin(phi);
        hasSpare_ = true;
        return r * std::cos(phi);
    }

private:
    void refill() {
        const Philox4x32 w = randomWords(seed_, purpose_, subject_, sequence_++);
        buffer_[0] = unitOpen(w[0], w[1]);
        buffer_[1] = unitOpen(w[2], w[3]);
        left_ = 2;
    }
    std::uint64_t seed_;
    RngPurpose purpose_;
    std::uint32_t subject_;
    std::uint64_t sequence_;
    double buffer_[2] = {0, 0};
    int left_ = 0;
    double spare_ = 0;
    bool hasSpare_ = false;
};

// The first sequence number of a step's draws: 2³² blocks per subject and step.
inline std::uint64_t stepBase(std::int64_t step) {
    return static_cast<std::uint64_t>(step) << 32;
}

// Speed of a molecule leaving a diffuse wall along its normal: the flux-weighted half-range Maxwellian
// v_n f(v_n) ∝ v_n exp(−v_n²/2σ²), σ² = kT/m, inverted exactly: v_n = σ √(−2 ln u) (Bird 1994 §12.4).
inline double fluxWeightedNormalSpeed(double sigma, double u) {
    return sigma * std::sqrt(-2.0 * std::log(u));
}

// The inward number flux of a Maxwellian gas through a surface per unit area [1/(m² s)] (Bird 1994
// eq. 4.22): n √(kT/2πm) [exp(−s²) + √π s (1 + erf s)], s the inward stream speed over √(2kT/m).
inline double halfRangeFlux(double density, double sigma, double s) {
    return density * sigma / std::sqrt(2.0 * std::numbers::pi) *
           (std::exp(-s * s) + std::sqrt(std::numbers::pi) * s * (1.0 + std::erf(s)));
}

// The inward normal velocity over √(2kT/m), x > 0, of a molecule entering from a Maxwellian with inward
// drift s: density ∝ x exp(−(x − s)²) (the flux-weighted shifted Maxwellian, Bird 1994 §12.5; Garcia &
// Wagner 2006 give an exact scheme). Acceptance–rejection on y = x − s:
//   s ≥ 0: propose g(y) ∝ (|y| + s) e^(−y²) on y > −s, a mixture of |y| e^(−y²) and s e^(−y²) sampled
//          exactly, accept with (y + s)/(|y| + s) (1 for y ≥ 0, at least 1/3 of the proposals overall);
//   s < 0: propose x e^(−x²), accept with e^(2xs) ≤ 1 (the flux is then small).
template <class Rng> double inflowNormalSpeedRatio(double s, Rng& rng) {
    constexpr int kTries = 1000; // the acceptance is ≥ 1/3 for s ≥ 0; below, a cap against s ≪ 0
    double x = 0.0;
    if (s >= 0) {
        const double tail = std::exp(-s * s);
        const double massAbs = 1.0 - 0.5 * tail; // ∫ |y| e^(−y²)
        const double massFlat = s * 0.5 * std::sqrt(std::numbers::pi) * (1.0 + std::erf(s)); // ∫ s e^(−y²)
        for (int k = 0; k < kTries; ++k) {
            double y;
            if (rng.uniform() * (massAbs + massFlat) < massAbs) {
                // |y| e^(−y²) on y > −s: y > 0 holds ½ of it, −s < y < 0 the remaining ½ (1 − e^(−s²)).
                if (rng.uniform() * massAbs < 0.5)
                    y = std::sqrt(-std::log(rng.uniform()));
                else
                    y = -std::sqrt(-std::log(1.0 - rng.uniform() * (1.0 - tail)));
            } else {
                do y = rng.normal() * std::numbers::sqrt2 / 2.0; // e^(−y²): σ = 1/√2
                while (y <= -s);
            }
            x = y + s;
            if (y >= 0 || rng.uniform() * (std::abs(y) + s) < x) return x;
        }
        return x;
    }
    for (int k = 0; k < kTries; ++k) {
        x = std::sqrt(-std::log(rng.uniform()));
        if (rng.uniform() < std::exp(2.0 * x * s)) return x;
    }
    return x;
}

// A body during one step: its centre at the step's start and its velocity (the drive's displacement
// over the step), so the flight meets it in its own frame.
struct BodyFrame {
    bool disc = true;
    double x0 = 0, y0 = 0;                            // centre at τ = 0 [m]
    double vx = 0, vy = 0;                            // [m/s]
    double radius = 0, halfWidth = 0, halfHeight = 0; // [m]
    // The rectangle the body sweeps over the step: a flight whose own bounding box misses it cannot
    // meet the body (the move's fast path).
    double sweptLeft = 0, sweptBottom = 0, sweptRight = 0, sweptTop = 0;

    static BodyFrame of(bool disc, double x, double y, double vx, double vy, double radius, double halfWidth,
                        double halfHeight, double h) {
        BodyFrame f{disc, x - vx * h, y - vy * h, vx, vy, radius, halfWidth, halfHeight};
        const double ex = disc ? radius : halfWidth, ey = disc ? radius : halfHeight;
        f.sweptLeft = std::min(f.x0, x) - ex;
        f.sweptRight = std::max(f.x0, x) + ex;
        f.sweptBottom = std::min(f.y0, y) - ey;
        f.sweptTop = std::max(f.y0, y) + ey;
        return f;
    }
    bool sweepMisses(double xa, double ya, double xb, double yb) const {
        return std::max(xa, xb) < sweptLeft || std::min(xa, xb) > sweptRight ||
               std::max(ya, yb) < sweptBottom || std::min(ya, yb) > sweptTop;
    }
};

// Time t ≥ 0 at which the point r + w t enters the disc |p| < R (centre at the origin), or kNever. A
// point inside moving inward hits at once (t = 0): rounding left it a hair inside after a reflection.
inline double discHitTime(double rx, double ry, double wx, double wy, double radius) {
    const double b = rx * wx + ry * wy; // half the linear coefficient of |r + w t|² − R²
    if (b >= 0) return kNever;          // moving away (or along)
    const double c = rx * rx + ry * ry - radius * radius;
    if (c <= 0) return 0.0;
    const double a = wx * wx + wy * wy;
    const double discriminant = b * b - a * c;
    if (discriminant < 0) return kNever;
    // The smaller root, in the form that does not cancel: t = c / (−b + √D).
    return c / (-b + std::sqrt(discriminant));
}

// Time t ≥ 0 at which r + w t enters the box |x| < a, |y| < b, or kNever; normal: the outward normal of
// the face hit (slab method).
inline double boxHitTime(double rx, double ry, double wx, double wy, double a, double b, double& nx,
                         double& ny) {
    double enter = -kNever, leave = kNever;
    double fx = 0, fy = 0;
    // x slab
    if (wx == 0) {
        if (std::abs(rx) >= a) return kNever;
    } else {
        const double t0 = (-a - rx) / wx, t1 = (a - rx) / wx;
        const double near = std::min(t0, t1), far = std::max(t0, t1);
        if (near > enter) enter = near, fx = wx > 0 ? -1 : 1, fy = 0;
        leave = std::min(leave, far);
    }
    if (wy == 0) {
        if (std::abs(ry) >= b) return kNever;
    } else {
        const double t0 = (-b - ry) / wy, t1 = (b - ry) / wy;
        const double near = std::min(t0, t1), far = std::max(t0, t1);
        if (near > enter) enter = near, fx = 0, fy = wy > 0 ? -1 : 1;
        leave = std::min(leave, far);
    }
    if (enter > leave || leave <= 0) return kNever;
    // Already inside: a body placed onto the particle; the next step's push-out moves it to the surface.
    if (enter < 0) return kNever;
    nx = fx;
    ny = fy;
    return std::max(enter, 0.0);
}

} // namespace pl::tunnel
