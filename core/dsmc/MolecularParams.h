// The molecular parameters the DSMC cell and the wind tunnel share (mass_amu, cross_section, diameter,
// vhs_d_ref, vhs_T_ref, vhs_omega, maxwell_sigma_cr): one table, bound to either scene's parameter struct,
// so a molecule has the same keys, labels, units, ranges and tooltips in both.
#pragma once

#include "DsmcParams.h" // DsmcCrossSection

#include <string>
#include <vector>

namespace pl {

// What differs between the scenes that show the table: where the panel puts the parameters, and the gas
// whose values the defaults (and so the tooltips) are.
struct MolecularParamsText {
    std::string massGroup;      // panel section of mass_amu
    std::string collisionGroup; // panel section of the cross-section model and its constants
    std::string gas;            // the gas of the defaults, as the tooltips name it: "O2", "argon"
    bool writeUpScene = false;  // the scene of the write-up, whose σ the tooltip says is used as written
};

// The defaults of one scene's struct (DsmcParams{}, TunnelParams{}), which the specs offer and some
// tooltips quote.
struct MolecularDefaults {
    double massAmu;        // [u]
    double diameter;       // hard-sphere diameter [m]
    double vhsDiameter;    // VHS d_ref [m]
    double vhsTref;        // VHS T_ref [K]
    double vhsOmega;       // VHS viscosity index ω
    double maxwellSigmaCr; // σ c_r of Maxwell molecules [m³/s]
};

// mass_amu: the molecular mass [u].
ParamSpec molecularMassSpec(const MolecularParamsText& text, const MolecularDefaults& defaults);

// The cross-section model and its constants, in table order: cross_section (its choices and default are
// bindChoice's), diameter, vhs_d_ref, vhs_T_ref, vhs_omega, maxwell_sigma_cr.
struct CrossSectionSpecs {
    ParamSpec model, diameter, vhsDiameter, vhsTref, vhsOmega, maxwellSigmaCr;
};
CrossSectionSpecs crossSectionSpecs(const MolecularParamsText& text, const MolecularDefaults& defaults);

// The defaults of P, a parameter struct with the members the table binds (DsmcParams, TunnelParams).
template <class P> MolecularDefaults molecularDefaults() {
    const P d;
    return {d.massAmu, d.diameter, d.vhsDiameter, d.vhsTref, d.vhsOmega, d.maxwellSigmaCr};
}

template <class P> ParamField<P> molecularMassField(const MolecularParamsText& text) {
    return bindReal(&P::massAmu, molecularMassSpec(text, molecularDefaults<P>()));
}

template <class P> std::vector<ParamField<P>> crossSectionFields(const MolecularParamsText& text) {
    CrossSectionSpecs s = crossSectionSpecs(text, molecularDefaults<P>());
    return {bindChoice(&P::crossSection, std::move(s.model)),
            bindReal(&P::diameter, std::move(s.diameter)),
            bindReal(&P::vhsDiameter, std::move(s.vhsDiameter)),
            bindReal(&P::vhsTref, std::move(s.vhsTref)),
            bindReal(&P::vhsOmega, std::move(s.vhsOmega)),
            bindReal(&P::maxwellSigmaCr, std::move(s.maxwellSigmaCr))};
}

} // namespace pl
