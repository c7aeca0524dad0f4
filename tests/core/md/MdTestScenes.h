// Small gas scenes shared by the MD tests.
#pragma once

#include "md/MdModel.h"

#include <vector>

namespace pl::test {

// A gas model reset from the defaults plus these parameter values.
MdModel makeGas(const ParamValues& values, std::uint64_t seed = 1, std::vector<Obstacle> obstacles = {});

// Total momentum recomputed from the state.
std::pair<double, double> totalMomentum(const MdModel& model);

// Root-mean-square distance between the positions of two states of the same particles (matched by id).
double rmsDistance(const MdState& a, const MdState& b);

} // namespace pl::test
