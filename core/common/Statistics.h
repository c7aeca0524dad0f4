// Distribution tests and fits used by observables and by the physics tests.
#pragma once

#include <functional>
#include <vector>

namespace pl {

// 2D Maxwell–Boltzmann speed pdf (Rayleigh with σ² = kT/m): f(v) = (m v / kT) exp(−m v² / 2kT).
double rayleighPdf(double v, double kT, double mass);
// Its CDF: F(v) = 1 − exp(−m v² / 2kT).
double rayleighCdf(double v, double kT, double mass);

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
