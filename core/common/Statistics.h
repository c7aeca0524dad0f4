// Distribution tests and fits used by observables and by the physics tests.
#pragma once

#include <functional>
#include <vector>

namespace pl {

// Maxwell–Boltzmann speed distributions, one of each, for every kind and test. σ² = kT/m is the variance
// of one velocity component [speed²]; a caller that has σ² passes kT = σ², mass = 1.
// In the plane, the speed is Rayleigh distributed: f(v) = (m v / kT) exp(−m v² / 2kT).
double rayleighPdf(double v, double kT, double mass);
// Its CDF: F(v) = 1 − exp(−m v² / 2kT), through expm1 so that the difference of two close speeds keeps
// its digits (the bins of a KL divergence).
double rayleighCdf(double v, double kT, double mass);
// In space, the density of |v| of a Maxwellian of σ² drifting at speed drift: f(s) = s / (u √(2π) σ)
// [exp(−(s − u)²/2σ²) − exp(−(s + u)²/2σ²)]; drift = 0 is Maxwell's 4π s² (2π σ²)^(−3/2) exp(−s²/2σ²).
double maxwellSpeedPdf(double speed, double sigma2, double drift = 0.0);
// Maxwell's speed CDF in space (no drift): erf(x) − (2/√π) x e^(−x²), x = s / √(2σ²).
double maxwellSpeedCdf(double speed, double sigma2);

// Kolmogorov–Smirnov distance sup |F_N(v) − F(v)| of a sample against a fully specified CDF.
// Sorts its argument.
double ksDistance(std::vector<double>& sample, const std::function<double(double)>& cdf);

// Critical KS distance for a sample of size n at significance 5 % (1.358/√n) or 1 % (1.628/√n).
double ksCritical(double n, double significance);

// Two-sample KS distance sup |F_a − F_b| of two empirical distributions. Sorts its arguments.
double ksTwoSampleDistance(std::vector<double>& a, std::vector<double>& b);
// Asymptotic probability that two samples of sizes na and nb from one distribution lie this far apart or
// farther: Q_KS(λ) = 2 Σ (−1)^(j−1) e^(−2 j² λ²), λ = (√n_e + 0.12 + 0.11/√n_e) D, n_e = na nb/(na + nb)
// (Stephens 1970).
double ksTwoSamplePValue(double distance, double na, double nb);

// Kurtosis ⟨(x − x̄)⁴⟩ / ⟨(x − x̄)²⟩² of a sample: 3 for a Gaussian, 1 for two equal spikes. NaN when all
// values are equal.
double kurtosis(const std::vector<double>& values);

struct PowerLawFit {
    double exponent = 0.0;  // p in y = c x^p
    double prefactor = 0.0; // c
};
// Least-squares fit of log y = log c + p log x (the order of convergence of an error curve).
PowerLawFit fitPowerLaw(const std::vector<double>& x, const std::vector<double>& y);

} // namespace pl
