// The interchangeable piece of the NTC method: σ c_r as a function of the relative speed. Every model
// here is a power law σ c_r = A c_r^(2 − 2ω) (docs/dsmc.md#cross-sections-and-collision-frequency): the
// write-up's σ = 1e-18 c_r^-1/2 (inverse-root) is ω = 3/4, hard spheres ω = 1/2, Maxwell molecules ω = 1, and
// VHS any ω with A from (d_ref, T_ref).
#pragma once

#include "DsmcParams.h"

#include <cmath>

namespace pl {

struct CollisionModel {
    enum class Kind { InverseRoot, HardSphere, Vhs, Maxwell };
    Kind kind = Kind::InverseRoot;
    double prefactor = 1e-18; // A [m^(2ω+1) s^(2ω−2)]
    double omega = 0.75;

    static CollisionModel fromParams(const DsmcParams& p);
    // The same prefactors from the cross-section parameters alone (the DSMC cell and the wind tunnel
    // share them): massKg the molecular mass.
    static CollisionModel fromCrossSection(DsmcCrossSection crossSection, double diameter, double vhsDiameter,
                                           double vhsTref, double vhsOmega, double maxwellSigmaCr,
                                           double massKg);

    // σ c_r [m³/s]. The common exponents get exact fast paths; pow only for a general VHS ω.
    double sigmaCr(double cr) const {
        switch (kind) {
        case Kind::InverseRoot:
            return prefactor * std::sqrt(cr);
        case Kind::HardSphere:
            return prefactor * cr;
        case Kind::Maxwell:
            return prefactor;
        case Kind::Vhs:
            return prefactor * std::pow(cr, 2.0 - 2.0 * omega);
        }
        return 0.0;
    }

    // Equilibrium ⟨σ c_r⟩ at temperature T for molecules of mass m: the relative speed is Maxwellian
    // with reduced mass m/2, so ⟨c_r^p⟩ = (4kT/m)^(p/2) Γ((3+p)/2) / Γ(3/2).
    double meanSigmaCr(double temperature, double mass) const;
};

} // namespace pl
