// The wind tunnel's reference formulas (core/tunnel/TunnelTheory, docs/wind-tunnel.md#reference-formulas)
// against their limits, their sum rules and a direct quadrature of the integrals they close: the
// physics tests compare the model with these, so these must be right first.
#include "tunnel/TunnelTheory.h"

#include <QtTest>

#include <numbers>

using namespace pl;
namespace tt = pl::tunnel_theory;

namespace {

constexpr double kArgonMass = 39.948 * kAtomicMass;

bool near(double value, double expected, double relative) {
    return std::abs(value - expected) <= relative * std::abs(expected);
}

// The drag coefficient integrated over the surface as docs/wind-tunnel.md#free-molecular-drag sets it up
// (incident pressure and shear from the half-range moments, diffuse re-emission at T_w), by the midpoint
// rule in the angle from the stagnation point.
double dragCoefficientByQuadrature(double s, double wallToStream) {
    const double sqrtPi = std::sqrt(std::numbers::pi);
    const int intervals = 20000;
    double sum = 0;
    for (int k = 0; k < intervals; ++k) {
        const double theta = (k + 0.5) * std::numbers::pi / intervals;
        const double e = s * std::cos(theta);
        const double chi = std::exp(-e * e) + sqrtPi * e * (1 + std::erf(e)); // 2√π β Ṅ / n
        const double pressure = e * std::exp(-e * e) / sqrtPi + (0.5 + e * e) * (1 + std::erf(e)) +
                                0.5 * std::sqrt(wallToStream) * chi; // in units n m / 2β²
        const double shear = s * std::sin(theta) / sqrtPi * chi;
        sum += (pressure * std::cos(theta) + shear * std::sin(theta)) * std::numbers::pi / intervals;
    }
    return sum / (s * s);
}

} // namespace

class TestTunnelTheory : public QObject {
    Q_OBJECT
private slots:
    void halfRangeFluxesAtRestAreEffusion() {
        // At rest: Ṅ = n c̄ / 4, normal momentum p / 2, energy 2 kT per molecule (Bird 1994 §4.3).
        const double n = 1e20, t = 300;
        const tt::HalfRangeFlux f = tt::halfRangeFlux(n, t, kArgonMass, 0.0);
        QVERIFY(near(f.number, n * tt::meanSpeed(t, kArgonMass) / 4, 1e-13));
        QVERIFY(near(f.normalMomentum, 0.5 * n * kBoltzmann * t, 1e-13));
        QVERIFY(near(f.energy, 2 * kBoltzmann * t * f.number, 1e-13));
    }

    void halfRangeFluxesOfBothSidesAddToTheFullFlux() {
        // The flux towards +n of a stream U_n minus the flux towards −n (the same formula at −U_n) is the
        // full-range flux: n U_n, ρ U_n² + p, n U_n (½ m U² + 5/2 kT).
        const double n = 3e19, t = 200, m = kArgonMass, ut = 150;
        for (double un : {-900.0, -50.0, 10.0, 400.0, 2634.0}) {
            const tt::HalfRangeFlux plus = tt::halfRangeFlux(n, t, m, un, ut);
            const tt::HalfRangeFlux minus = tt::halfRangeFlux(n, t, m, -un, ut);
            const double kt = kBoltzmann * t;
            QVERIFY(near(plus.number - minus.number, n * un, 1e-9));
            QVERIFY(near(plus.normalMomentum + minus.normalMomentum, n * m * un * un + n * kt, 1e-12));
            QVERIFY(near(plus.tangentialMomentum - minus.tangentialMomentum, n * m * un * ut, 1e-9));
            QVERIFY(
                near(plus.energy - minus.energy, n * un * (0.5 * m * (un * un + ut * ut) + 2.5 * kt), 1e-9));
        }
    }

    void scaledBesselFunctionsMatchTheLibrary() {
        for (double x : {0.0, 1e-3, 0.5, 3.0, 12.0, 24.9, 25.1, 60.0, 300.0, 650.0}) {
            const double e = std::exp(-x);
            QVERIFY2(near(tt::scaledBesselI0(x), std::cyl_bessel_i(0.0, x) * e, 1e-12),
                     qPrintable(QString::number(x)));
            QVERIFY2(near(tt::scaledBesselI1(x) + 1e-300, std::cyl_bessel_i(1.0, x) * e + 1e-300, 1e-12),
                     qPrintable(QString::number(x)));
        }
    }

    void cylinderDragMatchesTheSurfaceIntegral() {
        for (double s : {0.1, 0.5, 1.0, 2.0, 5.0, 10.0})
            for (double tw : {0.0, 1.0, 2.5}) {
                const double closed = tt::freeMolecularCylinderDragCoefficient(s, tw);
                const double quadrature = dragCoefficientByQuadrature(s, tw);
                QVERIFY2(near(closed, quadrature, 1e-8),
                         qPrintable(
                             QString("s %1, Tw/T %2: %3 vs %4").arg(s).arg(tw).arg(closed).arg(quadrature)));
            }
    }

