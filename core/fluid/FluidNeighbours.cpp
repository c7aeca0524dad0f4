// Single-pass neighbour search into fixed-capacity rows, grown and repeated on overflow, and the two
// packings of those rows (CSR for the observables, lane pairs for the solver).
#include "FluidNeighbours.h"
#include "FluidRowScan.h"

#include "common/Parallel.h"

#include <omp.h>

#include <algorithm>

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
    const RowScanFunction scan = rowScan(); // AVX-512 where the CPU has it
    for (;;) {
        // One spare slot per row takes the writes past the capacity, so the scan needs no branch per
        // candidate; an overflow is seen in the count and the scan repeated with larger rows.
        rows_.resize(count * (capacity_ + 1));
        // In solver numbers: row k lists the solver numbers of particle order[k]'s neighbours.
        const RowScanInputs in{sortedX,   sortedY,         order,           cellOf,
                               start,     cells_.cellsX(), cells_.cellsY(), reach * reach,
                               capacity_, rows_.data(),    counts_.data()};
        std::uint32_t largest = 0;
#pragma omp parallel reduction(max : largest) if (n >= kParallelMinParticles)
        {
            // One contiguous stretch of rows per thread; each row is its own, so the split changes no bit.
            const long long threads = omp_get_num_threads(), thread = omp_get_thread_num();
            largest = scan(in, n * thread / threads, n * (thread + 1) / threads);
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
