// The SPH kernels and per-pair terms of Position-Based Fluids (Macklin & Müller 2013, eqs. 1–13), written
// for one pair at a time so the CPU loops and the GPU shaders share them function for function.
//
// Normalisation: the write-up (and its Taichi ancestor) use the 3D constants in 2D,
//   poly6 W = 315/(64π h⁹)(h² − r²)³,   spiky ∇W = −45/(π h⁶)(h − r)² r̂,
// whose integrals over the plane are 315/(256 h) and 3/(2 h), not 1. With ρ₀ = 1 this only
// rescales ρ, λ and in effect ε. The 2D constants that do integrate to 1 are
//   poly6 W = 4/(π h⁸)(h² − r²)³,       spiky W = 10/(π h⁵)(h − r)³, ∇W = −30/(π h⁵)(h − r)² r̂.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "common/Lanes.h"

namespace pl {
// Which constants the kernels use (the header comment): the write-up's 3D ones, or those normalised in 2D.
enum class FluidKernelConstants { Unnormalised3d, Normalised2d };
} // namespace pl

namespace pl::fluid {

struct Kernels {
    double h = 1, h2 = 1;
    double poly6 = 0;     // W(r) = poly6 (h² − r²)³
    double spikyGrad = 0; // ∇W(r) = −spikyGrad (h − r)² r̂
    double spiky = 0;     // W_spiky(r) = spiky (h − r)³ (for tests and the normalisation check)
    bool selfTerm = false;

    static Kernels make(double h, FluidKernelConstants normalisation, bool selfTerm) {
        Kernels k;
        k.h = h;
        k.h2 = h * h;
        k.selfTerm = selfTerm;
        const double pi = std::numbers::pi;
        if (normalisation == FluidKernelConstants::Normalised2d) {
            k.poly6 = 4.0 / (pi * std::pow(h, 8));
            k.spiky = 10.0 / (pi * std::pow(h, 5));
            k.spikyGrad = 30.0 / (pi * std::pow(h, 5));
        } else { // FluidKernelConstants::Unnormalised3d
            k.poly6 = 315.0 / (64.0 * pi * std::pow(h, 9));
            k.spiky = 15.0 / (pi * std::pow(h, 6));
            k.spikyGrad = 45.0 / (pi * std::pow(h, 6));
        }
        return k;
    }

    // Poly6 from the squared distance. As in the write-up, a pair at r = 0 weighs nothing (it has no gradient
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

// Kernels::w, Kernels::gradFactor and ArtificialPressure for two pairs (common/Lanes.h: each lane does
// the scalar operations in the scalar order, hence the same bits), with the constants kept in registers.
// Outside the support they give +0 where the scalar code returns 0.0.
struct LaneKernels {
    Lanes h, h2, poly6, minusSpikyGrad, minusK, inverseReference;
    int n = 4;
    bool scorr = false;

    LaneKernels(const Kernels& k, const ArtificialPressure& s)
        : h(Lanes::all(k.h)), h2(Lanes::all(k.h2)), poly6(Lanes::all(k.poly6)),
          minusSpikyGrad(Lanes::all(-k.spikyGrad)), minusK(Lanes::all(-s.k)),
          inverseReference(Lanes::all(s.inverseReference)), n(s.n), scorr(s.k != 0.0) {}

    Lanes w(Lanes r2) const {
        const Lanes d = h2 - r2;
        return Lanes::insideSupport(poly6 * d * d * d, r2, h2);
    }
    Lanes gradFactor(Lanes r2) const {
        const Lanes r = sqrt(r2);
        const Lanes d = h - r;
        return Lanes::insideSupport(minusSpikyGrad * d * d / r, r2, h2);
    }
    Lanes artificialPressure(Lanes w) const {
        if (!scorr) return Lanes::all(0.0);
        const Lanes ratio = w * inverseReference;
        Lanes p = ratio;
        for (int e = 1; e < n; ++e) p = p * ratio;
        return minusK * p;
    }
};

// The two solver particles of lane-pair block b (the same one twice in an odd count's last block), or
// their particle numbers: the blocks every two-lane pass of the solver walks.
struct BlockPair {
    std::uint32_t first, second;
    BlockPair(long long b, long long count)
        : first(static_cast<std::uint32_t>(2 * b)),
          second(static_cast<std::uint32_t>(std::min(2 * b + 1, count - 1))) {}
    BlockPair(BlockPair solver, const std::uint32_t* order)
        : first(order[solver.first]), second(order[solver.second]) {}
    Lanes gather(const double* values) const { return Lanes::gather(values, first, second); }
    void scatter(Lanes v, double* values) const {
        values[first] = v.lane0();
        if (second != first) values[second] = v.lane1(); // a lone particle fills both lanes alike
    }
};

} // namespace pl::fluid
