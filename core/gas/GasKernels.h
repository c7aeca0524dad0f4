// Stateless per-particle and per-pair formulas of the gas, in gather form. The GLSL twin
// resources/shaders/gas/gas_kernels.glsl keeps the same names, argument order and equations.
#pragma once

#include <cmath>

namespace pl::gas {

// Pairs closer than this are treated as coincident: no direction, no force [L²].
constexpr double kCoincidentR2 = 1e-24;

struct PairResult {
    double fx, fy;    // force on i from j [M·L/T²]
    double potential; // U(r) = k/2 (d − r)² [energy]
    double virial;    // r_ij · f_ij = k (d − r) r [energy]
};

// Harmonic repulsion (docs/gas.md#pair-force): f_ij = k (d − r) r̂_ij for r < d, zero beyond.
// The write-up: a = k (d − r)/r · dr.
inline bool harmonicPair(double dx, double dy, double contactDiameter, double stiffness, PairResult& out) {
    const double r2 = dx * dx + dy * dy;
    if (r2 >= contactDiameter * contactDiameter || r2 < kCoincidentR2) return false;
    const double r = std::sqrt(r2);
    const double overlap = contactDiameter - r;
    const double fOverR = stiffness * overlap / r;
    out.fx = fOverR * dx;
    out.fy = fOverR * dy;
    out.potential = 0.5 * stiffness * overlap * overlap;
    out.virial = stiffness * overlap * r;
    return true;
}

// Contact distance of two disks: the mean of their diameters.
inline double contactDiameter(double di, double dj) {
    return 0.5 * (di + dj);
}

// Mirror reflection off a plane wall at position w whose outward normal points along +axis (sign = +1)
// or −axis (sign = −1), moving with velocity u along the axis. timeSign is the sign of the drift's time
// step: a disk crosses into the wall when it moves into it in the drift's direction of time, so under
// −dt the flip undoes the forward one exactly (time reversal). Returns the normal velocity change
// (before − after)·sign, or 0 when no crossing happened.
inline double reflectPlane(double& p, double& v, double w, double sign, double u, double timeSign) {
    if ((p - w) * sign <= 0) return 0.0;
    p = 2.0 * w - p;
    const double before = v;
    if ((v - u) * sign * timeSign > 0) v = 2.0 * u - v; // reflect only when moving into the wall
    return (before - v) * sign;
}

// Harmonic oscillator frequency of a contact between masses mi and mj: ω = √(k / μ), μ = mi mj / (mi + mj).
inline double contactOmega(double stiffness, double mi, double mj) {
    return std::sqrt(stiffness * (mi + mj) / (mi * mj));
}

} // namespace pl::gas
