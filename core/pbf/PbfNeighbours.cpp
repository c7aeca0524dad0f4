// Single-pass neighbour search into fixed-capacity rows, grown and repeated on overflow.
#include "PbfNeighbours.h"

#include "common/Parallel.h"

#include <algorithm>

namespace pl::pbf {

void Neighbours::build(const double* x, const double* y, std::size_t count, double reach, double width,
                       double height) {
    cells_.configure(0.0, 0.0, width, height, reach);
    cells_.build(x, y, count);
    const auto n = static_cast<long long>(count);
    const std::uint32_t* order = cells_.order().data();
    const std::uint32_t* start = cells_.cellStart().data();
    sortedX_.resize(count);
    sortedY_.resize(count);
    counts_.resize(count);
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long k = 0; k < n; ++k) {
        sortedX_[k] = x[order[k]];
        sortedY_[k] = y[order[k]];
    }
    const double reach2 = reach * reach;
    const int nx = cells_.cellsX(), ny = cells_.cellsY();
    const double *sx = sortedX_.data(), *sy = sortedY_.data();
    for (;;) {
        rows_.resize(count * capacity_);
        std::uint32_t largest = 0;
        const std::uint32_t capacity = capacity_;
#pragma omp parallel for schedule(static) reduction(max : largest) if (n >= kParallelMinParticles)
        for (long long i = 0; i < n; ++i) {
            const double xi = x[i], yi = y[i];
            const int cx = cells_.cellX(xi), cy = cells_.cellY(yi);
            std::uint32_t* row = rows_.data() + static_cast<std::size_t>(i) * capacity;
            std::uint32_t found = 0;
            for (int r = std::max(cy - 1, 0); r <= std::min(cy + 1, ny - 1); ++r) {
                const std::uint32_t first = start[r * nx + std::max(cx - 1, 0)];
                const std::uint32_t last = start[r * nx + std::min(cx + 1, nx - 1) + 1];
                for (std::uint32_t k = first; k < last; ++k) {
                    const double dx = xi - sx[k], dy = yi - sy[k];
                    if (dx * dx + dy * dy >= reach2 || order[k] == static_cast<std::uint32_t>(i)) continue;
                    if (found < capacity) row[found] = order[k];
                    ++found;
                }
            }
            counts_[i] = found;
            largest = std::max(largest, found);
        }
        if (largest <= capacity_) break;
        capacity_ = largest + largest / 4; // rare: a denser clump than ever before
    }
    offsets_.resize(count + 1);
    offsets_[0] = 0;
    for (std::size_t i = 0; i < count; ++i) offsets_[i + 1] = offsets_[i] + counts_[i];
    entries_.resize(offsets_[count]);
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i)
        std::copy_n(rows_.data() + static_cast<std::size_t>(i) * capacity_, counts_[i],
                    entries_.data() + offsets_[i]);
}

} // namespace pl::pbf
