// MD against planar DSMC: from the same two beams both relax to one Maxwellian (two-sample KS), the
// kurtosis of v_x climbs from about 1 to 3 in a few collisions per particle, and DSMC needs far less time.
#include "common/Statistics.h"
#include "comparison/GasVsDsmc.h"

#include <QtTest>

using namespace pl::methods;

class TestGasVsDsmc : public QObject {
    Q_OBJECT

private slots:
    void sharedStartIsTwoColdBeams() {
        TwoBeamSetup setup;
        setup.particles = 2000;
        const auto v = twoBeamVelocities(setup);
        QCOMPARE(v.size(), std::size_t(2000));
        double px = 0, py = 0, energy = 0;
        std::vector<double> vx;
        for (const auto& [x, y] : v) {
            px += x, py += y, energy += 0.5 * (x * x + y * y);
            vx.push_back(x);
        }
        QVERIFY(std::abs(px) < 1e-9 && std::abs(py) < 1e-9);
        // ½ u² of drift plus kT per particle in two components.
        QVERIFY(std::abs(energy / 2000 - (0.5 + setup.beamKT)) < 1e-9);
        QVERIFY(pl::kurtosis(vx) < 1.1); // two narrow peaks at ±1
    }

    void bothEndAtTheSameMaxwellian() {
        TwoBeamSetup setup;
        setup.particles = 1024;
        setup.collisionsPerParticle = 12;
        std::atomic<bool> stop{false};
        int gasSamples = 0;
        const RelaxationRun md = relaxWithMd(
            setup, [&](const RelaxationSample&) { ++gasSamples; }, &stop);
        const RelaxationRun dsmc = relaxWithDsmc(setup);
        QCOMPARE(static_cast<std::size_t>(gasSamples), md.curve.size());
        const GasVsDsmcResult r = compareRelaxations(md, dsmc);
        qInfo("MD %.3f s (%lld particle-steps), DSMC %.5f s: cost ratio %.0f; KS D = %.4f, p = %.3f",
              r.md.seconds, r.md.particleSteps, r.dsmc.seconds, r.costRatio, r.ksDistance, r.ksPValue);
        for (const RelaxationRun* run : {&r.md, &r.dsmc}) {
            QVERIFY(run->curve.front().kurtosisVx < 1.2);
            QVERIFY2(std::abs(run->curve.back().kurtosisVx - 3.0) < 0.4, run->method.c_str());
            QVERIFY(run->curve.back().collisionsPerParticle >= setup.collisionsPerParticle);
            QCOMPARE(run->finalVx.size(), std::size_t(1024));
        }
        QVERIFY(r.ksPValue > 0.01);
        QVERIFY(r.costRatio > 10);
        // Halfway, after 2 collisions each, neither is Maxwellian yet.
        for (const RelaxationRun* run : {&r.md, &r.dsmc})
            for (const auto& s : run->curve)
                if (s.collisionsPerParticle < 1.0) QVERIFY(s.kurtosisVx < 2.5);
    }

    void ksTellsDifferentTemperaturesApart() {
        // The same comparison with DSMC started hotter must fail the test the two above pass.
        TwoBeamSetup cold, hot;
        cold.collisionsPerParticle = hot.collisionsPerParticle = 8;
        hot.beamKT = 1.0; // final kT/m 1.5 u² against 0.51 u²
        const GasVsDsmcResult r = compareRelaxations(relaxWithDsmc(cold), relaxWithDsmc(hot));
        qInfo("cold against hot: KS D = %.4f, p = %.2g", r.ksDistance, r.ksPValue);
        QVERIFY(r.ksPValue < 1e-3);
    }

    void stopEndsEarly() {
        TwoBeamSetup setup;
        std::atomic<bool> stop{true};
        const RelaxationRun run = relaxWithMd(setup, {}, &stop);
        QCOMPARE(run.curve.size(), std::size_t(1));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, [] {
            TwoBeamSetup tiny;
            tiny.particles = 2;
            relaxWithDsmc(tiny);
        }());
    }
};

QTEST_GUILESS_MAIN(TestGasVsDsmc)
#include "tst_gas_vs_dsmc.moc"
