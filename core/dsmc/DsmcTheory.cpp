// Closed forms of the BKW solution (Bobylev; Krook & Wu).
#include "DsmcTheory.h"

#include <cmath>

namespace pl::dsmc {

double bkwK(double collisionTimes, double k0) {
    return 1.0 - (1.0 - k0) * std::exp(-collisionTimes / 6.0);
}

double bkwMomentRatio(int k, double K) {
    return std::pow(K, k - 1) * (k - (k - 1) * K);
}

} // namespace pl::dsmc
