// The contiguous block of particles each OpenMP thread owns inside a parallel region, with block edges
// on multiples of kThreadBlock: SIMD loops then see the same pairs of particles at any thread count,
// which keeps results bit-identical between 1 and 2 threads even where vector and scalar code differ.
#pragma once

#include <omp.h>

#include <cstddef>

namespace pl::gas {

constexpr std::size_t kThreadBlock = 64;

struct ParticleRange {
    std::size_t begin, end;
};

// The calling thread's share of [0, count): blocks of kThreadBlock dealt out in order, the last
// thread taking the remainder. Outside a parallel region this is the whole range.
inline ParticleRange threadRange(std::size_t count) {
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t blocks = (count + kThreadBlock - 1) / kThreadBlock;
    const std::size_t first = blocks * thread / threads, last = blocks * (thread + 1) / threads;
    const std::size_t begin = first * kThreadBlock, end = last * kThreadBlock;
    return {begin < count ? begin : count, end < count ? end : count};
}

} // namespace pl::gas