    void cylinderDragHasItsAsymptotes() {
        const double pi = std::numbers::pi, sqrtPi = std::sqrt(pi);
        for (double tw : {0.0, 1.0, 4.0}) {
            // s → 0: C_D s → √π (3/2 + (π/4) √(T_w/T)); the next term is O(s²).
            const double s0 = 1e-4;
            QVERIFY(near(s0 * tt::freeMolecularCylinderDragCoefficient(s0, tw),
                         sqrtPi * (1.5 + pi / 4 * std::sqrt(tw)), 1e-7));
            // s → ∞: all incident momentum absorbed (C_D → 2) plus the re-emitted molecules' push
            // π^(3/2) √(T_w/T) / 4s; Hankel's series gives the incident part as 2 + 3/2s² − 3/16s⁴ + O(s⁻⁶).
            for (double s : {30.0, 100.0}) {
                const double reemitted = pi * sqrtPi * std::sqrt(tw) / (4 * s);
                const double incident = 2 + 1.5 / (s * s) - 3.0 / (16 * s * s * s * s);
                QVERIFY(near(tt::freeMolecularCylinderDragCoefficient(s, tw), incident + reemitted, 1e-9));
            }
        }
    }

    void rankineHugoniotJumps() {
        const double a = 320;
        // M = 2, γ = 5/3: ρ₂/ρ₁ = 32/14, p₂/p₁ = 4.75.
        const tt::NormalShock m2 = tt::normalShockOfMach(2.0, a);
        QVERIFY(near(m2.densityRatio, 32.0 / 14.0, 1e-14));
        QVERIFY(near(m2.pressureRatio, 4.75, 1e-14));
        QVERIFY(near(m2.temperatureRatio, 4.75 * 14.0 / 32.0, 1e-14));
        // The piston speed is the gas speed behind the shock: u_p = W (1 − ρ₁/ρ₂).
        for (double up : {50.0, 640.0, 5000.0}) {
            const tt::NormalShock shock = tt::pistonDrivenShock(up, a);
            QVERIFY(near(shock.shockSpeed * (1 - 1 / shock.densityRatio), up, 1e-12));
            QVERIFY(shock.shockSpeed > a && shock.shockSpeed > up);
        }
        // A vanishing piston speed sends a sound wave; a strong shock compresses 4× at γ = 5/3.
        QVERIFY(near(tt::pistonDrivenShock(0.0, a).shockSpeed, a, 1e-15));
        QVERIFY(near(tt::normalShockOfMach(1e4, a).densityRatio, 4.0, 1e-7));
    }

    void meanFreePathsAgree() {
        const double n = 1e21, t = 200, m = kArgonMass;
        // VHS: c̄ / (n ⟨σ c_r⟩) with the cell's cross-section is Bird's eq. 4.65.
        const double dRef = 4.17e-10, tRef = 273, omega = 0.81;
        const CollisionModel vhs =
            CollisionModel::fromCrossSection(DsmcCrossSection::Vhs, 0, dRef, tRef, omega, 0, m);
        QVERIFY(near(tt::meanFreePath(vhs, n, t, m), tt::vhsMeanFreePath(n, t, dRef, tRef, omega), 1e-12));
        // ... and Bird's eq. 4.76 from the VHS viscosity: λ = 2(7 − 2ω)(5 − 2ω)/15 √(m/2πkT) μ/ρ.
        const double mu = tt::vhsViscosity(t, m, dRef, tRef, omega);
        const double fromViscosity = 2 * (7 - 2 * omega) * (5 - 2 * omega) / 15 *
                                     std::sqrt(m / (2 * std::numbers::pi * kBoltzmann * t)) * mu / (n * m);
        QVERIFY(near(tt::vhsMeanFreePath(n, t, dRef, tRef, omega), fromViscosity, 1e-12));
        // Argon's VHS viscosity at T_ref is the measured 2.117e-5 Pa s (Bird 1994 App. A) within 0.1 %.
        QVERIFY(near(tt::vhsViscosity(273, m, dRef, tRef, omega), 2.117e-5, 1e-3));
        // Hard spheres: the shock-thickness length 16 μ/(5 ρ √(2πkT/m)) with the first-approximation
        // viscosity is 1/(√2 π d² n) exactly.
        const double d = 3.6e-10;
        const double muFirst = tt::vhsViscosity(t, m, d, t, 0.5);
        QVERIFY(near(tt::viscosityMeanFreePath(muFirst, n, t, m),
                     1 / (std::sqrt(2.0) * std::numbers::pi * d * d * n), 1e-12));
        QVERIFY(near(tt::hardSphereViscosity(t, m, d), 1.016034 * muFirst, 1e-15));
    }

    void couetteLimits() {
        const double n = 1e20, t = 273, m = kArgonMass;
        const tt::CouetteFlow free = tt::freeMolecularCouette(n, t, m, -100, 100);
        QVERIFY(near(free.shearStress, n * m * tt::meanSpeed(t, m) * 200 / 4, 1e-14));
        QCOMPARE(free.wallSlip, 100.0);
        QCOMPARE(free.centreSpeed, 0.0);
        // No slip: τ = μ ΔU / H; slip lengths ζ at both walls widen the gap to H + 2ζ.
        const double mu = 2e-5;
        QVERIFY(near(tt::slipCouette(mu, 0, 0.01, -100, 100).shearStress, mu * 200 / 0.01, 1e-14));
        const tt::CouetteFlow slip = tt::slipCouette(mu, 1e-3, 0.01, -100, 100);
        QVERIFY(near(slip.shearStress, mu * 200 / 0.012, 1e-14));
        QVERIFY(near(slip.wallSlip, 200 * 1e-3 / 0.012, 1e-14));
        QVERIFY(near(2 * slip.wallSlip + slip.shearStress / mu * 0.01, 200, 1e-14)); // slips + profile = ΔU
    }
};

QTEST_APPLESS_MAIN(TestTunnelTheory)
#include "tst_tunnel_theory.moc"
