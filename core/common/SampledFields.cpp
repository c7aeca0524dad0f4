// Reading a sampled field at a point and along a line: the click probe's and the profile dock's lookups
// (the value of the cell holding each point, no interpolation, so a profile shows what was measured).
#include "SampledFields.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pl {

double FieldGrid::at(double x, double y) const {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    if (nx <= 0 || ny <= 0 || values.size() != std::size_t(nx) * std::size_t(ny)) return kNaN;
    // Closed on every side (NaN coordinates fail the test too); the right and top edges belong to the
    // last column and row.
    if (!(x >= left && x <= right && y >= bottom && y <= top)) return kNaN;
    const int i = std::clamp(int(std::floor((x - left) / dx())), 0, nx - 1);
    const int j = std::clamp(int(std::floor((y - bottom) / dy())), 0, ny - 1);
    return values[std::size_t(j) * std::size_t(nx) + std::size_t(i)];
}

FieldProfile profileAlong(const FieldGrid& grid, double x0, double y0, double x1, double y1, int samples) {
    if (samples < 2) throw std::invalid_argument("profileAlong: a profile needs at least 2 samples");
    FieldProfile profile;
    profile.choice = grid.choice;
    profile.distance.reserve(std::size_t(samples));
    profile.values.reserve(std::size_t(samples));
    const double length = std::hypot(x1 - x0, y1 - y0);
    for (int k = 0; k < samples; ++k) {
        const double t = double(k) / double(samples - 1);
        // (1 − t)·a + t·b lands exactly on both ends.
        const double x = (1.0 - t) * x0 + t * x1, y = (1.0 - t) * y0 + t * y1;
        profile.distance.push_back(t * length);
        profile.values.push_back(grid.at(x, y));
    }
    return profile;
}

} // namespace pl
