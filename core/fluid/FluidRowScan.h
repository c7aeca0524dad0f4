// The scan that fills the fluid's neighbour rows (Neighbours::search): for each particle in cell order,
// the candidates of its 3×3 cell block tested against the search radius and their solver numbers written
// to its fixed-capacity row in cell order. Two builds: SSE2 (two candidates per compare, the x86-64
// baseline) and, where the CPU has AVX-512F, eight candidates per compare with the ones within reach
// packed into the row by one compress. Both make each decision with the scalar test's operations
// (-ffp-contract=off for this file) and write the same rows, so the choice changes no bit.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pl::fluid {

struct RowScanInputs {
    const double* x; // positions in solver numbers (cell order)
    const double* y;
    const std::uint32_t* order;     // solver number → particle number
    const std::uint32_t* cellOf;    // cell of each particle (particle numbers)
    const std::uint32_t* cellStart; // first solver number of each cell; cellStart[cells] = count
    int cellsX, cellsY;
    double reach2;
    std::uint32_t capacity; // of a row; one spare slot beyond it takes the writes past the capacity
    std::uint32_t* rows;    // capacity + 1 slots per solver particle
    std::uint32_t* counts;  // neighbours found; above capacity, the row overflowed and is incomplete
};

// Rows [first, last); returns the largest count among them.
using RowScanFunction = std::uint32_t (*)(const RowScanInputs&, long long first, long long last);
RowScanFunction rowScan(); // the build this CPU runs
// Each build by name, for the test that compares them: the AVX-512 one is nullptr where the CPU lacks it.
RowScanFunction rowScanSse2();
RowScanFunction rowScanAvx512();

} // namespace pl::fluid
