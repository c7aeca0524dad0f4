// Thermal palette stops, as in the gas seed's WGSL palette().
#include "ThermalPalette.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pl::ui {

namespace {
struct Rgb {
    double r, g, b;
};
constexpr std::array<Rgb, 10> kStops{{{0.91, 0.93, 0.96},
                                      {0.72, 0.77, 0.86},
                                      {0.43, 0.53, 0.69},
                                      {0.18, 0.27, 0.47},
                                      {0.21, 0.52, 0.60},
                                      {0.51, 0.65, 0.47},
                                      {0.79, 0.65, 0.31},
                                      {0.78, 0.49, 0.23},
                                      {0.70, 0.22, 0.37},
                                      {0.29, 0.10, 0.16}}};
} // namespace

QColor thermalColor(double t) {
    const double x = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 9.0;
    const auto i0 = static_cast<std::size_t>(std::floor(x));
    const auto i1 = std::min<std::size_t>(i0 + 1, 9);
    const double a = x - static_cast<double>(i0);
    const Rgb& p = kStops[i0];
    const Rgb& q = kStops[i1];
    return QColor::fromRgbF(static_cast<float>(p.r + a * (q.r - p.r)),
                            static_cast<float>(p.g + a * (q.g - p.g)),
                            static_cast<float>(p.b + a * (q.b - p.b)));
}

} // namespace pl::ui
