// Closed forms. The drifting-Maxwellian speed density integrates the 3D Gaussian over the sphere |v| = s:
// f(s) = s / (u √(2π) σ) [exp(−(s − u)²/2σ²) − exp(−(s + u)²/2σ²)].
#include "DsmcTheory.h"

#include <cmath>
#include <numbers>

namespace pl::dsmc {

double maxwellianSpeedPdf(double speed, double sigma2, double drift) {
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

double bkwK(double collisionTimes, double k0) {
    return 1.0 - (1.0 - k0) * std::exp(-collisionTimes / 6.0);
}

double bkwMomentRatio(int k, double K) {
    return std::pow(K, k - 1) * (k - (k - 1) * K);
}

} // namespace pl::dsmc
