// Uniform-grid cell list by counting sort: particle indices grouped by cell with cell start offsets.
// Shared by the gas and fluid models; the GPU backends build the same layout.
#pragma once

#include <cstdint>
#include <vector>

namespace pl {

class CellList {
public:
    // Grid over [x0, x1] × [y0, y1] with square cells no smaller than minCellSize. Points outside the
    // rectangle are clamped into the edge cells, so a search of the 3×3 block stays correct for them.
    void configure(double x0, double y0, double x1, double y1, double minCellSize);

    // Counting sort: cell of each point, counts, exclusive prefix sum, stable scatter. Deterministic.
    void build(const double* x, const double* y, std::size_t count);

    int cellsX() const { return nx_; }
    int cellsY() const { return ny_; }
    double cellSize() const { return size_; }
    int cellOf(double x, double y) const;
    int cellX(double x) const;
    int cellY(double y) const;

    // Particles of cell c are order()[cellStart()[c] .. cellStart()[c + 1]).
    const std::vector<std::uint32_t>& cellStart() const { return start_; }
    const std::vector<std::uint32_t>& order() const { return order_; }
    const std::vector<std::uint32_t>& cellOfParticle() const { return cellOfParticle_; }

private:
    double x0_ = 0, y0_ = 0, size_ = 1, inv_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<std::uint32_t> start_, order_, cellOfParticle_, cursor_;
};

} // namespace pl
