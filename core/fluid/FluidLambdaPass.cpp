// The λ pass's block loop in SSE2, AVX and AVX-512 (FluidLambdaPass.h).
#include "FluidLambdaPass.h"

#include "FluidAvx512.h"

#include <algorithm>
#if defined(__x86_64__) // SSE2 is the baseline there: Lanes holds an __m128d
#include <immintrin.h>
#define PARTICLELAB_FLUID_AVX 1
#endif

namespace pl::fluid {

namespace {

// One block's sums over its rows, two pairs per step (each lane its own row).
struct BlockSums {
    Lanes rho, gx, gy, sumSquares, sx, sy;
};

// Slot e (entries e, e + 1) of a block whose particles sit at (xi, yi): the SSE2 step of the pass.
inline void addSlot(const LambdaArrays& a, const LaneKernels& k, Lanes xi, Lanes yi, std::size_t e,
                    BlockSums& s) {
    const std::uint32_t j0 = a.lanes[e], j1 = a.lanes[e + 1];
    const Lanes dx = xi - Lanes::gather(a.px, j0, j1), dy = yi - Lanes::gather(a.py, j0, j1);
    const Lanes r2 = dx * dx + dy * dy;
    const Lanes w = k.w(r2);
    const Lanes f = k.gradFactor(r2); // both 0 beyond h
    const Lanes p = k.artificialPressure(w);
    const Lanes fx = f * dx, fy = f * dy;
    s.rho += w;
    fx.store(a.pairGradX + e);
    fy.store(a.pairGradY + e);
    s.gx += fx;
    s.gy += fy;
    s.sx += p * f * dx;
    s.sy += p * f * dy;
    s.sumSquares += f * f * r2;
}

inline void finishBlock(const LambdaArrays& a, const LambdaConstants& c, BlockPair pair, const BlockSums& s) {
    const Lanes inverseRest = Lanes::all(c.inverseRest), one = Lanes::all(1.0);
    const Lanes constraint = s.rho * inverseRest - one;
    pair.scatter(constraint, a.constraint);
    // The solve of the step's new compression (FluidModel::solveNewCompression) sees C_i − b_i. The
    // inequality ρ_i ≤ ρ₀ (Müller et al. 2007 §3.3: a constraint projected only while violated) then leaves
    // an under-dense particle's λ at 0: it pulls no neighbour.
    Lanes target = constraint;
    if (a.bias) target = target - pair.gather(a.bias);
    if (c.compressionOnly) {
        const double clamped[2] = {std::max(target.lane0(), 0.0), std::max(target.lane1(), 0.0)};
        target = Lanes::gather(clamped, 0, 1);
    }
    pair.scatter(-target / ((s.gx * s.gx + s.gy * s.gy + s.sumSquares) * inverseRest * inverseRest +
                            Lanes::all(c.epsilon)),
                 a.lambda);
    pair.scatter(s.gx, a.gradSumX);
    pair.scatter(s.gy, a.gradSumY);
    pair.scatter(s.sx, a.scorrSumX);
    pair.scatter(s.sy, a.scorrSumY);
}

BlockSums startBlock(const LambdaConstants& c) {
    const Lanes zero = Lanes::all(0.0);
    return {Lanes::all(c.selfWeight), zero, zero, zero, zero, zero};
}

void sse2Blocks(const LambdaArrays& a, const LambdaConstants& c, long long first, long long last) {
    for (long long b = first; b < last; ++b) {
        const BlockPair pair(b, a.count);
        const Lanes xi = pair.gather(a.px), yi = pair.gather(a.py);
        BlockSums s = startBlock(c);
        for (std::size_t e = 2 * std::size_t{a.blockStart[b]}; e < 2 * std::size_t{a.blockStart[b + 1]};
             e += 2)
            addSlot(a, c.kernels, xi, yi, e, s);
        finishBlock(a, c, pair, s);
    }
}

#if PARTICLELAB_FLUID_AVX
// Four pairs: slot t's two lanes in the low half, slot t + 1's in the high half.
struct Quad {
    __m256d v;
};

__attribute__((target("avx"))) inline Quad quadAll(Lanes a) {
    return {_mm256_set_m128d(a.v, a.v)};
}
__attribute__((target("avx"))) inline Quad quadGather(const double* p, const std::uint32_t* j) {
    return {_mm256_set_pd(p[j[3]], p[j[2]], p[j[1]], p[j[0]])};
}
__attribute__((target("avx"))) inline Lanes low(Quad q) {
    return {_mm256_castpd256_pd128(q.v)};
}
__attribute__((target("avx"))) inline Lanes high(Quad q) {
    return {_mm256_extractf128_pd(q.v, 1)};
}

// addSlot for slots e/2 and e/2 + 1 at once: the same operations per pair, then the sums in slot order.
__attribute__((target("avx"))) void addTwoSlots(const LambdaArrays& a, const LaneKernels& k, Quad xi, Quad yi,
                                                std::size_t e, BlockSums& s) {
    const __m256d dx = _mm256_sub_pd(xi.v, quadGather(a.px, a.lanes + e).v);
    const __m256d dy = _mm256_sub_pd(yi.v, quadGather(a.py, a.lanes + e).v);
    const __m256d r2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    // Lanes::insideSupport: not (r2 ≥ h² or r2 ≤ 0), NaN counting as inside.
    const __m256d h2 = quadAll(k.h2).v;
    const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(r2, h2, _CMP_NGE_UQ),
                                         _mm256_cmp_pd(r2, _mm256_setzero_pd(), _CMP_NLE_UQ));
    const __m256d d = _mm256_sub_pd(h2, r2);
    const __m256d w =
        _mm256_and_pd(inside, _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(quadAll(k.poly6).v, d), d), d));
    const __m256d r = _mm256_sqrt_pd(r2);
    const __m256d hr = _mm256_sub_pd(quadAll(k.h).v, r);
    const __m256d f = _mm256_and_pd(
        inside, _mm256_div_pd(_mm256_mul_pd(_mm256_mul_pd(quadAll(k.minusSpikyGrad).v, hr), hr), r));
    __m256d p = _mm256_setzero_pd();
    if (k.scorr) {
        const __m256d ratio = _mm256_mul_pd(w, quadAll(k.inverseReference).v);
        p = ratio;
        for (int n = 1; n < k.n; ++n) p = _mm256_mul_pd(p, ratio);
        p = _mm256_mul_pd(quadAll(k.minusK).v, p);
    }
    const __m256d fx = _mm256_mul_pd(f, dx), fy = _mm256_mul_pd(f, dy);
    _mm256_storeu_pd(a.pairGradX + e, fx);
    _mm256_storeu_pd(a.pairGradY + e, fy);
    const __m256d pf = _mm256_mul_pd(p, f);
    const __m256d psx = _mm256_mul_pd(pf, dx), psy = _mm256_mul_pd(pf, dy);
    const __m256d squares = _mm256_mul_pd(_mm256_mul_pd(f, f), r2);
    s.rho += low({w});
    s.rho += high({w});
    s.gx += low({fx});
    s.gx += high({fx});
    s.gy += low({fy});
    s.gy += high({fy});
    s.sx += low({psx});
    s.sx += high({psx});
    s.sy += low({psy});
    s.sy += high({psy});
    s.sumSquares += low({squares});
    s.sumSquares += high({squares});
}

