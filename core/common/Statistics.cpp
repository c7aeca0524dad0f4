// The Maxwell–Boltzmann speed distributions, KS distance and power-law fits (least squares via Eigen).
#include "Statistics.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace pl {

double rayleighPdf(double v, double kT, double mass) {
    if (v < 0 || kT <= 0) return 0.0;
    const double a = mass / kT;
    return a * v * std::exp(-0.5 * a * v * v);
}

double rayleighCdf(double v, double kT, double mass) {
    if (v <= 0 || kT <= 0) return 0.0;
    return -std::expm1(-0.5 * mass * v * v / kT);
}

double maxwellSpeedPdf(double speed, double sigma2, double drift) {
    if (speed < 0 || sigma2 <= 0) return 0.0;
    const double sigma = std::sqrt(sigma2);
    if (drift * drift < 1e-12 * sigma2) // the u → 0 limit
        return 4.0 * std::numbers::pi * speed * speed * std::pow(2.0 * std::numbers::pi * sigma2, -1.5) *
               std::exp(-speed * speed / (2.0 * sigma2));
    const double norm = speed / (drift * std::sqrt(2.0 * std::numbers::pi) * sigma);
    return norm * (std::exp(-(speed - drift) * (speed - drift) / (2.0 * sigma2)) -
                   std::exp(-(speed + drift) * (speed + drift) / (2.0 * sigma2)));
}

double maxwellSpeedCdf(double speed, double sigma2) {
    if (speed <= 0) return 0.0;
    const double x = speed / std::sqrt(2.0 * sigma2);
    return std::erf(x) - 2.0 / std::sqrt(std::numbers::pi) * x * std::exp(-x * x);
}

double ksDistance(std::vector<double>& sample, const std::function<double(double)>& cdf) {
    if (sample.empty()) return 0.0;
    std::sort(sample.begin(), sample.end());
    const double n = static_cast<double>(sample.size());
    double d = 0.0;
    for (std::size_t i = 0; i < sample.size(); ++i) {
        const double f = cdf(sample[i]);
        d = std::max({d, (static_cast<double>(i) + 1.0) / n - f, f - static_cast<double>(i) / n});
    }
    return d;
}

double ksCritical(double n, double significance) {
    // Asymptotic Kolmogorov quantiles (docs/gas.md#kolmogorov-smirnov-test).
    const double c = significance <= 0.01 ? 1.628 : 1.358;
    return c / std::sqrt(n);
}

double ksTwoSampleDistance(std::vector<double>& a, std::vector<double>& b) {
    if (a.empty() || b.empty()) throw std::invalid_argument("a KS comparison needs two non-empty samples");
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    std::size_t i = 0, j = 0;
    double distance = 0;
    const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
    while (i < a.size() && j < b.size()) {
        const double v = std::min(a[i], b[j]); // step both empirical CDFs past every copy of v
        while (i < a.size() && a[i] <= v) ++i;
        while (j < b.size() && b[j] <= v) ++j;
        distance = std::max(distance, std::abs(static_cast<double>(i) / na - static_cast<double>(j) / nb));
    }
    return distance;
}

double ksTwoSamplePValue(double distance, double na, double nb) {
    const double ne = std::sqrt(na * nb / (na + nb));
    const double lambda = (ne + 0.12 + 0.11 / ne) * distance;
    if (lambda < 0.2) return 1.0; // the series converges slowly here, and the answer is 1 to 1e-6
    double sum = 0, sign = 1;
    for (int j = 1; j <= 100; ++j) {
        const double term = sign * std::exp(-2.0 * j * j * lambda * lambda);
        sum += term;
        if (std::abs(term) < 1e-12) break;
        sign = -sign;
    }
    return std::clamp(2.0 * sum, 0.0, 1.0);
}

double kurtosis(const std::vector<double>& values) {
    double mean = 0;
    for (double v : values) mean += v;
    mean /= static_cast<double>(values.size());
    double m2 = 0, m4 = 0;
    for (double v : values) {
        const double d2 = (v - mean) * (v - mean);
        m2 += d2;
        m4 += d2 * d2;
    }
    m2 /= static_cast<double>(values.size());
    m4 /= static_cast<double>(values.size());
    return m2 > 0 ? m4 / (m2 * m2) : std::numeric_limits<double>::quiet_NaN();
}

PowerLawFit fitPowerLaw(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size() || x.size() < 2)
        throw std::invalid_argument("power-law fit needs two or more points");
    Eigen::MatrixXd design(static_cast<Eigen::Index>(x.size()), 2);
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(x.size()));
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (x[i] <= 0 || y[i] <= 0) throw std::invalid_argument("power-law fit needs positive data");
        const auto r = static_cast<Eigen::Index>(i);
        design(r, 0) = 1.0;
        design(r, 1) = std::log(x[i]);
        rhs(r) = std::log(y[i]);
    }
    const Eigen::Vector2d coef = design.colPivHouseholderQr().solve(rhs);
    return {coef(1), std::exp(coef(0))};
}

} // namespace pl
