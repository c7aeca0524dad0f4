// The accuracy-against-cost sweep: on the harmonic pair every integrator converges at its theoretical
// order, and the cost columns count what each scheme does.
#include "md/MethodSweep.h"

#include <QtTest>

using namespace pl::md;

class TestMdSweep : public QObject {
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

    void orderFitIgnoresTheNoiseFloor() {
        QCOMPARE(fitOrder({0.1, 0.01, 0.001}, {1e-2, 1e-4, 1e-6}), 2.0);
        QCOMPARE(fitOrder({0.1, 0.01, 0.001}, {1e-2, 1e-4, 1e-15}), 2.0);
        QVERIFY(std::isnan(fitOrder({0.1}, {1e-2})));
    }
};

QTEST_GUILESS_MAIN(TestMdSweep)
#include "tst_md_sweep.moc"
