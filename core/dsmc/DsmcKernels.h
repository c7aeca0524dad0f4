// Stateless pieces of one DSMC collision: choosing a pair and scattering it. Gather form throughout, so
// a GPU port can mirror them one for one.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

namespace pl::dsmc {

struct Velocity {
    double x, y, z;
};

// An index in [0, n) from 32 random bits (Lemire's multiply-shift; bias below n / 2³², negligible here).
inline std::uint32_t randomIndex(std::uint32_t bits, std::uint32_t n) {
    return static_cast<std::uint32_t>((std::uint64_t{bits} * n) >> 32);
}

inline double relativeSpeed(const Velocity& a, const Velocity& b) {
    const double x = a.x - b.x, y = a.y - b.y, z = a.z - b.z;
    return std::sqrt(x * x + y * y + z * z);
}

// Elastic isotropic scattering in the centre-of-mass frame (Bird 1994 §2.4;
// docs/dsmc.md#isotropic-scattering): the centre of mass velocity and |c_r| are kept, the direction of c_r
// becomes (cos θ, φ) with cos θ = 2u₁ − 1 and φ = 2π u₂. Momentum and energy are conserved to round-off.
inline void scatterIsotropic(Velocity& a, Velocity& b, double ma, double mb, double u1, double u2) {
    const double total = ma + mb;
    const Velocity cm{(ma * a.x + mb * b.x) / total, (ma * a.y + mb * b.y) / total,
                      (ma * a.z + mb * b.z) / total};
    const double cr = relativeSpeed(a, b);
    const double cosTheta = 2.0 * u1 - 1.0;
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * std::numbers::pi * u2;
    const Velocity r{cr * cosTheta, cr * sinTheta * std::cos(phi), cr * sinTheta * std::sin(phi)};
    a = {cm.x + mb / total * r.x, cm.y + mb / total * r.y, cm.z + mb / total * r.z};
    b = {cm.x - ma / total * r.x, cm.y - ma / total * r.y, cm.z - ma / total * r.z};
}

// The same in the plane (2 velocity components, z stays 0): c_r turns to the angle φ = 2π u, uniform,
// the isotropic scattering of 2D hard disks averaged over impact parameters.
inline void scatterInPlane(Velocity& a, Velocity& b, double ma, double mb, double u) {
    const double total = ma + mb;
    const double cmx = (ma * a.x + mb * b.x) / total, cmy = (ma * a.y + mb * b.y) / total;
    const double cr = std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y));
    const double phi = 2.0 * std::numbers::pi * u;
    const double rx = cr * std::cos(phi), ry = cr * std::sin(phi);
    a = {cmx + mb / total * rx, cmy + mb / total * ry, 0.0};
    b = {cmx - ma / total * rx, cmy - ma / total * ry, 0.0};
}

} // namespace pl::dsmc
