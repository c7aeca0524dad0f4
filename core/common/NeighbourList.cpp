// Neighbour list construction: a gather over the 3×3 cell block, with a per-particle capacity that
// grows when a particle has more neighbours than it.
#include "NeighbourList.h"

#include "Parallel.h"

#include <algorithm>
#include <cmath>

namespace pl {

void NeighbourList::build(const double* x, const double* y, std::size_t count, double cutoff, double skin,
                          double x0, double y0, double x1, double y1) {
    const double reach = cutoff + skin;
    skin_ = skin;
    // Keep the previous lists to carry each surviving pair's payload over.
    const std::size_t oldStride = stride_;
    const bool carry = valid_ && counts_.size() == count;
    if (carry) {
        oldCounts_.swap(counts_);
        oldEntries_.swap(entries_);
        oldPayload_.swap(payload_);
    }
    // About one particle per cell keeps the grid cheap in dilute gases; never smaller than the reach.
    const double area = (x1 - x0) * (y1 - y0);
    cells_.configure(x0, y0, x1, y1, std::max(reach, std::sqrt(area / std::max<double>(1.0, count))));
    cells_.build(x, y, count);
    const auto& order = cells_.order();
    const auto& start = cells_.cellStart();
    const int nx = cells_.cellsX(), ny = cells_.cellsY();
    const double reach2 = reach * reach;
    const auto n = static_cast<long long>(count);
    counts_.assign(count, 0);

    for (;;) {
        entries_.resize(count * stride_);
        std::uint32_t widest = 0;
#pragma omp parallel for schedule(static) reduction(max : widest) if(n >= kParallelMinParticles)
        for (long long i = 0; i < n; ++i) {
            const int cx = cells_.cellX(x[i]), cy = cells_.cellY(y[i]);
            std::uint32_t found = 0;
            std::uint32_t* out = entries_.data() + static_cast<std::size_t>(i) * stride_;
            for (int row = std::max(cy - 1, 0); row <= std::min(cy + 1, ny - 1); ++row) {
                const std::uint32_t first = start[row * nx + std::max(cx - 1, 0)];
                const std::uint32_t last = start[row * nx + std::min(cx + 1, nx - 1) + 1];
                for (std::uint32_t k = first; k < last; ++k) {
                    const std::uint32_t j = order[k];
                    const double dx = x[i] - x[j], dy = y[i] - y[j];
                    if (j == static_cast<std::uint32_t>(i) || dx * dx + dy * dy >= reach2) continue;
                    if (found < stride_) out[found] = j;
                    ++found;
                }
            }
            counts_[i] = found;
            widest = std::max(widest, found);
        }
        if (widest <= stride_) break;
        stride_ = std::max<std::size_t>(2 * stride_, widest + 4); // rare: a denser region than before
    }

    payload_.assign(count * stride_, 0);
    if (carry) {
#pragma omp parallel for schedule(static) if(n >= kParallelMinParticles)
        for (long long i = 0; i < n; ++i) {
            const std::uint32_t* oldList = oldEntries_.data() + static_cast<std::size_t>(i) * oldStride;
            const std::uint8_t* oldBytes = oldPayload_.data() + static_cast<std::size_t>(i) * oldStride;
            for (std::uint32_t a = 0; a < counts_[i]; ++a) {
                const std::uint32_t j = entries_[static_cast<std::size_t>(i) * stride_ + a];
                for (std::uint32_t b = 0; b < oldCounts_[i]; ++b)
                    if (oldList[b] == j) payload_[static_cast<std::size_t>(i) * stride_ + a] = oldBytes[b];
            }
        }
    }
    builtX_.assign(x, x + count);
    builtY_.assign(y, y + count);
    valid_ = true;
    ++builds_;
}

void NeighbourList::permute(const std::vector<std::uint32_t>& newToOld) {
    if (!valid_) return;
    const std::size_t count = newToOld.size();
    std::vector<std::uint32_t> oldToNew(count);
    for (std::size_t n = 0; n < count; ++n) oldToNew[newToOld[n]] = static_cast<std::uint32_t>(n);
    oldCounts_.swap(counts_);
    oldEntries_.swap(entries_);
    oldPayload_.swap(payload_);
    counts_.resize(count);
    entries_.resize(count * stride_);
    payload_.resize(count * stride_);
    const auto total = static_cast<long long>(count);
#pragma omp parallel for schedule(static) if(total >= kParallelMinParticles)
    for (long long n = 0; n < total; ++n) {
        const std::size_t from = newToOld[n];
        counts_[n] = oldCounts_[from];
        for (std::uint32_t k = 0; k < counts_[n]; ++k) {
            entries_[static_cast<std::size_t>(n) * stride_ + k] = oldToNew[oldEntries_[from * stride_ + k]];
            payload_[static_cast<std::size_t>(n) * stride_ + k] = oldPayload_[from * stride_ + k];
        }
    }
    std::vector<double> bx(count), by(count);
    for (std::size_t n = 0; n < count; ++n) bx[n] = builtX_[newToOld[n]], by[n] = builtY_[newToOld[n]];
    builtX_.swap(bx);
    builtY_.swap(by);
}

bool NeighbourList::needsRebuild(const double* x, const double* y, std::size_t count) const {
    if (!valid_ || builtX_.size() != count) return true;
    double worst = 0.0;
    const auto n = static_cast<long long>(count);
#pragma omp parallel for schedule(static) reduction(max : worst) if(n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        const double dx = x[i] - builtX_[i], dy = y[i] - builtY_[i];
        worst = std::max(worst, dx * dx + dy * dy);
    }
    return needsRebuild(worst);
}

} // namespace pl
