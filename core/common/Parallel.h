// When loops over particles are worth running on several threads.
#pragma once

namespace pl {

// A parallel region costs a few microseconds to fork and join (far more when the cores are shared with
// another busy process), while a particle's work in one loop is nanoseconds: below this count every
// loop runs on the calling thread. Results are identical either way (gather form, serial sums).
constexpr long long kParallelMinParticles = 2048;

} // namespace pl
