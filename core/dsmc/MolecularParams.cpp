// The shared molecular parameter table: keys, labels, units, ranges and tooltips of the molecular mass and
// the cross-section model, for the DSMC cell and the wind tunnel alike.
#include "MolecularParams.h"

namespace pl {

ParamSpec molecularMassSpec(const MolecularParamsText& text, const MolecularDefaults& d) {
    return makeSpec("mass_amu", "Molecular mass", "u", text.massGroup,
                    "Mass of one molecule; " + text.gas + " is " + formatNumber(d.massAmu) + ".", 1e-3, 1e6,
                    1, d.massAmu);
}

CrossSectionSpecs crossSectionSpecs(const MolecularParamsText& text, const MolecularDefaults& d) {
    const std::string& group = text.collisionGroup;
    return {
        makeChoice("cross_section", "Cross-section", group,
                   std::string("inverse-root: σ = 1e-18 c_r^-1/2 m²") +
                       (text.writeUpScene ? " as written" : "") +
                       "; hard-sphere: σ = π d²; vhs: variable hard sphere (d_ref, T_ref, ω); maxwell: σ c_r "
                       "constant.",
                   true),
        makeSpec("diameter", "Hard-sphere diameter", "m", group,
                 "Molecular diameter of the hard-sphere model.", 1e-12, 1e-6, 0, d.diameter, true),
        makeSpec("vhs_d_ref", "VHS d_ref", "m", group,
                 "VHS reference diameter (" + text.gas + ": " + formatNumber(d.vhsDiameter) + ").", 1e-12,
                 1e-6, 0, d.vhsDiameter, true),
        makeSpec("vhs_T_ref", "VHS T_ref", "K", group, "Temperature at which d = d_ref (273 K).", 1e-3, 1e6,
                 1, d.vhsTref, true),
        makeSpec("vhs_omega", "VHS ω", "", group,
                 "Viscosity index: 0.5 hard sphere, 1 Maxwell, " + text.gas + " " + formatNumber(d.vhsOmega) +
                     ".",
                 0.5, 1.0, 0.01, d.vhsOmega, true),
        makeSpec("maxwell_sigma_cr", "Maxwell σ c_r", "m³/s", group,
                 "The constant σ c_r of Maxwell molecules.", 1e-30, 1e-5, 0, d.maxwellSigmaCr, true),
    };
}

} // namespace pl
