// CollisionModel: prefactors of the four models.
#include "DsmcCollisionModel.h"

#include <numbers>

namespace pl {

CollisionModel CollisionModel::fromParams(const DsmcParams& p) {
    return fromCrossSection(p.crossSection, p.diameter, p.vhsDiameter, p.vhsTref, p.vhsOmega,
                            p.maxwellSigmaCr, p.mass());
}

CollisionModel CollisionModel::fromCrossSection(DsmcCrossSection crossSection, double diameter,
                                                double vhsDiameter, double vhsTref, double vhsOmega,
                                                double maxwellSigmaCr, double massKg) {
    CollisionModel m;
    if (crossSection == DsmcCrossSection::InverseRoot) {
        m = {Kind::InverseRoot, 1e-18, 0.75}; // σ = 1e-18 c_r^-1/2 m², as the write-up writes it
    } else if (crossSection == DsmcCrossSection::HardSphere) {
        m = {Kind::HardSphere, std::numbers::pi * diameter * diameter, 0.5};
    } else if (crossSection == DsmcCrossSection::Maxwell) {
        m = {Kind::Maxwell, maxwellSigmaCr, 1.0};
    } else {
        // Bird (1994) eq. 4.63: σ = π d_ref² (2 k T_ref / (m_r c_r²))^(ω − 1/2) / Γ(5/2 − ω), m_r = m/2.
        const double w = vhsOmega;
        const double reference = 4.0 * kBoltzmann * vhsTref / massKg;
        m = {Kind::Vhs,
             std::numbers::pi * vhsDiameter * vhsDiameter * std::pow(reference, w - 0.5) /
                 std::tgamma(2.5 - w),
             w};
    }
    return m;
}

double CollisionModel::meanSigmaCr(double temperature, double mass) const {
    const double p = 2.0 - 2.0 * omega; // exponent of c_r in σ c_r
    const double scale = 4.0 * kBoltzmann * temperature / mass;
    return prefactor * std::pow(scale, 0.5 * p) * std::tgamma(0.5 * (3.0 + p)) / std::tgamma(1.5);
}

} // namespace pl
