// Neighbour lists for the fluid, rebuilt every step from the predicted positions (the paper's Algorithm 1
// finds neighbours once per step and keeps them through the solver iterations): one branch-free pass per
// particle over the 3×3 cell block into a fixed-capacity row (as a GPU kernel fills them), over
// cell-ordered copies of the positions so each scanned block row is one contiguous read. The rows are then
// packed either into CSR rows or into lane pairs for the two-wide pair passes of PbfSolver.cpp.
#pragma once

#include "common/CellList.h"

#include <cstdint>
#include <vector>

namespace pl::pbf {

class Neighbours {
public:
    // Lists every j ≠ i with |x_i − x_j| < reach, in cell order; deterministic for any thread count.
    // CSR rows: neighbours of i are entries()[offsets()[i] … offsets()[i + 1]).
    void build(const double* x, const double* y, std::size_t count, double reach, double width,
               double height);
    const std::uint32_t* offsets() const { return offsets_.data(); }
    const std::uint32_t* entries() const { return entries_.data(); }

    // The same rows, in the same order, as lane pairs: block b holds the particles blockParticles()[2b]
    // and blockParticles()[2b + 1], taken in cell order so that the two are neighbours with rows of about
    // the same length. Their rows are interleaved slot by slot, laneEntries()[2 (blockStart()[b] + t) +
    // lane] being neighbour t of the block's particle in that lane. The shorter row of a block is padded
    // with the particle itself, at distance 0, where every kernel is zero. An odd count leaves the last
    // block with one particle in both lanes. Each lane sums its own row in row order, so which particles
    // share a block changes no bit of any sum, only how many padded slots there are.
    void buildLanePairs(const double* x, const double* y, std::size_t count, double reach, double width,
                        double height);
    std::size_t blocks() const { return blockStart_.empty() ? 0 : blockStart_.size() - 1; }
    const std::uint32_t* blockStart() const { return blockStart_.data(); }
    const std::uint32_t* blockParticles() const { return blockParticles_.data(); }
    const std::uint32_t* laneEntries() const { return laneEntries_.data(); }
    std::size_t laneSlots() const { return laneEntries_.size(); }  // 2 × blockStart()[blocks()]
    const std::uint32_t* counts() const { return counts_.data(); } // real neighbours of each particle
    // Particle i's row in lane form: laneEntries()[rowStart()[i] + 2 t] for t < counts()[i].
    const std::uint32_t* rowStart() const { return rowStart_.data(); }

private:
    void search(const double* x, const double* y, std::size_t count, double reach, double width,
                double height);
    CellList cells_;
    std::vector<double> sortedX_, sortedY_;
    std::vector<std::uint32_t> rows_, counts_, offsets_, entries_;
    std::vector<std::uint32_t> blockStart_, blockParticles_, laneEntries_, rowStart_;
    std::uint32_t capacity_ = 32;
};

} // namespace pl::pbf
