// The SPH kernels and per-pair terms of Position-Based Fluids (Macklin & Müller 2013, eqs. 1–13), written
// for one pair at a time so the CPU loops and the GPU shaders share them function for function.
//
// Normalisation: the seed (and its Taichi ancestor) use the 3D constants in 2D,
//   poly6 W = 315/(64π h⁹)(h² − r²)³,   spiky ∇W = −45/(π h⁶)(h − r)² r̂,
// whose integrals over the plane are 315/(256 h) and 3/(2 h), not 1. With ρ₀ = 1 this only
// rescales ρ, λ and in effect ε. The 2D constants that do integrate to 1 are
//   poly6 W = 4/(π h⁸)(h² − r²)³,       spiky W = 10/(π h⁵)(h − r)³, ∇W = −30/(π h⁵)(h − r)² r̂.
#pragma once

#include <cmath>
#include <numbers>
#include <string>

namespace pl::pbf {

struct Kernels {
    double h = 1, h2 = 1;
    double poly6 = 0;     // W(r) = poly6 (h² − r²)³
    double spikyGrad = 0; // ∇W(r) = −spikyGrad (h − r)² r̂
    double spiky = 0;     // W_spiky(r) = spiky (h − r)³ (for tests and the normalisation check)
    bool selfTerm = false;

    static Kernels make(double h, const std::string& normalisation, bool selfTerm) {
        Kernels k;
        k.h = h;
        k.h2 = h * h;
        k.selfTerm = selfTerm;
        const double pi = std::numbers::pi;
        if (normalisation == "2d") {
            k.poly6 = 4.0 / (pi * std::pow(h, 8));
            k.spiky = 10.0 / (pi * std::pow(h, 5));
            k.spikyGrad = 30.0 / (pi * std::pow(h, 5));
        } else { // "seed-3d"
            k.poly6 = 315.0 / (64.0 * pi * std::pow(h, 9));
            k.spiky = 15.0 / (pi * std::pow(h, 6));
            k.spikyGrad = 45.0 / (pi * std::pow(h, 6));
        }
        return k;
    }

    // Poly6 from the squared distance. As in the seed, a pair at r = 0 weighs nothing (it has no gradient
    // to separate it either); a particle's own weight is added, or not, by selfWeight().
    double w(double r2) const {
        if (r2 >= h2 || r2 <= 0.0) return 0.0;
        const double d = h2 - r2;
        return poly6 * d * d * d;
    }
    double selfWeight() const { return selfTerm ? poly6 * h2 * h2 * h2 : 0.0; }
    double wSpiky(double r) const { return r < h ? spiky * (h - r) * (h - r) * (h - r) : 0.0; }

    // ∇_i W_spiky(x_i − x_j) = −spikyGrad (h − r)² (x_i − x_j)/r, returned as the factor multiplying
    // (dx, dy) = x_i − x_j. Zero at r = 0 (no direction) and beyond h.
    double gradFactor(double r2) const {
        if (r2 >= h2 || r2 <= 0.0) return 0.0;
        const double r = std::sqrt(r2);
        const double d = h - r;
        return -spikyGrad * d * d / r;
    }
};

// Artificial pressure (eq. 13): s_corr = −k (W(r) / W(Δq h))ⁿ; the 1/W(Δq h) is precomputed.
struct ArtificialPressure {
    double k = 0, inverseReference = 0;
    int n = 4;
    double operator()(double w) const {
        if (k == 0.0) return 0.0;
        const double ratio = w * inverseReference;
        double p = ratio;
        for (int e = 1; e < n; ++e) p *= ratio;
        return -k * p;
    }
};

} // namespace pl::pbf
