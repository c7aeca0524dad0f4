// Grids of sweep settings.
#pragma once

#include <cmath>
#include <vector>

namespace pl::methods {

// count values from first to last, equally spaced in log (first·(last/first)^(i/(count−1))).
inline std::vector<double> logSpaced(double first, double last, int count) {
    std::vector<double> v;
    for (int i = 0; i < count; ++i)
        v.push_back(first * std::pow(last / first, count > 1 ? i / (count - 1.0) : 0.0));
    return v;
}

} // namespace pl::methods
