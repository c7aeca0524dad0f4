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

struct PowerLawFit {
    double exponent = 0.0;  // p in y = c x^p
    double prefactor = 0.0; // c
};
// Least-squares fit of log y = log c + p log x (the order of convergence of an error curve).
PowerLawFit fitPowerLaw(const std::vector<double>& x, const std::vector<double>& y);

} // namespace pl
