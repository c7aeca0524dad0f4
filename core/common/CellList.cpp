// Counting-sort construction of the cell list.
#include "CellList.h"
#include "Parallel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pl {

namespace {
constexpr double kMaxCells = 1 << 26; // 64 M cells: beyond this the grid costs more than the particles
}

void CellList::configure(double x0, double y0, double x1, double y1, double minCellSize) {
    if (!(minCellSize > 0) || !(x1 > x0) || !(y1 > y0))
        throw std::invalid_argument("cell list needs a non-empty box");
    double size = minCellSize;
    // Grow cells until the grid is of bounded size; correctness only needs size ≥ the interaction range.
    while (std::ceil((x1 - x0) / size) * std::ceil((y1 - y0) / size) > kMaxCells) size *= 2;
    x0_ = x0;
    y0_ = y0;
    size_ = size;
    inv_ = 1.0 / size;
    nx_ = std::max(1, static_cast<int>(std::ceil((x1 - x0) * inv_)));
    ny_ = std::max(1, static_cast<int>(std::ceil((y1 - y0) * inv_)));
    start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
}

int CellList::cellX(double x) const {
    const double cx = std::floor((x - x0_) * inv_);
    if (!(cx > 0)) return 0; // also catches NaN, which the model reports as a blow-up
    return cx >= nx_ - 1 ? nx_ - 1 : static_cast<int>(cx);
}

int CellList::cellY(double y) const {
    const double cy = std::floor((y - y0_) * inv_);
    if (!(cy > 0)) return 0;
    return cy >= ny_ - 1 ? ny_ - 1 : static_cast<int>(cy);
}

int CellList::cellOf(double x, double y) const {
    return cellY(y) * nx_ + cellX(x);
}

void CellList::build(const double* x, const double* y, std::size_t count) {
    cellOfParticle_.resize(count);
    order_.resize(count);
    const auto n = static_cast<long long>(count);
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) cellOfParticle_[i] = static_cast<std::uint32_t>(cellOf(x[i], y[i]));

    std::fill(start_.begin(), start_.end(), 0u);
    for (std::size_t i = 0; i < count; ++i) ++start_[cellOfParticle_[i] + 1];
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    cursor_.assign(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < count; ++i)
        order_[cursor_[cellOfParticle_[i]]++] = static_cast<std::uint32_t>(i);
}

} // namespace pl
