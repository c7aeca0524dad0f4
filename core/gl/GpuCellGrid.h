// Counting-sort cell list on the GPU: a model's own pass counts each particle into its cell with an
// atomic (keeping the returned slot), scan() turns the counts into cell starts, and the model's scatter
// pass writes each particle to start[cell] + slot. Particles then sit in cell order, so a cell's
// neighbours are a few contiguous ranges.
#pragma once

#include "GlProgram.h"

namespace pl::gl {

class GpuCellGrid {
public:
    GpuCellGrid();

    // A grid over the rectangle with cells of at least minSide, and no smaller than needed for about
    // particlesPerCell particles per cell (fewer cells: a shorter scan, more pairs per cell).
    void configure(double left, double bottom, double width, double height, double minSide,
                   std::size_t particles, double particlesPerCell);
    // cellOrigin, cellInverseSide, cellDims of common/cells.glsl, on the program in use.
    void setUniforms(ComputeProgram& program) const;

    std::size_t cells() const { return static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_); }
    int nx() const { return nx_; }
    int ny() const { return ny_; }
    double side() const { return side_; }
    Buffer& counts() { return counts_; } // cells + 1 entries; zero between sorts
    Buffer& starts() { return starts_; } // cells + 1 entries; starts[cells] = particles
    // Exclusive prefix sum of the counts into the starts, zeroing the counts. Ends with a barrier.
    void scan();
    // Dispatches the last scan() issued (for counting dispatches per step).
    int scanDispatches() const { return scanDispatches_; }

private:
    void scanLevel(Buffer& input, Buffer& output, std::size_t count, std::size_t level, bool clearInput);

    ComputeProgram scan_, add_;
    Buffer counts_, starts_;
    std::vector<Buffer> blockSums_, blockOffsets_;
    double left_ = 0, bottom_ = 0, side_ = 1;
    int nx_ = 1, ny_ = 1;
    int scanDispatches_ = 0;
};

} // namespace pl::gl
