// Exact results the DSMC cell is checked against (docs/dsmc.md#reference-formulas): the BKW solution's
// moments. The Maxwellian speed distributions are common/Statistics.h's, shared with the other kinds.
#pragma once

namespace pl::dsmc {

// BKW (Bobylev; Krook & Wu): K(t) = 1 − (1 − K₀) e^(−t/6), t in mean collision times (t = ν t_phys).
double bkwK(double collisionTimes, double k0 = 0.6);
// M_2k(t) / M_2k^eq = K^(k−1) (k − (k − 1) K): 1 at equilibrium.
double bkwMomentRatio(int k, double K);

} // namespace pl::dsmc
