// Verlet neighbour lists (Verlet 1967; as in LAMMPS): for each particle, the others within
// cutoff + skin, found through the cell list and reused until some particle has moved more than
// skin / 2 since the build. Stored compactly (CSR: offsets and packed entries), since a dilute gas has
// about one neighbour per particle. Each entry carries one byte of payload (e.g. "this pair was in
// contact") that survives rebuilds and reorderings for pairs present in both lists.
#pragma once

#include "CellList.h"

#include <cstdint>
#include <vector>

namespace pl {

class NeighbourList {
public:
    // Lists every j ≠ i with |r_i − r_j| < reach, reach = cutoff + skin, using cells over the box
    // [x0, x1] × [y0, y1] no smaller than reach. Deterministic for any thread count.
    void build(const double* x, const double* y, std::size_t count, double cutoff, double skin, double x0,
               double y0, double x1, double y1);
    // The same build, called by every thread of an enclosing parallel region (or outside any): its loops
    // are orphaned work-sharing constructs, so a step can rebuild without forking threads of its own.
    // Ends with a barrier; the result does not depend on the number of threads.
    void buildInRegion(const double* x, const double* y, std::size_t count, double cutoff, double skin,
                       double x0, double y0, double x1, double y1);

    // Largest squared displacement since the build, compared with (skin / 2)²: a pair outside the
    // list cannot have come closer than cutoff while this is false.
    bool needsRebuild(const double* x, const double* y, std::size_t count) const;
    bool needsRebuild(double maxDisplacementSquared) const {
        return !valid_ || maxDisplacementSquared > 0.25 * skin_ * skin_;
    }
    void invalidate() { valid_ = false; }
    bool valid() const { return valid_; }
    // Follows a reordering of the particles (newToOld[n] = old index of new particle n): rows, entries,
    // payload and build positions are renumbered, so the list stays valid without a rebuild.
    void permute(const std::vector<std::uint32_t>& newToOld);

    // The whole list, for snapshots: a list that was permuted is not what a fresh build would give, so
    // an exact continuation needs these rows as they are.
    struct Contents {
        std::vector<std::uint32_t> offsets, entries;
        std::vector<std::uint8_t> payload;
        std::vector<double> builtX, builtY;
        double skin = 0.0;
        bool valid = false;
    };
    Contents contents() const { return {offsets_, entries_, payload_, builtX_, builtY_, skin_, valid_}; }
    void restore(Contents c);

    // Neighbours of i are entries()[offsets()[i] … offsets()[i + 1]).
    const std::uint32_t* offsets() const { return offsets_.data(); }
    const std::uint32_t* entries() const { return entries_.data(); }
    // The row (particle i) of each entry, so a loop can run over all pairs in one flat sweep instead of
    // one short inner loop per particle, whose varying trip count costs a mispredicted branch each.
    const std::uint32_t* rowOf() const { return rowOf_.data(); }
    std::uint8_t* payload() { return payload_.data(); }
    const double* builtX() const { return builtX_.data(); }
    const double* builtY() const { return builtY_.data(); }

private:
    CellList cells_; // the grid's geometry; the binning is done here, fused with the search
    void fillRows(); // rowOf_ from offsets_
    void binParticles(const double* x, const double* y, std::size_t count); // in one omp single
    // Cell of each particle and the positions in cell order, so the 3×3 search reads them contiguously.
    std::vector<std::uint32_t> cellX_, cellY_, cellStart_, cellOrder_, cellCursor_;
    std::vector<double> cellOrderX_, cellOrderY_;
    // Each thread's rows, found in one pass and then copied to their place in entries_.
    std::vector<std::vector<std::uint32_t>> threadEntries_;
    std::vector<std::uint32_t> threadTotals_;
    bool carrying_ = false;
    std::vector<std::uint32_t> offsets_, entries_, rowOf_;
    std::vector<std::uint8_t> payload_;
    std::vector<std::uint32_t> oldOffsets_, oldEntries_;
    std::vector<std::uint8_t> oldPayload_;
    std::vector<double> builtX_, builtY_;
    double skin_ = 0.0;
    bool valid_ = false;
};

} // namespace pl
