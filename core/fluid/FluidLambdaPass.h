// The λ pass's loop over lane-pair blocks (FluidModel::computeLambdas), in three builds: the SSE2 one of
// common/Lanes.h, one that evaluates two slots of a block (four pairs) per AVX instruction where the CPU
// has AVX, and one that evaluates four slots (eight pairs) per AVX-512 instruction where it has AVX-512F.
// The square root and the division set this pass's speed (BENCHMARKS.md, "Limits"): a 256-bit vsqrtpd or
// vdivpd costs about what a 128-bit one does, and on a CPU with a full 512-bit datapath (AMD Zen 5) a
// 512-bit one again the same. Every pair gets exactly the scalar operations (no FMA: this file is
// compiled with -ffp-contract=off, and the vector square roots and divisions are correctly rounded), and
// the sums still add slot by slot in row order, so the results are bit-identical to the SSE2 loop and to
// the scalar code.
#pragma once

#include "FluidKernels.h"

#include <cstddef>
#include <cstdint>

namespace pl::fluid {

// What the λ pass reads and writes, in solver numbers.
struct LambdaArrays {
    const double* px;
    const double* py;
    const std::uint32_t* blockStart;
    const std::uint32_t* lanes;
    double* lambda;
    double* constraint;
    double* pairGradX;
    double* pairGradY;
    double* gradSumX;
    double* gradSumY;
    double* scorrSumX;
    double* scorrSumY;
    long long count;    // particles
    const double* bias; // old compression max(C_i(x), 0) subtracted from C_i
                        // (FluidModel::solveNewCompression), or nullptr
};

struct LambdaConstants {
    LaneKernels kernels;
    double selfWeight, inverseRest, epsilon;
    bool compressionOnly; // λ from max(C_i, 0): the constraint ρ_i ≤ ρ₀ (FluidParams::compressionOnly)
};

// Blocks [first, last) of the pass; lambdaBlocks() picks the build the CPU runs.
using LambdaBlocksFunction = void (*)(const LambdaArrays&, const LambdaConstants&, long long first,
                                      long long last);
LambdaBlocksFunction lambdaBlocks();
// Each build by name, for the test that compares them: a wide one is nullptr where the CPU lacks it.
LambdaBlocksFunction lambdaBlocksSse2();
LambdaBlocksFunction lambdaBlocksAvx();
LambdaBlocksFunction lambdaBlocksAvx512();

} // namespace pl::fluid
