// Small gas scenes shared by the MD tests.
#pragma once

#include "gas/GasModel.h"

#include <vector>

namespace pl::test {

// A gas model reset from the defaults plus these parameter values.
GasModel makeGas(const ParamValues& values, std::uint64_t seed = 1, std::vector<Obstacle> obstacles = {});

// Total momentum recomputed from the state.
std::pair<double, double> totalMomentum(const GasModel& model);

// Root-mean-square distance between the positions of two states of the same particles (matched by id).
double rmsDistance(const GasState& a, const GasState& b);

} // namespace pl::test