__attribute__((target("avx"))) void avxBlocks(const LambdaArrays& a, const LambdaConstants& c,
                                              long long first, long long last) {
    for (long long b = first; b < last; ++b) {
        const BlockPair pair(b, a.count);
        const Lanes xi = pair.gather(a.px), yi = pair.gather(a.py);
        const Quad xq = quadAll(xi), yq = quadAll(yi);
        BlockSums s = startBlock(c);
        std::size_t e = 2 * std::size_t{a.blockStart[b]};
        const std::size_t end = 2 * std::size_t{a.blockStart[b + 1]};
        for (; e + 4 <= end; e += 4) addTwoSlots(a, c.kernels, xq, yq, e, s);
        if (e < end) addSlot(a, c.kernels, xi, yi, e, s);
        finishBlock(a, c, pair, s);
    }
}

#pragma GCC diagnostic push
// GCC 12's AVX-512 intrinsics pass an "undefined" vector as the merge source their full mask never
// reads, and -Wmaybe-uninitialized reports it.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
using avx512::addSlotSums;
using avx512::Oct;
using avx512::octAll;
using avx512::octGather;

// addSlot for slots e/2 … e/2 + 3 at once: the same operations per pair, then the sums in slot order.
__attribute__((target("avx512f"))) void addFourSlots(const LambdaArrays& a, const LaneKernels& k, Oct xi,
                                                     Oct yi, std::size_t e, BlockSums& s) {
    const __m512d dx = _mm512_sub_pd(xi.v, octGather(a.px, a.lanes + e).v);
    const __m512d dy = _mm512_sub_pd(yi.v, octGather(a.py, a.lanes + e).v);
    const __m512d r2 = _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
    // Lanes::insideSupport: not (r2 ≥ h² or r2 ≤ 0), NaN counting as inside.
    const __m512d h2 = octAll(k.h2).v;
    const __mmask8 inside =
        _mm512_cmp_pd_mask(r2, h2, _CMP_NGE_UQ) & _mm512_cmp_pd_mask(r2, _mm512_setzero_pd(), _CMP_NLE_UQ);
    const __m512d d = _mm512_sub_pd(h2, r2);
    const __m512d w =
        _mm512_maskz_mov_pd(inside, _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(octAll(k.poly6).v, d), d), d));
    const __m512d r = _mm512_sqrt_pd(r2);
    const __m512d hr = _mm512_sub_pd(octAll(k.h).v, r);
    const __m512d f = _mm512_maskz_mov_pd(
        inside, _mm512_div_pd(_mm512_mul_pd(_mm512_mul_pd(octAll(k.minusSpikyGrad).v, hr), hr), r));
    __m512d p = _mm512_setzero_pd();
    if (k.scorr) {
        const __m512d ratio = _mm512_mul_pd(w, octAll(k.inverseReference).v);
        p = ratio;
        for (int n = 1; n < k.n; ++n) p = _mm512_mul_pd(p, ratio);
        p = _mm512_mul_pd(octAll(k.minusK).v, p);
    }
    const __m512d fx = _mm512_mul_pd(f, dx), fy = _mm512_mul_pd(f, dy);
    _mm512_storeu_pd(a.pairGradX + e, fx);
    _mm512_storeu_pd(a.pairGradY + e, fy);
    const __m512d pf = _mm512_mul_pd(p, f);
    addSlotSums(s.rho, w);
    addSlotSums(s.gx, fx);
    addSlotSums(s.gy, fy);
    addSlotSums(s.sx, _mm512_mul_pd(pf, dx));
    addSlotSums(s.sy, _mm512_mul_pd(pf, dy));
    addSlotSums(s.sumSquares, _mm512_mul_pd(_mm512_mul_pd(f, f), r2));
}

