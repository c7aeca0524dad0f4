// Two doubles per operation for the CPU pair loops: the fluid's passes run two particles side by side, each
// lane walking its own neighbour row. Every lane performs exactly the scalar operations, in the same order
// (SSE2 has no fused multiply-add, and its square root and division are correctly rounded, as IEEE scalar
// ones are), so the results are the scalar ones bit for bit at any lane or thread count. Without SSE2, the
// same operations one lane at a time.
#pragma once

#include <cmath>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pl {

#if defined(__SSE2__)
struct Lanes {
    __m128d v;
    static Lanes all(double a) { return {_mm_set1_pd(a)}; }
    static Lanes load(const double* p) { return {_mm_load_pd(p)}; } // p 16-byte aligned
    static Lanes gather(const double* p, std::uint32_t j0, std::uint32_t j1) {
        return {_mm_loadh_pd(_mm_load_sd(p + j0), p + j1)};
    }
    void store(double* p) const { _mm_store_pd(p, v); }
    double lane0() const { return _mm_cvtsd_f64(v); }
    double lane1() const { return _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); }
    friend Lanes operator+(Lanes a, Lanes b) { return {_mm_add_pd(a.v, b.v)}; }
    friend Lanes operator-(Lanes a, Lanes b) { return {_mm_sub_pd(a.v, b.v)}; }
    friend Lanes operator*(Lanes a, Lanes b) { return {_mm_mul_pd(a.v, b.v)}; }
    friend Lanes operator/(Lanes a, Lanes b) { return {_mm_div_pd(a.v, b.v)}; }
    friend Lanes operator-(Lanes a) { return {_mm_xor_pd(a.v, _mm_set1_pd(-0.0))}; } // exact, as scalar −a
    Lanes& operator+=(Lanes b) { return *this = *this + b; }
    friend Lanes sqrt(Lanes a) { return {_mm_sqrt_pd(a.v)}; }
    // a where the lane's r2 is inside the support, i.e. not (r2 ≥ h² or r2 ≤ 0) as in the scalar test; +0
    // elsewhere (NaN r2 keeps a, like the scalar code).
    static Lanes insideSupport(Lanes a, Lanes r2, Lanes h2) {
        const __m128d inside = _mm_and_pd(_mm_cmpnge_pd(r2.v, h2.v), _mm_cmpnle_pd(r2.v, _mm_setzero_pd()));
        return {_mm_and_pd(inside, a.v)};
    }
};
#else
struct Lanes {
    double a0, a1;
    static Lanes all(double a) { return {a, a}; }
    static Lanes load(const double* p) { return {p[0], p[1]}; }
    static Lanes gather(const double* p, std::uint32_t j0, std::uint32_t j1) { return {p[j0], p[j1]}; }
    void store(double* p) const {
        p[0] = a0;
        p[1] = a1;
    }
    double lane0() const { return a0; }
    double lane1() const { return a1; }
    friend Lanes operator+(Lanes a, Lanes b) { return {a.a0 + b.a0, a.a1 + b.a1}; }
    friend Lanes operator-(Lanes a, Lanes b) { return {a.a0 - b.a0, a.a1 - b.a1}; }
    friend Lanes operator*(Lanes a, Lanes b) { return {a.a0 * b.a0, a.a1 * b.a1}; }
    friend Lanes operator/(Lanes a, Lanes b) { return {a.a0 / b.a0, a.a1 / b.a1}; }
    friend Lanes operator-(Lanes a) { return {-a.a0, -a.a1}; }
    Lanes& operator+=(Lanes b) { return *this = *this + b; }
    friend Lanes sqrt(Lanes a) { return {std::sqrt(a.a0), std::sqrt(a.a1)}; }
    static Lanes insideSupport(Lanes a, Lanes r2, Lanes h2) {
        return {r2.a0 >= h2.a0 || r2.a0 <= 0.0 ? 0.0 : a.a0, r2.a1 >= h2.a1 || r2.a1 <= 0.0 ? 0.0 : a.a1};
    }
};
#endif

} // namespace pl
