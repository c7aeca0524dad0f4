// Neighbour list construction in two gather passes over the 3×3 cell block: count, then fill at the
// offsets of an exclusive prefix sum.
#include "NeighbourList.h"

#include "Parallel.h"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {

// Calls visit(j) for every j ≠ i within reach² of particle i.
template <class Visit>
void forEachNear(const CellList& cells, const double* x, const double* y, std::uint32_t i, double reach2,
                 Visit&& visit) {
    const auto& order = cells.order();
    const auto& start = cells.cellStart();
    const int nx = cells.cellsX(), ny = cells.cellsY();
    const int cx = cells.cellX(x[i]), cy = cells.cellY(y[i]);
    for (int row = std::max(cy - 1, 0); row <= std::min(cy + 1, ny - 1); ++row) {
        const std::uint32_t first = start[row * nx + std::max(cx - 1, 0)];
        const std::uint32_t last = start[row * nx + std::min(cx + 1, nx - 1) + 1];
        for (std::uint32_t k = first; k < last; ++k) {
            const std::uint32_t j = order[k];
            const double dx = x[i] - x[j], dy = y[i] - y[j];
            if (j != i && dx * dx + dy * dy < reach2) visit(j);
        }
    }
}

void exclusivePrefixSum(std::vector<std::uint32_t>& values) {
    std::uint32_t sum = 0;
    for (auto& v : values) {
        const std::uint32_t c = v;
        v = sum;
        sum += c;
    }
}

// Carries each surviving pair's payload byte from the previous lists of the same particle.
void carryPayload(std::size_t count, const std::vector<std::uint32_t>& offsets,
                  const std::vector<std::uint32_t>& entries, std::vector<std::uint8_t>& payload,
                  const std::vector<std::uint32_t>& oldOffsets, const std::vector<std::uint32_t>& oldEntries,
                  const std::vector<std::uint8_t>& oldPayload) {
    const auto n = static_cast<long long>(count);
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i)
        for (std::uint32_t a = offsets[i]; a < offsets[i + 1]; ++a)
            for (std::uint32_t b = oldOffsets[i]; b < oldOffsets[i + 1]; ++b)
                if (oldEntries[b] == entries[a]) payload[a] = oldPayload[b];
}

} // namespace

void NeighbourList::build(const double* x, const double* y, std::size_t count, double cutoff, double skin,
                          double x0, double y0, double x1, double y1) {
    const double reach = cutoff + skin;
    const double reach2 = reach * reach;
    skin_ = skin;
    const bool carry = valid_ && offsets_.size() == count + 1;
    if (carry) {
        oldOffsets_.swap(offsets_);
        oldEntries_.swap(entries_);
        oldPayload_.swap(payload_);
    }
    // About one particle per cell keeps the grid cheap in dilute gases; never smaller than the reach.
    const double area = (x1 - x0) * (y1 - y0);
    cells_.configure(x0, y0, x1, y1, std::max(reach, std::sqrt(area / std::max<double>(1.0, count))));
    cells_.build(x, y, count);
    const auto n = static_cast<long long>(count);

    offsets_.assign(count + 1, 0);
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        std::uint32_t found = 0;
        forEachNear(cells_, x, y, static_cast<std::uint32_t>(i), reach2, [&](std::uint32_t) { ++found; });
        offsets_[i] = found;
    }
    exclusivePrefixSum(offsets_);
    entries_.resize(offsets_[count]);
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        std::uint32_t* out = entries_.data() + offsets_[i];
        forEachNear(cells_, x, y, static_cast<std::uint32_t>(i), reach2,
                    [&](std::uint32_t j) { *out++ = j; });
    }
    fillRows();
    payload_.assign(entries_.size(), 0);
    if (carry) carryPayload(count, offsets_, entries_, payload_, oldOffsets_, oldEntries_, oldPayload_);
    builtX_.assign(x, x + count);
    builtY_.assign(y, y + count);
    valid_ = true;
}

void NeighbourList::restore(Contents c) {
    offsets_ = std::move(c.offsets);
    entries_ = std::move(c.entries);
    payload_ = std::move(c.payload);
    builtX_ = std::move(c.builtX);
    builtY_ = std::move(c.builtY);
    skin_ = c.skin;
    valid_ = c.valid;
    fillRows();
}

void NeighbourList::fillRows() {
    const auto n = static_cast<long long>(offsets_.empty() ? 0 : offsets_.size() - 1);
    rowOf_.resize(entries_.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i)
        for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k)
            rowOf_[k] = static_cast<std::uint32_t>(i);
}

void NeighbourList::permute(const std::vector<std::uint32_t>& newToOld) {
    if (!valid_) return;
    const std::size_t count = newToOld.size();
    std::vector<std::uint32_t> oldToNew(count);
    for (std::size_t m = 0; m < count; ++m) oldToNew[newToOld[m]] = static_cast<std::uint32_t>(m);
    oldOffsets_.swap(offsets_);
    oldEntries_.swap(entries_);
    oldPayload_.swap(payload_);
    offsets_.assign(count + 1, 0);
    for (std::size_t m = 0; m < count; ++m)
        offsets_[m] = oldOffsets_[newToOld[m] + 1] - oldOffsets_[newToOld[m]];
    exclusivePrefixSum(offsets_);
    entries_.resize(oldEntries_.size());
    payload_.resize(oldPayload_.size());
    const auto n = static_cast<long long>(count);
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long m = 0; m < n; ++m) {
        const std::uint32_t from = oldOffsets_[newToOld[m]];
        for (std::uint32_t k = 0; k < offsets_[m + 1] - offsets_[m]; ++k) {
            entries_[offsets_[m] + k] = oldToNew[oldEntries_[from + k]];
            payload_[offsets_[m] + k] = oldPayload_[from + k];
        }
    }
    fillRows();
    std::vector<double> bx(count), by(count);
    for (std::size_t m = 0; m < count; ++m) bx[m] = builtX_[newToOld[m]], by[m] = builtY_[newToOld[m]];
    builtX_.swap(bx);
    builtY_.swap(by);
}

bool NeighbourList::needsRebuild(const double* x, const double* y, std::size_t count) const {
    if (!valid_ || builtX_.size() != count) return true;
    double worst = 0.0;
    const auto n = static_cast<long long>(count);
#pragma omp parallel for schedule(static) reduction(max : worst) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        const double dx = x[i] - builtX_[i], dy = y[i] - builtY_[i];
        worst = std::max(worst, dx * dx + dy * dy);
    }
    return needsRebuild(worst);
}

} // namespace pl
