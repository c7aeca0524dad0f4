// Neighbour lists for the fluid, rebuilt every step from the predicted positions (the paper's Algorithm 1
// finds neighbours once per step and keeps them through the solver iterations): one branch-free pass per
// particle over the 3×3 cell block into a fixed-capacity row (FluidRowScan.h; as a GPU kernel fills
// them), over cell-ordered copies of the positions so each scanned block row is one contiguous read. The
// rows are then packed either into CSR rows or into lane pairs for the two-wide pair passes of
// FluidSolver.cpp.
//
// Two numberings. Particle numbers are the model's (state order). Solver numbers are the particles in
// cell order, particle order()[k] being solver particle k: there each thread's share of a pass is one
// stretch of the box and of memory, so its writes share no cache line with the other thread's and a
// particle's neighbours lie in nearby lines. A row lists the same neighbours in the same (cell) order in
// either numbering, so sums over rows have the same bits.
#pragma once

#include "common/CellList.h"

#include <cstdint>
#include <vector>

namespace pl::fluid {

class Neighbours {
public:
    // Lists every j ≠ i with |x_i − x_j| < reach, in cell order; deterministic for any thread count.
    // CSR rows in particle numbers: neighbours of i are entries()[offsets()[i] … offsets()[i + 1]).
    void build(const double* x, const double* y, std::size_t count, double reach, double width,
               double height);
    const std::uint32_t* offsets() const { return offsets_.data(); }
    const std::uint32_t* entries() const { return entries_.data(); }

    // The same rows in solver numbers, as lane pairs: block b holds solver particles 2b and 2b + 1,
    // neighbours in cell order with rows of about the same length. Their rows are interleaved slot by
    // slot, laneEntries()[2 (blockStart()[b] + t) + lane] being neighbour t of solver particle 2b + lane.
    // The shorter row of a block is padded with the particle itself, at distance 0, where every kernel
    // is zero. An odd count leaves the last block with one particle in both lanes. Each lane sums its
    // own row in row order, so which particles share a block changes no bit of any sum, only how many
    // padded slots there are.
    void buildLanePairs(const double* x, const double* y, std::size_t count, double reach, double width,
                        double height);
    std::size_t blocks() const { return blockStart_.empty() ? 0 : blockStart_.size() - 1; }
    const std::uint32_t* blockStart() const { return blockStart_.data(); }
    const std::uint32_t* laneEntries() const { return laneEntries_.data(); }
    std::size_t laneSlots() const { return laneEntries_.size(); } // 2 × blockStart()[blocks()]
    // Solver particle k: its real neighbours, and the first slot of its row (the row continues at
    // stride 2: laneEntries()[rowStart(k) + 2 t] for t < counts()[k]).
    const std::uint32_t* counts() const { return counts_.data(); }
    std::size_t rowStart(std::size_t k) const { return 2 * std::size_t{blockStart_[k / 2]} + k % 2; }
    // Solver number → particle number, and back; the positions of the last build in solver numbers.
    const std::uint32_t* order() const { return cells_.order().data(); }
    const std::uint32_t* rank() const { return rank_.data(); }
    const double* sortedX() const { return sortedX_.data(); }
    const double* sortedY() const { return sortedY_.data(); }

    // The blocks [first, last) that the calling thread of an OpenMP region takes in a pair pass: equal
    // shares of the slots (plus one per block, for its closing arithmetic) rather than of the blocks, so
    // that the thread with the dense bottom of a tank does not keep the other waiting (the filled write-up
    // tank's first half of the blocks holds 1.4 times the slots of the second). Which thread sums a block
    // changes no bit. Outside a parallel region: all blocks.
    struct BlockRange {
        long long first, last;
    };
    BlockRange threadBlocks() const;

private:
    void search(const double* x, const double* y, std::size_t count, double reach, double width,
                double height);
    CellList cells_;
    std::vector<double> sortedX_, sortedY_;
    std::vector<std::uint32_t> rows_, counts_, rank_, offsets_, entries_, blockStart_, laneEntries_;
    std::uint32_t capacity_ = 32;
};

} // namespace pl::fluid
