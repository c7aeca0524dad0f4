// Neighbour lists for the fluid, rebuilt every step from the predicted positions: one pass per particle
// over the 3×3 cell block into a fixed-capacity row (as a GPU kernel fills them), then packed into CSR
// rows. Cell-ordered copies of the positions make each scanned block row one contiguous read.
#pragma once

#include "common/CellList.h"

#include <cstdint>
#include <vector>

namespace pl::pbf {

class Neighbours {
public:
    // Lists every j ≠ i with |x_i − x_j| < reach, in cell order; deterministic for any thread count.
    void build(const double* x, const double* y, std::size_t count, double reach, double width,
               double height);

    // Neighbours of i are entries()[offsets()[i] … offsets()[i + 1]).
    const std::uint32_t* offsets() const { return offsets_.data(); }
    const std::uint32_t* entries() const { return entries_.data(); }
    std::size_t pairs() const { return entries_.size(); }

private:
    CellList cells_;
    std::vector<double> sortedX_, sortedY_;
    std::vector<std::uint32_t> rows_, counts_, offsets_, entries_;
    std::uint32_t capacity_ = 32;
};

} // namespace pl::pbf
