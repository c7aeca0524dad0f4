// Four lane-pair slots in one AVX-512 register, for the fluid's AVX-512 pair passes
// (FluidLambdaPass.cpp): slot t's two lanes in the lowest 128 bits, slot t + 3's in the highest. Only
// AVX-512F is assumed (no DQ or VL). Each function is compiled for AVX-512F alone; the callers choose
// them at run time, and only where the CPU has it.
#pragma once

#include "common/Lanes.h"

#include <cstdint>

#if defined(__x86_64__) // SSE2 is the baseline there; AVX-512F is chosen at run time
#include <immintrin.h>
#define PARTICLELAB_FLUID_AVX512 1

namespace pl::fluid::avx512 {

#pragma GCC diagnostic push
// GCC 12's AVX-512 intrinsics pass an "undefined" vector as the merge source their full mask never reads,
// and -Wmaybe-uninitialized reports it.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

struct Oct {
    __m512d v;
};

// A block pair's two lanes in all four slots.
__attribute__((target("avx512f"))) inline Oct octAll(Lanes a) {
    return {_mm512_castps_pd(_mm512_broadcast_f32x4(_mm_castpd_ps(a.v)))};
}

// p[j[0]] … p[j[7]]: eight scalar loads (a vgatherdpd was slower on AMD Zen 5, BENCHMARKS.md).
__attribute__((target("avx512f"))) inline Oct octGather(const double* p, const std::uint32_t* j) {
    return {_mm512_set_pd(p[j[7]], p[j[6]], p[j[5]], p[j[4]], p[j[3]], p[j[2]], p[j[1]], p[j[0]])};
}

// The slot-th 128 bits: one slot's two lanes.
template <int slot> __attribute__((target("avx512f"))) inline Lanes slotOf(__m512d v) {
    return {_mm_castps_pd(_mm512_extractf32x4_ps(_mm512_castpd_ps(v), slot))};
}

// The four slots' values added to a lane pair's sum in slot order, as the one-slot loop adds them.
__attribute__((target("avx512f"))) inline void addSlotSums(Lanes& sum, __m512d v) {
    sum += slotOf<0>(v);
    sum += slotOf<1>(v);
    sum += slotOf<2>(v);
    sum += slotOf<3>(v);
}

#pragma GCC diagnostic pop

} // namespace pl::fluid::avx512
#endif
