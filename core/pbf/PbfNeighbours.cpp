// Single-pass neighbour search into fixed-capacity rows, grown and repeated on overflow, and the two
// packings of those rows (CSR for the observables, lane pairs for the solver).
#include "PbfNeighbours.h"

#include "common/Parallel.h"

#include <algorithm>

namespace pl::pbf {

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
    double *sortedX = sortedX_.data(), *sortedY = sortedY_.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long k = 0; k < n; ++k) {
        sortedX[k] = x[order[k]];
        sortedY[k] = y[order[k]];
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
#pragma omp parallel for schedule(static) reduction(max : largest) if (n >= kParallelMinParticles)
        for (long long i = 0; i < n; ++i) {
            const double xi = x[i], yi = y[i];
            const auto self = static_cast<std::uint32_t>(i);
            const int cx = static_cast<int>(cellOf[i] % static_cast<std::uint32_t>(nx));
            const int cy = static_cast<int>(cellOf[i] / static_cast<std::uint32_t>(nx));
            std::uint32_t* row = rows + static_cast<std::size_t>(i) * stride;
            std::uint32_t found = 0;
            for (int r = std::max(cy - 1, 0); r <= std::min(cy + 1, ny - 1); ++r) {
                const std::uint32_t first = start[r * nx + std::max(cx - 1, 0)];
                const std::uint32_t last = start[r * nx + std::min(cx + 1, nx - 1) + 1];
                for (std::uint32_t k = first; k < last; ++k) {
                    const double dx = xi - sortedX[k], dy = yi - sortedY[k];
                    const std::uint32_t j = order[k];
                    row[std::min(found, capacity)] = j;
                    found += static_cast<std::uint32_t>(!(dx * dx + dy * dy >= reach2) & (j != self));
                }
            }
            counts[i] = found;
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
    offsets_.resize(count + 1);
    offsets_[0] = 0;
    for (std::size_t i = 0; i < count; ++i) offsets_[i + 1] = offsets_[i] + counts_[i];
    entries_.resize(offsets_[count]);
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i)
        std::copy_n(rows_.data() + static_cast<std::size_t>(i) * stride, counts_[i],
                    entries_.data() + offsets_[i]);
}

void Neighbours::buildLanePairs(const double* x, const double* y, std::size_t count, double reach,
                                double width, double height) {
    search(x, y, count, reach, width, height);
    const std::size_t blocks = (count + 1) / 2;
    const std::size_t stride = capacity_ + 1;
    // Partners in cell order: neighbouring particles see about the same number of neighbours, so the
    // padding of the shorter row shrinks (index order pairs particles poured in one after the other).
    const std::uint32_t* order = cells_.order().data();
    blockParticles_.resize(2 * blocks);
    blockStart_.resize(blocks + 1);
    blockStart_[0] = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
        const std::uint32_t first = order[2 * b], second = order[std::min(2 * b + 1, count - 1)];
        blockParticles_[2 * b] = first;
        blockParticles_[2 * b + 1] = second;
        blockStart_[b + 1] = blockStart_[b] + std::max(counts_[first], counts_[second]);
    }
    laneEntries_.resize(2 * static_cast<std::size_t>(blockStart_[blocks]));
    rowStart_.resize(count);
    const std::uint32_t *rows = rows_.data(), *counts = counts_.data(), *blockStart = blockStart_.data(),
                        *particles = blockParticles_.data();
    std::uint32_t *lanes = laneEntries_.data(), *rowStart = rowStart_.data();
    const auto blockCount = static_cast<long long>(blocks);
#pragma omp parallel for schedule(static) if (static_cast <long long>(count) >= kParallelMinParticles)
    for (long long b = 0; b < blockCount; ++b) {
        const std::uint32_t length = blockStart[b + 1] - blockStart[b];
        const std::size_t first = 2 * static_cast<std::size_t>(blockStart[b]);
        for (int lane = 1; lane >= 0; --lane) { // lane 0 last: a lone particle's row starts in lane 0
            const std::uint32_t i = particles[2 * b + lane];
            const std::uint32_t* row = rows + std::size_t{i} * stride;
            std::uint32_t* slots = lanes + first + lane;
            for (std::uint32_t t = 0; t < length; ++t) slots[2 * t] = t < counts[i] ? row[t] : i;
            rowStart[i] = static_cast<std::uint32_t>(first + lane);
        }
    }
}

} // namespace pl::pbf
