// Integrators: convergence orders of the energy error on a small cluster whose contacts persist over
// the horizon (smooth dynamics), and exact amplification factors on a head-on contact, which is a
// 1D harmonic oscillator of frequency ω = √(k/μ) (docs/gas.md#integrators-on-the-harmonic-oscillator; Hairer,
// Lubich & Wanner 2003).
#include "../BackendRows.h"
#include "GasTestScenes.h"
#include "common/Statistics.h"

#include <QtTest>
#include <complex>

using namespace pl;

namespace {

constexpr double kStiffness = 1000.0;
constexpr double kDiameter = 0.1;

GasModel clusterModel(const std::string& integrator, double dt) {
    GasModel model = test::makeGas({{"box_width", 4.0},
                                    {"box_height", 4.0},
                                    {"count_a", 4.0},
                                    {"diameter_a", kDiameter},
                                    {"stiffness", kStiffness},
                                    {"integrator", integrator},
                                    {"dt", dt}});
    // Four mutually overlapping disks (all six pairs closer than d), moving slowly: over the horizon no
    // contact begins or ends, so the force is smooth along the trajectory.
    model.placeParticles({{0.00, 0.00, 0.30, 0.10, 0},
                          {0.06, 0.01, -0.20, 0.20, 0},
                          {0.02, 0.06, 0.10, -0.30, 0},
                          {0.05, 0.055, -0.15, 0.05, 0}});
    return model;
}

bool allPairsInContact(const GasState& s) {
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j)
            if (std::hypot(s.x[i] - s.x[j], s.y[i] - s.y[j]) >= kDiameter) return false;
    return true;
}

// Largest |E(t) − E₀| / E₀ over a fixed horizon.
double maxEnergyError(const std::string& integrator, double horizon, int steps) {
    GasModel model = clusterModel(integrator, horizon / steps);
    const double e0 = model.totalEnergy();
    double worst = 0;
    for (int s = 0; s < steps; ++s) {
        model.step();
        if (!allPairsInContact(model.state())) return -1; // the scene no longer tests smooth dynamics
        worst = std::max(worst, std::abs(model.totalEnergy() - e0) / e0);
    }
    return worst;
}

// Two disks overlapping head-on at rest, released from the turning point r = d/2: until they separate
// (a quarter period) the relative coordinate is an exact harmonic oscillator.
ParamValues headOnParams(const std::string& integrator, double dt) {
    return {
        {"box_width", 4.0},        {"box_height", 4.0},        {"count_a", 2.0}, {"diameter_a", kDiameter},
        {"stiffness", kStiffness}, {"integrator", integrator}, {"dt", dt}};
}
const std::vector<GasParticle> kHeadOnPair = {{-kDiameter / 4, 0.0, 0.0, 0.0, 0},
                                              {kDiameter / 4, 0.0, 0.0, 0.0, 0}};

GasModel headOnContact(const std::string& integrator, double dt) {
    GasModel model = test::makeGas(headOnParams(integrator, dt));
    model.placeParticles(kHeadOnPair);
    return model;
}

} // namespace

class TestGasIntegrators : public QObject {
    Q_OBJECT
private slots:
    void energyErrorOrder_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("expectedOrder");
        QTest::newRow("symplectic-euler") << "symplectic-euler" << 1.0;
        QTest::newRow("explicit-euler") << "explicit-euler" << 1.0;
        QTest::newRow("velocity-verlet") << "velocity-verlet" << 2.0;
        QTest::newRow("rk4") << "rk4" << 4.0;
        QTest::newRow("forest-ruth") << "forest-ruth" << 4.0;
    }
    void energyErrorOrder() {
        QFETCH(QString, integrator);
        QFETCH(double, expectedOrder);
        const double horizon = 0.01; // ω·horizon ≈ 0.45 with ω = √(2k/m)
        std::vector<double> dts, errors;
        for (int steps : {32, 64, 128, 256}) {
            const double e = maxEnergyError(integrator.toStdString(), horizon, steps);
            QVERIFY2(e > 0, "contacts changed inside the horizon: the scene is not smooth");
            dts.push_back(horizon / steps);
            errors.push_back(e);
        }
        const double order = fitPowerLaw(dts, errors).exponent;
        QVERIFY2(
            std::abs(order - expectedOrder) < 0.25,
            qPrintable(
                QString("%1: measured order %2, expected %3").arg(integrator).arg(order).arg(expectedOrder)));
    }

    void explicitEulerGainsEnergyExactly() {
        // Explicit Euler multiplies the oscillator energy by exactly (1 + ω²h²) every step.
        const double mu = 0.5, omega = std::sqrt(kStiffness / mu), h = 0.002;
        GasModel model = headOnContact("explicit-euler", h);
        const double e0 = model.totalEnergy();
        for (int n = 1; n <= 10; ++n) {
            model.step();
            const double expected = e0 * std::pow(1 + omega * omega * h * h, n);
            QVERIFY(std::abs(model.totalEnergy() / expected - 1) < 1e-12);
        }
        QVERIFY(model.totalEnergy() > e0);
    }

    void rungeKuttaLosesEnergyExactly() {
        // RK4 multiplies it by |R(iωh)|² < 1, R(z) = 1 + z + z²/2 + z³/6 + z⁴/24: a steady loss.
        const double mu = 0.5, omega = std::sqrt(kStiffness / mu), h = 0.004;
        const std::complex<double> z(0.0, omega * h);
        const double gain = std::norm(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
        QVERIFY(gain < 1.0);
        GasModel model = headOnContact("rk4", h);
        const double e0 = model.totalEnergy();
        double previous = e0;
        for (int n = 1; n <= 8; ++n) { // ω·8h ≈ 1.43 < π/2: still in contact
            model.step();
            const double e = model.totalEnergy();
            QVERIFY(e < previous);
            QVERIFY(std::abs(e / (e0 * std::pow(gain, n)) - 1) < 1e-12);
            previous = e;
        }
    }

    void symplecticMethodsKeepEnergyBounded_data() { test::addBackendRows(); }

    void symplecticMethodsKeepEnergyBounded() {
        // Verlet's energy error on the oscillator stays O((ωh)²) and returns: no drift. The bound,
        // 0.25 (ωh)² = 2e-3, holds on the GL row unchanged: its float32 positions and forces round the
        // energy at ~1e-7 of itself, four orders of magnitude below it.
        const double mu = 0.5, omega = std::sqrt(kStiffness / mu), h = 0.002;
        Preset preset;
        preset.model = "gas";
        preset.seed = 1;
        preset.params = headOnParams("velocity-verlet", h);
        PL_MODEL_ON_ROW_BACKEND(made, preset);
        auto& model = made.as<GasModel>();
        model.placeParticles(kHeadOnPair);
        const double e0 = model.totalEnergy();
        for (int n = 1; n <= 17; ++n) { // up to the quarter period
            model.step();
            QVERIFY(std::abs(model.totalEnergy() - e0) / e0 < 0.25 * omega * omega * h * h);
        }
    }
};

QTEST_APPLESS_MAIN(TestGasIntegrators)
#include "tst_gas_integrators.moc"
