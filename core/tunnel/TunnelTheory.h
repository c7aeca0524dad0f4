// Exact and published results the wind tunnel is checked against (docs/wind-tunnel.md#reference-formulas):
// half-range fluxes of a drifting Maxwellian, the free-molecular drag of a diffuse cylinder, the
// Rankine–Hugoniot jump of a piston-driven shock, Couette shear and slip, collision rates and mean free
// paths. SI units throughout (m, s, kg, K).
#pragma once

#include "dsmc/DsmcCollisionModel.h"

namespace pl::tunnel_theory {

inline constexpr double kMonatomicGamma = 5.0 / 3.0;

// √(2kT/m), the most probable speed [m/s]; the speed ratio is s = U / √(2kT/m).
double mostProbableSpeed(double temperature, double mass);
// c̄ = √(8kT/πm), the mean molecular speed [m/s].
double meanSpeed(double temperature, double mass);
// a = √(γkT/m) [m/s].
double soundSpeed(double temperature, double mass, double gamma = kMonatomicGamma);

// What a drifting Maxwellian (density n, temperature T, mean velocity with component normalSpeed along a
// plane's normal and tangentialSpeed along it) carries through the plane per unit area and time, counting
// only the molecules that cross in the normal's direction (Bird 1994 eq. 4.22 and its moments;
// docs/wind-tunnel.md#half-range-fluxes). normalSpeed < 0: the stream moves away from that side.
struct HalfRangeFlux {
    double number = 0;             // [m⁻² s⁻¹]
    double normalMomentum = 0;     // flux of normal momentum [Pa]
    double tangentialMomentum = 0; // flux of tangential momentum [Pa]
    double energy = 0;             // flux of translational energy ½ m |v|² [W/m²]
};
HalfRangeFlux halfRangeFlux(double density, double temperature, double mass, double normalSpeed,
                            double tangentialSpeed = 0.0);

// e^(−x) I₀(x) and e^(−x) I₁(x) for x ≥ 0 (modified Bessel functions, scaled so large x does not
// overflow): power series below x = 25, Hankel's asymptotic series above.
double scaledBesselI0(double x);
double scaledBesselI1(double x);

// Drag coefficient per unit length of a circular cylinder in free-molecular flow with diffuse
// reflection at wall temperature T_w (docs/wind-tunnel.md#free-molecular-drag), on the reference area
// of its diameter: D = C_D · ½ ρ U² · 2r. speedRatio = U / √(2kT/m) > 0, wallToStream = T_w / T.
double freeMolecularCylinderDragCoefficient(double speedRatio, double wallToStream);
// The drag itself [N per m of depth] of a cylinder of the given radius [m].
double freeMolecularCylinderDrag(double density, double temperature, double mass, double speed, double radius,
                                 double wallTemperature);

// A piston pushed at pistonSpeed into gas at rest of sound speed a₁ drives a normal shock ahead of it
// (Rankine–Hugoniot; docs/wind-tunnel.md#shock-tube). Ratios are downstream / upstream.
struct NormalShock {
    double shockSpeed = 0; // lab frame [m/s]
    double machNumber = 0; // shockSpeed / a₁
    double densityRatio = 0;
    double temperatureRatio = 0;
    double pressureRatio = 0;
};
NormalShock pistonDrivenShock(double pistonSpeed, double upstreamSoundSpeed, double gamma = kMonatomicGamma);
// The same jump from the shock Mach number.
NormalShock normalShockOfMach(double machNumber, double upstreamSoundSpeed, double gamma = kMonatomicGamma);

// Equilibrium collision rate per molecule ν = n ⟨σ c_r⟩ [1/s] (docs/dsmc.md#cross-sections-and-
// collision-frequency), and the mean free path λ = c̄ / ν [m]; for VHS that is Bird 1994 eq. 4.65.
double collisionRate(const CollisionModel& model, double density, double temperature, double mass);
double meanFreePath(const CollisionModel& model, double density, double temperature, double mass);
// Bird 1994 eq. 4.65 written out: λ = 1 / (√2 π d_ref² n (T_ref/T)^(ω − ½)).
double vhsMeanFreePath(double density, double temperature, double dRef, double tRef, double omega);
// VHS viscosity in the first Chapman–Enskog approximation (Bird 1994 eq. 4.62 with d_ref at T_ref):
// μ = 15 √(m k T_ref / π) (T/T_ref)^ω / (2 (5 − 2ω)(7 − 2ω) d_ref²) [Pa s]. ω = ½ is the hard sphere's
// first approximation (5/16) √(π m k T) / (π d²).
double vhsViscosity(double temperature, double mass, double dRef, double tRef, double omega);
// The hard-sphere viscosity to convergence: 1.016034 × the first approximation (Chapman & Cowling 1970,
// ch. 10) — what a DSMC hard-sphere gas has, since DSMC solves the Boltzmann equation itself.
double hardSphereViscosity(double temperature, double mass, double diameter);
// The mean free path shock thicknesses are measured in (Alsmeyer 1976; Bird 1994 eq. 4.76 at ω = ½):
// λ = 16 μ / (5 ρ √(2π k T / m)) [m].
double viscosityMeanFreePath(double viscosity, double density, double temperature, double mass);

// Plane Couette flow between diffuse walls a distance gap apart, both at the gas temperature, moving
// along x at bottomSpeed and topSpeed (docs/wind-tunnel.md#couette).
struct CouetteFlow {
    double shearStress = 0; // |P_xy|, uniform across the gap [Pa]
    double wallSlip = 0;    // wall speed − gas speed at the wall, at each wall (profile extrapolated) [m/s]
    double centreSpeed = 0; // gas speed at mid-gap [m/s]
};
// Free-molecular limit (exact): τ = ρ c̄ |ΔU| / 4, the gas at (U_b + U_t)/2 everywhere.
CouetteFlow freeMolecularCouette(double density, double temperature, double mass, double bottomSpeed,
                                 double topSpeed);
// Navier–Stokes with first-order velocity slip u_gas − U_wall = ζ ∂u/∂n at each wall:
// τ = μ |ΔU| / (gap + 2ζ), slip = |ΔU| ζ / (gap + 2ζ).
CouetteFlow slipCouette(double viscosity, double slipLength, double gap, double bottomSpeed, double topSpeed);
// ζ = 1.1113 λ_HS for hard spheres with diffuse walls (Ohwada, Sone & Aoki 1989, Phys. Fluids A 1, 1588:
// k₀ = 1.2540 in units of (√π/2) λ_HS), λ_HS = 1 / (√2 π d² n) the hard-sphere mean free path.
inline constexpr double kHardSphereSlipCoefficient = 1.1113;

} // namespace pl::tunnel_theory
