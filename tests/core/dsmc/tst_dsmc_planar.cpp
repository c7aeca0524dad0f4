// DSMC with two velocity components: scattering stays in the plane and conserves momentum and energy,
// the cell relaxes to the 2D Maxwellian (kurtosis 3, ⟨c⁴⟩ = 8 (kT/m)², speed² exponential), and the BKW
// start, a 3D solution, is refused in the plane.
#include "common/Philox.h"
#include "dsmc/DsmcKernels.h"
#include "dsmc/DsmcModel.h"

#include <QtTest>

using namespace pl;

class TestDsmcPlanar : public QObject {
    Q_OBJECT
private slots:
    void inPlaneScatteringConservesAndIsIsotropic() {
        double worst = 0, sumCos2 = 0;
        const int n = 20000;
        for (std::uint32_t k = 0; k < n; ++k) {
            const auto [a1, a2] = gaussianPair(randomWords(3, RngPurpose::Shuffle, k, 0));
            const auto [b1, b2] = gaussianPair(randomWords(3, RngPurpose::Shuffle, k, 1));
            const auto [u, unused] = uniformPair(randomWords(3, RngPurpose::Shuffle, k, 2));
            (void)unused;
            dsmc::Velocity a{a1, a2, 0}, b{b1 + 2, b2, 0};
            const dsmc::Velocity a0 = a, b0 = b;
            dsmc::scatterInPlane(a, b, 1.0, 1.0, u);
            QCOMPARE(a.z, 0.0);
            QCOMPARE(b.z, 0.0);
            worst = std::max({worst, std::abs(a.x + b.x - a0.x - b0.x), std::abs(a.y + b.y - a0.y - b0.y),
                              std::abs(a.x * a.x + a.y * a.y + b.x * b.x + b.y * b.y -
                                       (a0.x * a0.x + a0.y * a0.y + b0.x * b0.x + b0.y * b0.y))});
            const double rx = a.x - b.x, ry = a.y - b.y;
            sumCos2 += rx * rx / (rx * rx + ry * ry);
        }
        QVERIFY(worst < 1e-12);
        // Uniform angle: ⟨cos² φ⟩ = ½ with standard error √(1/8n).
        QVERIFY(std::abs(sumCos2 / n - 0.5) < 4 * std::sqrt(0.125 / n));
    }

    void twoBeamsRelaxToThePlanarMaxwellian() {
        DsmcModel model;
        Preset p;
        p.model = "dsmc";
        p.params = {{"velocity_components", 2.0},
                    {"cross_section", "hard-sphere"},
                    {"count_a", 4000.0},
                    {"count_b", 4000.0},
                    {"run_steps", 0.0}};
        model.reset(p);
        const DsmcObservables start = model.observe();
        QCOMPARE(start.tz, 0.0);
        QVERIFY(start.kurtosisVx < 1.5);
        const double temperature = start.t;
        while (model.observe().collisionsPerParticle < 15) model.step();
        const DsmcObservables end = model.observe();
        qInfo("after %.1f collisions each: T = %.4f K (start %.4f), kurtosis %.3f, M4 %.3f, M6 %.3f, KL %.4f",
              end.collisionsPerParticle, end.t, temperature, end.kurtosisVx, end.m4, end.m6,
              end.klDivergence);
        QCOMPARE(end.tz, 0.0);
        QVERIFY(std::abs(end.t / temperature - 1) < 1e-10); // energy conserved, all of it in the plane
        QVERIFY(std::abs(end.tx / end.ty - 1) < 0.05);
        QVERIFY(std::abs(end.kurtosisVx - 3) < 0.15);
        QVERIFY(std::abs(end.m4 - 1) < 0.06);
        QVERIFY(std::abs(end.m6 - 1) < 0.2);
        QVERIFY(end.klDivergence < 0.01);
        QVERIFY(std::isnan(end.m4Bkw));
    }

    void planarBkwIsRefused() {
        DsmcModel model;
        try {
            model.setParams({{"velocity_components", 2.0}, {"initial", "bkw"}});
            QFAIL("a planar BKW start was accepted");
        } catch (const ParamError& e) {
            QCOMPARE(e.key(), std::string("velocity_components"));
        }
    }
};

QTEST_GUILESS_MAIN(TestDsmcPlanar)
#include "tst_dsmc_planar.moc"