__attribute__((target("avx512f"))) void avx512Blocks(const LambdaArrays& a, const LambdaConstants& c,
                                                     long long first, long long last) {
    for (long long b = first; b < last; ++b) {
        const BlockPair pair(b, a.count);
        const Lanes xi = pair.gather(a.px), yi = pair.gather(a.py);
        const Oct xo = octAll(xi), yo = octAll(yi);
        const Quad xq = quadAll(xi), yq = quadAll(yi);
        BlockSums s = startBlock(c);
        std::size_t e = 2 * std::size_t{a.blockStart[b]};
        const std::size_t end = 2 * std::size_t{a.blockStart[b + 1]};
        for (; e + 8 <= end; e += 8) addFourSlots(a, c.kernels, xo, yo, e, s);
        if (e + 4 <= end) {
            addTwoSlots(a, c.kernels, xq, yq, e, s);
            e += 4;
        }
        if (e < end) addSlot(a, c.kernels, xi, yi, e, s);
        finishBlock(a, c, pair, s);
    }
}
#pragma GCC diagnostic pop
#endif

} // namespace

LambdaBlocksFunction lambdaBlocksSse2() {
    return sse2Blocks;
}

LambdaBlocksFunction lambdaBlocksAvx() {
#if PARTICLELAB_FLUID_AVX
    static const bool avx = __builtin_cpu_supports("avx");
    if (avx) return avxBlocks;
#endif
    return nullptr;
}

LambdaBlocksFunction lambdaBlocksAvx512() {
#if PARTICLELAB_FLUID_AVX
    static const bool avx512 = __builtin_cpu_supports("avx512f");
    if (avx512) return avx512Blocks;
#endif
    return nullptr;
}

LambdaBlocksFunction lambdaBlocks() {
    static const LambdaBlocksFunction chosen = lambdaBlocksAvx512() ? lambdaBlocksAvx512()
                                               : lambdaBlocksAvx()  ? lambdaBlocksAvx()
                                                                    : lambdaBlocksSse2();
    return chosen;
}

} // namespace pl::fluid
