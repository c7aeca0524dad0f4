// Helpers of the wind tunnel's physics tests: presets of the "tunnel" model, batch means for the standard
// error of correlated samples, a least-squares line, and QVERIFY_WITHIN, which logs and checks a comparison.
#pragma once

#include "common/Preset.h"
#include "dsmc/DsmcParams.h"

#include <QString>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace pl::tunnel_physics {

inline constexpr double kArgonMass = 39.948 * kAtomicMass; // the tunnel's default gas
inline const std::string kVhs = "vhs";

// The four sides' keys (left, right, bottom, top), e.g. sides("inflow", "outflow", "specular", "specular").
inline ParamValues sides(const std::string& left, const std::string& right, const std::string& bottom,
                         const std::string& top) {
    return {{"left", left}, {"right", right}, {"bottom", bottom}, {"top", top}};
}

inline Preset tunnelPreset(ParamValues params, const ParamValues& sideKeys = {},
                           std::vector<Obstacle> obstacles = {}, std::uint64_t seed = 7) {
    params.insert(sideKeys.begin(), sideKeys.end());
    Preset p;
    p.model = "tunnel";
    p.seed = seed;
    p.params = std::move(params);
    p.obstacles = std::move(obstacles);
    return p;
}

// Means of consecutive batches of samples; their spread gives the standard error of the overall mean
// with the correlation between nearby steps included (batches much longer than it).
struct BatchMeans {
    std::vector<double> values;
    double mean() const { return std::accumulate(values.begin(), values.end(), 0.0) / double(values.size()); }
    double standardError(int batches = 20) const {
        const std::size_t size = values.size() / std::size_t(batches);
        std::vector<double> means;
        for (int b = 0; b < batches; ++b)
            means.push_back(std::accumulate(values.begin() + b * size, values.begin() + (b + 1) * size, 0.0) /
                            double(size));
        const double m = std::accumulate(means.begin(), means.end(), 0.0) / batches;
        double var = 0;
        for (double x : means) var += (x - m) * (x - m);
        return std::sqrt(var / (batches - 1) / batches);
    }
};

// Least-squares line y = a + b x.
struct Line {
    double intercept = 0, slope = 0;
};
inline Line fitLine(const std::vector<double>& x, const std::vector<double>& y) {
    const double n = double(x.size());
    const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n,
                 my = std::accumulate(y.begin(), y.end(), 0.0) / n;
    double sxy = 0, sxx = 0;
    for (std::size_t k = 0; k < x.size(); ++k)
        sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
    return {my - sxy / sxx * mx, sxy / sxx};
}

// The largest fall −dy/dx of a profile sampled every binWidth, each slope a least-squares line over the
// 2·half + 1 bins around a point.
inline double steepestFall(const std::vector<double>& profile, double binWidth, std::size_t half) {
    double steepest = 0;
    for (std::size_t b = half; b + half < profile.size(); ++b) {
        std::vector<double> xs, ys;
        for (std::size_t k = b - half; k <= b + half; ++k)
            xs.push_back(double(k) * binWidth), ys.push_back(profile[k]);
        steepest = std::max(steepest, -fitLine(xs, ys).slope);
    }
    return steepest;
}

// Where the 3-bin running mean of counts falls through level, searched from the last bin down; in bins
// from the first bin's left edge (linear between bin centres).
inline double fallingCrossing(const std::vector<double>& counts, double level) {
    const auto smooth = [&](std::size_t c) { return (counts[c - 1] + counts[c] + counts[c + 1]) / 3; };
    std::size_t c = counts.size() - 2;
    while (c > 1 && smooth(c) < level) --c;
    return double(c) + 0.5 + (smooth(c) - level) / (smooth(c) - smooth(c + 1));
}

inline QString describe(const char* what, double measured, double expected, double tolerance) {
    return QString("%1: measured %2, expected %3 ± %4").arg(what).arg(measured).arg(expected).arg(tolerance);
}

} // namespace pl::tunnel_physics

// Logs the comparison (one QINFO line per check, the run's measured values) and fails the test function
// unless |measured − expected| < tolerance.
#define QVERIFY_WITHIN(what, measured, expected, tolerance)                                                  \
    do {                                                                                                     \
        const double measuredValue = (measured), expectedValue = (expected), allowed = (tolerance);          \
        const QString line = pl::tunnel_physics::describe(what, measuredValue, expectedValue, allowed);      \
        qInfo().noquote() << line;                                                                           \
        QVERIFY2(std::abs(measuredValue - expectedValue) < allowed, qPrintable(line));                       \
    } while (false)
