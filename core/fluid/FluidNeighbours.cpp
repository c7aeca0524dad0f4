// Single-pass neighbour search into fixed-capacity rows, grown and repeated on overflow, and the two
// packings of those rows (CSR for the observables, lane pairs for the solver).
#include "FluidNeighbours.h"

#include "common/Parallel.h"

#include <omp.h>

#include <algorithm>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pl::fluid {

void Neighbours::search(const double* x, const double* y, std::size_t count, double reach, double width,
                        double height) {
    cells_.configure(0.0, 0.0, width, height, reach);
    cells_.build(x, y, count);
    const auto n = static_cast<long long>(count);
    const std::uint32_t* order = cells_.order().data();
    const std::uint32_t* start = cells_.cellStart().data();
    const std::uint32_t* cellOf = cells_.cellOfParticle().data();
    sortedX_.resize(count);
    sortedY_.resize(count);
    counts_.resize(count);
    rank_.resize(count);
    double *sortedX = sortedX_.data(), *sortedY = sortedY_.data();
    std::uint32_t* rank = rank_.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long k = 0; k < n; ++k) {
        sortedX[k] = x[order[k]];
        sortedY[k] = y[order[k]];
        rank[order[k]] = static_cast<std::uint32_t>(k);
    }
    const double reach2 = reach * reach;
    const int nx = cells_.cellsX(), ny = cells_.cellsY();
    std::uint32_t* counts = counts_.data();
    for (;;) {
        // One spare slot per row takes the writes past the capacity, so the scan below needs no branch
        // per candidate; an overflow is seen in the count and the scan repeated with larger rows.
        const std::uint32_t capacity = capacity_, stride = capacity_ + 1;
        rows_.resize(count * stride);
        std::uint32_t* rows = rows_.data();
        std::uint32_t largest = 0;
        // In solver numbers: row k lists the solver numbers of particle order[k]'s neighbours.
#pragma omp parallel for schedule(static) reduction(max : largest) if (n >= kParallelMinParticles)
        for (long long k = 0; k < n; ++k) {
            const double xi = sortedX[k], yi = sortedY[k];
            const auto self = static_cast<std::uint32_t>(k);
            const std::uint32_t cell = cellOf[order[k]];
            const int cx = static_cast<int>(cell % static_cast<std::uint32_t>(nx));
            const int cy = static_cast<int>(cell / static_cast<std::uint32_t>(nx));
            std::uint32_t* row = rows + static_cast<std::size_t>(k) * stride;
            std::uint32_t found = 0;
            for (int r = std::max(cy - 1, 0); r <= std::min(cy + 1, ny - 1); ++r) {
                const std::uint32_t first = start[r * nx + std::max(cx - 1, 0)];
                const std::uint32_t last = start[r * nx + std::min(cx + 1, nx - 1) + 1];
                std::uint32_t m = first;
#if defined(__SSE2__)
                // Two candidates per SSE2 compare (each lane the scalar test's operations, so the same
                // decisions), still written in cell order.
                const __m128d x2 = _mm_set1_pd(xi), y2 = _mm_set1_pd(yi), reach2x2 = _mm_set1_pd(reach2);
                for (; m + 2 <= last; m += 2) {
                    const __m128d dx = _mm_sub_pd(x2, _mm_loadu_pd(sortedX + m));
                    const __m128d dy = _mm_sub_pd(y2, _mm_loadu_pd(sortedY + m));
                    const __m128d r2 = _mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy));
                    const auto within =
                        static_cast<std::uint32_t>(_mm_movemask_pd(_mm_cmpnge_pd(r2, reach2x2)));
                    row[std::min(found, capacity)] = m;
                    found += (within & 1u) & static_cast<std::uint32_t>(m != self);
                    row[std::min(found, capacity)] = m + 1;
                    found += (within >> 1) & static_cast<std::uint32_t>(m + 1 != self);
                }
#endif
                for (; m < last; ++m) {
                    const double dx = xi - sortedX[m], dy = yi - sortedY[m];
                    row[std::min(found, capacity)] = m;
                    found += static_cast<std::uint32_t>(!(dx * dx + dy * dy >= reach2) & (m != self));
                }
            }
            counts[k] = found;
            largest = std::max(largest, found);
        }
        if (largest <= capacity_) break;
        capacity_ = largest + largest / 4; // rare: a denser clump than ever before
    }
}

void Neighbours::build(const double* x, const double* y, std::size_t count, double reach, double width,
                       double height) {
    search(x, y, count, reach, width, height);
    const auto n = static_cast<long long>(count);
    const std::size_t stride = capacity_ + 1;
    const std::uint32_t *order = cells_.order().data(), *rank = rank_.data(), *counts = counts_.data();
    offsets_.resize(count + 1);
    offsets_[0] = 0;
    for (std::size_t i = 0; i < count; ++i) offsets_[i + 1] = offsets_[i] + counts[rank[i]];
    entries_.resize(offsets_[count]);
    const std::uint32_t *rows = rows_.data(), *offsets = offsets_.data();
    std::uint32_t* entries = entries_.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        const std::uint32_t k = rank[i];
        const std::uint32_t* row = rows + std::size_t{k} * stride;
        for (std::uint32_t t = 0; t < counts[k]; ++t) entries[offsets[i] + t] = order[row[t]];
    }
}

void Neighbours::buildLanePairs(const double* x, const double* y, std::size_t count, double reach,
                                double width, double height) {
    search(x, y, count, reach, width, height);
    const std::size_t blocks = (count + 1) / 2;
    const std::size_t stride = capacity_ + 1;
    blockStart_.resize(blocks + 1);
    blockStart_[0] = 0;
    for (std::size_t b = 0; b < blocks; ++b)
        blockStart_[b + 1] =
            blockStart_[b] + std::max(counts_[2 * b], counts_[std::min(2 * b + 1, count - 1)]);
    laneEntries_.resize(2 * static_cast<std::size_t>(blockStart_[blocks]));
    const std::uint32_t *rows = rows_.data(), *counts = counts_.data(), *blockStart = blockStart_.data();
    std::uint32_t* lanes = laneEntries_.data();
    const auto blockCount = static_cast<long long>(blocks);
#pragma omp parallel for schedule(static) if (static_cast <long long>(count) >= kParallelMinParticles)
    for (long long b = 0; b < blockCount; ++b) {
        const std::uint32_t length = blockStart[b + 1] - blockStart[b];
        for (std::size_t lane = 0; lane < 2; ++lane) {
            const auto k =
                static_cast<std::uint32_t>(std::min(2 * static_cast<std::size_t>(b) + lane, count - 1));
            const std::uint32_t* row = rows + std::size_t{k} * stride;
            std::uint32_t* slots = lanes + 2 * std::size_t{blockStart[b]} + lane;
            for (std::uint32_t t = 0; t < length; ++t) slots[2 * t] = t < counts[k] ? row[t] : k;
        }
    }
}

Neighbours::BlockRange Neighbours::threadBlocks() const {
    const auto count = static_cast<long long>(blocks());
    const long long threads = omp_get_num_threads(), thread = omp_get_thread_num();
    // The first block at which slots + blocks before it reach the share's start.
    const auto edge = [&](long long part) {
        if (part >= threads) return count;
        const double target = static_cast<double>(blockStart_[count] + count) * part / threads;
        long long low = 0, high = count;
        while (low < high) {
            const long long mid = (low + high) / 2;
            if (static_cast<double>(blockStart_[mid] + mid) < target)
                low = mid + 1;
            else
                high = mid;
        }
        return low;
    };
    return {edge(thread), edge(thread + 1)};
}

} // namespace pl::fluid
