// The accuracy-against-cost sweep: on the harmonic pair every integrator converges at its theoretical
// order, and the cost columns count what each scheme does.
#include "catalog/ModelCatalog.h"
#include "gas/GasModel.h"
#include "gas/MethodSweep.h"

#include <QtTest>

using namespace pl::gas;

class TestGasSweep : public QObject {
    Q_OBJECT

private slots:
    void measuredOrdersMatchTheory() {
        const std::vector<std::string> schemes{"explicit-euler", "symplectic-euler", "velocity-verlet", "rk4",
                                               "forest-ruth"};
        const SweepResult r = sweepHarmonicPair(schemes, {16, 32, 64, 128, 256});
        QCOMPARE(r.orders.size(), schemes.size());
        for (const auto& o : r.orders) {
            qInfo("%-16s measured order %.3f (theory %d)", o.integrator.c_str(), o.measured, o.theory);
            QVERIFY2(std::abs(o.measured - o.theory) <= 0.2, o.integrator.c_str());
        }
    }

    void costsCountForceEvaluations() {
        const SweepResult r = sweepHarmonicPair({"velocity-verlet", "rk4"}, {20});
        QCOMPARE(r.points.size(), std::size_t(2));
        QCOMPARE(r.points[1].forcesPerTime / r.points[0].forcesPerTime, 4.0);
        for (const auto& p : r.points) QVERIFY(p.secondsPerTime > 0 && p.energyError >= 0);
        // Verlet is symplectic: bounded energy error far below explicit Euler's growth.
        const SweepResult euler = sweepHarmonicPair({"explicit-euler"}, {20});
        QVERIFY(euler.points[0].energyError > 10 * r.points[0].energyError);
    }

    void sweepsFromAGasState() {
        // The classroom gas after 300 steps (contacts under way), 64 of its steps as the horizon.
        pl::GasModel gas;
        gas.reset(pl::loadPreset("gas-classroom"));
        for (int s = 0; s < 300; ++s) gas.step();
        const double horizon = 64 * gas.parameters().dt;
        const GasReference reference = gasReference(gas, horizon, horizon / 1024);
        QCOMPARE(reference.x.size(), std::size_t(2500));
        std::vector<double> dts, errors;
        for (int steps : {16, 32, 64, 128}) {
            const SweepPoint p = sweepFromState(reference, "velocity-verlet", horizon / steps);
            QVERIFY(p.failure.empty());
            dts.push_back(p.dt);
            errors.push_back(p.trajectoryError);
        }
        const double order = fitOrder(dts, errors);
        qInfo("velocity Verlet from the gas: order %.2f, rms error %.2e at the gas's own dt", order,
              errors[2]);
        QVERIFY(std::abs(order - 2) < 0.3);
        // With forces present symplectic Euler is first order again, behind Verlet.
        QVERIFY(sweepFromState(reference, "symplectic-euler", horizon / 64).trajectoryError > 2 * errors[2]);
        // A step far beyond the contact's stability: stopped, reported, and no number plotted.
        const SweepPoint blown = sweepFromState(reference, "velocity-verlet", horizon / 2);
        QVERIFY(!blown.failure.empty());
        QVERIFY(std::isnan(blown.trajectoryError));
    }

    void orderFitIgnoresTheNoiseFloor() {
        QCOMPARE(fitOrder({0.1, 0.01, 0.001}, {1e-2, 1e-4, 1e-6}), 2.0);
        QCOMPARE(fitOrder({0.1, 0.01, 0.001}, {1e-2, 1e-4, 1e-15}), 2.0);
        QVERIFY(std::isnan(fitOrder({0.1}, {1e-2})));
    }
};

QTEST_GUILESS_MAIN(TestGasSweep)
#include "tst_gas_sweep.moc"
