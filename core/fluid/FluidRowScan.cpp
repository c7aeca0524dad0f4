// The neighbour rows' scan in SSE2 and AVX-512 (FluidRowScan.h).
#include "FluidRowScan.h"

#include <algorithm>
#if defined(__SSE2__)
#include <immintrin.h>
#endif
#if defined(__x86_64__) // SSE2 is the baseline there; AVX-512 is chosen at run time
#define PARTICLELAB_ROW_SCAN_AVX512 1
#endif

namespace pl::fluid {

namespace {

// The scalar test: within reach unless r² ≥ reach² (a NaN counts as within, as in every build).
inline std::uint32_t scanScalar(const RowScanInputs& in, double xi, double yi, std::uint32_t self,
                                std::uint32_t m, std::uint32_t last, std::uint32_t* row,
                                std::uint32_t found) {
    for (; m < last; ++m) {
        const double dx = xi - in.x[m], dy = yi - in.y[m];
        row[std::min(found, in.capacity)] = m;
        found += static_cast<std::uint32_t>(!(dx * dx + dy * dy >= in.reach2) & (m != self));
    }
    return found;
}

// Particle k's three block rows of cells (fewer at the box's edge), each one contiguous range of solver
// numbers.
struct BlockRows {
    std::uint32_t first[3], last[3];
    int count = 0;
};

inline BlockRows blockRows(const RowScanInputs& in, long long k) {
    const std::uint32_t cell = in.cellOf[in.order[k]];
    const int cx = static_cast<int>(cell % static_cast<std::uint32_t>(in.cellsX));
    const int cy = static_cast<int>(cell / static_cast<std::uint32_t>(in.cellsX));
    BlockRows rows;
    for (int r = std::max(cy - 1, 0); r <= std::min(cy + 1, in.cellsY - 1); ++r, ++rows.count) {
        rows.first[rows.count] = in.cellStart[r * in.cellsX + std::max(cx - 1, 0)];
        rows.last[rows.count] = in.cellStart[r * in.cellsX + std::min(cx + 1, in.cellsX - 1) + 1];
    }
    return rows;
}

std::uint32_t sse2Rows(const RowScanInputs& in, long long first, long long last) {
    std::uint32_t largest = 0;
    for (long long k = first; k < last; ++k) {
        const double xi = in.x[k], yi = in.y[k];
        const auto self = static_cast<std::uint32_t>(k);
        std::uint32_t* row = in.rows + static_cast<std::size_t>(k) * (in.capacity + 1);
        const BlockRows block = blockRows(in, k);
        std::uint32_t found = 0;
        for (int r = 0; r < block.count; ++r) {
            std::uint32_t m = block.first[r];
            const std::uint32_t end = block.last[r];
#if defined(__SSE2__)
            // Two candidates per compare (each lane the scalar test's operations), written in cell order.
            const __m128d x2 = _mm_set1_pd(xi), y2 = _mm_set1_pd(yi), reach2 = _mm_set1_pd(in.reach2);
            for (; m + 2 <= end; m += 2) {
                const __m128d dx = _mm_sub_pd(x2, _mm_loadu_pd(in.x + m));
                const __m128d dy = _mm_sub_pd(y2, _mm_loadu_pd(in.y + m));
                const __m128d r2 = _mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy));
                const auto within = static_cast<std::uint32_t>(_mm_movemask_pd(_mm_cmpnge_pd(r2, reach2)));
                row[std::min(found, in.capacity)] = m;
                found += (within & 1u) & static_cast<std::uint32_t>(m != self);
                row[std::min(found, in.capacity)] = m + 1;
                found += (within >> 1) & static_cast<std::uint32_t>(m + 1 != self);
            }
#endif
            found = scanScalar(in, xi, yi, self, m, end, row, found);
        }
        in.counts[k] = found;
        largest = std::max(largest, found);
    }
    return largest;
}

#if PARTICLELAB_ROW_SCAN_AVX512
// Eight candidates per compare; the last, shorter group through a masked load (lanes past the range read
// nothing and count as out of reach). The solver numbers within reach are packed in cell order by one
// compress and written by a masked store of exactly that many; a row that would pass its capacity is not
// written (its count says so, and the search repeats with larger rows).
__attribute__((target("avx512f"))) std::uint32_t avx512Rows(const RowScanInputs& in, long long first,
                                                            long long last) {
    const __m512d reach2 = _mm512_set1_pd(in.reach2);
    const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 0, 0, 0, 0, 0, 0, 0, 0);
    std::uint32_t largest = 0;
    for (long long k = first; k < last; ++k) {
        const __m512d x8 = _mm512_set1_pd(in.x[k]), y8 = _mm512_set1_pd(in.y[k]);
        const auto self = static_cast<std::uint32_t>(k);
        std::uint32_t* row = in.rows + static_cast<std::size_t>(k) * (in.capacity + 1);
        const BlockRows block = blockRows(in, k);
        std::uint32_t found = 0;
        for (int r = 0; r < block.count; ++r) {
            const std::uint32_t end = block.last[r];
            for (std::uint32_t m = block.first[r]; m < end; m += 8) {
                const auto present = static_cast<__mmask8>(end - m >= 8 ? 0xFFu : (1u << (end - m)) - 1u);
                const __m512d dx = _mm512_sub_pd(x8, _mm512_maskz_loadu_pd(present, in.x + m));
                const __m512d dy = _mm512_sub_pd(y8, _mm512_maskz_loadu_pd(present, in.y + m));
                const __m512d r2 = _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
                unsigned within = _mm512_mask_cmp_pd_mask(present, r2, reach2, _CMP_NGE_UQ);
                if (self - m < 8u) within &= ~(1u << (self - m));
                const auto taken = static_cast<std::uint32_t>(__builtin_popcount(within));
                if (found + taken <= in.capacity) {
                    const __m512i numbers = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(m)), lane);
                    _mm512_mask_storeu_epi32(
                        row + found, static_cast<__mmask16>((1u << taken) - 1u),
                        _mm512_maskz_compress_epi32(static_cast<__mmask16>(within), numbers));
                }
                found += taken;
            }
        }
        in.counts[k] = found;
        largest = std::max(largest, found);
    }
    return largest;
}
#endif

} // namespace

RowScanFunction rowScanSse2() {
    return sse2Rows;
}

RowScanFunction rowScanAvx512() {
#if PARTICLELAB_ROW_SCAN_AVX512
    static const bool avx512 = __builtin_cpu_supports("avx512f");
    if (avx512) return avx512Rows;
#endif
    return nullptr;
}

RowScanFunction rowScan() {
    static const RowScanFunction chosen = rowScanAvx512() ? rowScanAvx512() : rowScanSse2();
    return chosen;
}

} // namespace pl::fluid
