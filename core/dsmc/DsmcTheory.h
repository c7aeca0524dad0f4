// Exact results the DSMC cell is checked against (docs/dsmc.md#reference-formulas): equilibrium collision
// rates, the Maxwellian speed density (also of a drifting gas), and the BKW solution's moments.
#pragma once

namespace pl::dsmc {

// Density of |v| for a 3D Maxwellian of temperature kT/m = sigma2 drifting at speed drift [s/m].
// drift = 0 is the Maxwell–Boltzmann speed density 4π v² (2π σ²)^(−3/2) exp(−v²/2σ²).
double maxwellianSpeedPdf(double speed, double sigma2, double drift);
// Cumulative Maxwell–Boltzmann speed distribution (no drift).
double maxwellSpeedCdf(double speed, double sigma2);

// BKW (Bobylev; Krook & Wu): K(t) = 1 − (1 − K₀) e^(−t/6), t in mean collision times (t = ν t_phys).
double bkwK(double collisionTimes, double k0 = 0.6);
// M_2k(t) / M_2k^eq = K^(k−1) (k − (k − 1) K): 1 at equilibrium.
double bkwMomentRatio(int k, double K);

} // namespace pl::dsmc
