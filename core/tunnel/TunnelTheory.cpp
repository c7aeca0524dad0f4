// Closed forms of TunnelTheory.h; each function's derivation is in docs/wind-tunnel.md#reference-formulas.
#include "TunnelTheory.h"

#include <cmath>
#include <numbers>

namespace pl::tunnel_theory {

namespace {

constexpr double kPi = std::numbers::pi;
const double kSqrtPi = std::sqrt(kPi);
// Hard spheres: the converged Chapman–Enskog viscosity over its first approximation.
constexpr double kHardSphereViscosityFactor = 1.016034;
// Below this argument the power series of I_ν converges without cancellation in few terms; above it
// Hankel's asymptotic series is accurate to round-off before its terms start to grow.
constexpr double kBesselSeriesLimit = 25.0;

// e^(−x) I_ν(x) for ν = 0, 1 (Abramowitz & Stegun 9.6.10 and 9.7.1).
double scaledBessel(int nu, double x) {
    if (x < 0) return std::nan("");
    if (x <= kBesselSeriesLimit) {
        const double half = 0.5 * x;
        double term = nu == 0 ? 1.0 : half; // (x/2)^ν / ν!
        double sum = 0;
        for (int k = 0; k < 200; ++k) {
            sum += term;
            term *= half * half / ((k + 1.0) * (k + 1.0 + nu));
            if (term < 1e-17 * sum) break;
        }
        return sum * std::exp(-x);
    }
    // e^(−x) I_ν(x) ~ (2πx)^(−1/2) Σ_k (−1)^k Π_{j≤k} (4ν² − (2j − 1)²) / (8 j x)
    const double mu = 4.0 * nu * nu;
    double term = 1.0, sum = 1.0;
    for (int j = 1; j < 60; ++j) {
        const double next = -term * (mu - (2.0 * j - 1) * (2.0 * j - 1)) / (8.0 * j * x);
        if (std::abs(next) >= std::abs(term)) break; // the asymptotic series starts to diverge
        term = next;
        sum += term;
        if (std::abs(term) < 1e-17 * std::abs(sum)) break;
    }
    return sum / std::sqrt(2.0 * kPi * x);
}

} // namespace

double mostProbableSpeed(double temperature, double mass) {
    return std::sqrt(2.0 * kBoltzmann * temperature / mass);
}

double meanSpeed(double temperature, double mass) {
    return std::sqrt(8.0 * kBoltzmann * temperature / (kPi * mass));
}

double soundSpeed(double temperature, double mass, double gamma) {
    return std::sqrt(gamma * kBoltzmann * temperature / mass);
}

HalfRangeFlux halfRangeFlux(double density, double temperature, double mass, double normalSpeed,
                            double tangentialSpeed) {
    // With c = β v_n, β = 1/√(2kT/m) and s = β U_n, the normal velocity density is e^(−(c − s)²)/√π and
    // ∫₀^∞ c^k e^(−(c − s)²) dc / √π gives the k-th half-range moment J_k.
    const double beta = 1.0 / mostProbableSpeed(temperature, mass);
    const double s = normalSpeed * beta;
    const double gauss = std::exp(-s * s), tail = 1.0 + std::erf(s);
    const double j1 = (gauss + kSqrtPi * s * tail) / (2.0 * kSqrtPi);
    const double j2 = s * gauss / (2.0 * kSqrtPi) + (1.0 + 2.0 * s * s) * tail / 4.0;
    const double j3 = (s * s + 1.0) * gauss / (2.0 * kSqrtPi) + s * (3.0 + 2.0 * s * s) * tail / 4.0;
    HalfRangeFlux flux;
    flux.number = density * j1 / beta; // Bird 1994 eq. 4.22
    flux.normalMomentum = mass * density * j2 / (beta * beta);
    flux.tangentialMomentum = mass * tangentialSpeed * flux.number;
    // Normal part ½ m ∫ v_n³ f, plus per crossing molecule the tangential drift ½ m U_t² and kT from the
    // two thermal tangential components (in-plane and z).
    flux.energy = 0.5 * mass * density * j3 / (beta * beta * beta) +
                  (0.5 * mass * tangentialSpeed * tangentialSpeed + kBoltzmann * temperature) * flux.number;
    return flux;
}

double scaledBesselI0(double x) {
    return scaledBessel(0, x);
}

double scaledBesselI1(double x) {
    return scaledBessel(1, x);
}

double freeMolecularCylinderDragCoefficient(double speedRatio, double wallToStream) {
    // docs/wind-tunnel.md#free-molecular-drag: C_D = (√π/s) e^(−s²/2) [(s² + 3/2) I₀(s²/2) +
    // (s² + ½) I₁(s²/2)] + (π^(3/2) / 4s) √(T_w/T).
    const double s = speedRatio, half = 0.5 * s * s;
    const double incident =
        kSqrtPi / s * ((s * s + 1.5) * scaledBesselI0(half) + (s * s + 0.5) * scaledBesselI1(half));
    const double reemitted = kPi * kSqrtPi / (4.0 * s) * std::sqrt(wallToStream);
    return incident + reemitted;
}

double freeMolecularCylinderDrag(double density, double temperature, double mass, double speed, double radius,
                                 double wallTemperature) {
    const double s = speed / mostProbableSpeed(temperature, mass);
    const double dynamicPressure = 0.5 * density * mass * speed * speed;
    return freeMolecularCylinderDragCoefficient(s, wallTemperature / temperature) * dynamicPressure * 2.0 *
           radius;
}

NormalShock normalShockOfMach(double machNumber, double upstreamSoundSpeed, double gamma) {
    const double m2 = machNumber * machNumber;
    NormalShock shock;
    shock.machNumber = machNumber;
    shock.shockSpeed = machNumber * upstreamSoundSpeed;
    shock.densityRatio = (gamma + 1.0) * m2 / ((gamma - 1.0) * m2 + 2.0);
    shock.pressureRatio = 1.0 + 2.0 * gamma / (gamma + 1.0) * (m2 - 1.0);
    shock.temperatureRatio = shock.pressureRatio / shock.densityRatio; // ideal gas: T ∝ p/ρ
    return shock;
}

NormalShock pistonDrivenShock(double pistonSpeed, double upstreamSoundSpeed, double gamma) {
    // Mass conservation across the shock gives u_p = W (1 − ρ₁/ρ₂), which with the density jump becomes
    // W² − ((γ + 1)/2) u_p W − a₁² = 0; its positive root:
    const double q = 0.25 * (gamma + 1.0) * pistonSpeed;
    const double w = q + std::sqrt(q * q + upstreamSoundSpeed * upstreamSoundSpeed);
    return normalShockOfMach(w / upstreamSoundSpeed, upstreamSoundSpeed, gamma);
}

double collisionRate(const CollisionModel& model, double density, double temperature, double mass) {
    return density * model.meanSigmaCr(temperature, mass);
}

double meanFreePath(const CollisionModel& model, double density, double temperature, double mass) {
    return meanSpeed(temperature, mass) / collisionRate(model, density, temperature, mass);
}

double vhsMeanFreePath(double density, double temperature, double dRef, double tRef, double omega) {
    return 1.0 / (std::sqrt(2.0) * kPi * dRef * dRef * density * std::pow(tRef / temperature, omega - 0.5));
}

double vhsViscosity(double temperature, double mass, double dRef, double tRef, double omega) {
    return 15.0 * std::sqrt(mass * kBoltzmann * tRef / kPi) * std::pow(temperature / tRef, omega) /
           (2.0 * (5.0 - 2.0 * omega) * (7.0 - 2.0 * omega) * dRef * dRef);
}

double hardSphereViscosity(double temperature, double mass, double diameter) {
    return kHardSphereViscosityFactor * vhsViscosity(temperature, mass, diameter, temperature, 0.5);
}

double viscosityMeanFreePath(double viscosity, double density, double temperature, double mass) {
    return 16.0 * viscosity / (5.0 * density * mass * std::sqrt(2.0 * kPi * kBoltzmann * temperature / mass));
}

CouetteFlow freeMolecularCouette(double density, double temperature, double mass, double bottomSpeed,
                                 double topSpeed) {
    // Half the molecules at any height come from each wall with its velocity: each wall emits
    // n c̄ / 4 per unit area and time, every one carrying m ΔU of x-momentum across the gap.
    const double du = std::abs(topSpeed - bottomSpeed);
    CouetteFlow flow;
    flow.shearStress = density * mass * meanSpeed(temperature, mass) * du / 4.0;
    flow.wallSlip = 0.5 * du;
    flow.centreSpeed = 0.5 * (bottomSpeed + topSpeed);
    return flow;
}

CouetteFlow slipCouette(double viscosity, double slipLength, double gap, double bottomSpeed,
                        double topSpeed) {
    // A linear profile of slope G = τ/μ meets each wall a slip ζ G short of the wall's speed:
    // ΔU = G gap + 2 ζ G.
    const double du = std::abs(topSpeed - bottomSpeed);
    const double gradient = du / (gap + 2.0 * slipLength);
    CouetteFlow flow;
    flow.shearStress = viscosity * gradient;
    flow.wallSlip = slipLength * gradient;
    flow.centreSpeed = 0.5 * (bottomSpeed + topSpeed);
    return flow;
}

} // namespace pl::tunnel_theory
