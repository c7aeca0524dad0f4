// One DSMC collision conserves momentum and energy to round-off and scatters isotropically; a whole run
// conserves them too, and the write-up run ends at 17.83 K with mean velocity 200 m/s. The molecule's
// parameters are one table for the cell and the wind tunnel.
#include "catalog/ModelCatalog.h"
#include "common/Philox.h"
#include "dsmc/DsmcKernels.h"
#include "dsmc/DsmcModel.h"
#include "tunnel/TunnelParams.h"

#include <QtTest>

using namespace pl;

class TestDsmcCollision : public QObject {
    Q_OBJECT
private slots:
    void eachCollisionConservesMomentumAndEnergy() {
        double worstMomentum = 0, worstEnergy = 0, worstSpeed = 0;
        for (std::uint32_t k = 0; k < 10000; ++k) {
            const auto [a1, a2] = gaussianPair(randomWords(7, RngPurpose::Shuffle, k, 0));
            const auto [a3, b1] = gaussianPair(randomWords(7, RngPurpose::Shuffle, k, 1));
            const auto [b2, b3] = gaussianPair(randomWords(7, RngPurpose::Shuffle, k, 2));
            const auto [u1, u2] = uniformPair(randomWords(7, RngPurpose::Shuffle, k, 3));
            const double ma = 5.3e-26, mb = k % 2 ? 5.3e-26 : 2.1e-26; // equal and unequal masses
            dsmc::Velocity a{300 * a1, 300 * a2, 300 * a3}, b{300 * b1 + 100, 300 * b2, 300 * b3};
            const dsmc::Velocity a0 = a, b0 = b;
            dsmc::scatterIsotropic(a, b, ma, mb, u1, u2);
            const double p0[3] = {ma * a0.x + mb * b0.x, ma * a0.y + mb * b0.y, ma * a0.z + mb * b0.z};
            const double p1[3] = {ma * a.x + mb * b.x, ma * a.y + mb * b.y, ma * a.z + mb * b.z};
            const double scale = ma * 1000;
            for (int c = 0; c < 3; ++c)
                worstMomentum = std::max(worstMomentum, std::abs(p1[c] - p0[c]) / scale);
            auto energy = [&](const dsmc::Velocity& x, const dsmc::Velocity& y) {
                return ma * (x.x * x.x + x.y * x.y + x.z * x.z) + mb * (y.x * y.x + y.y * y.y + y.z * y.z);
            };
            worstEnergy = std::max(worstEnergy, std::abs(energy(a, b) / energy(a0, b0) - 1));
            worstSpeed =
                std::max(worstSpeed, std::abs(dsmc::relativeSpeed(a, b) / dsmc::relativeSpeed(a0, b0) - 1));
        }
        QVERIFY2(worstMomentum < 1e-13, qPrintable(QString::number(worstMomentum)));
        QVERIFY2(worstEnergy < 1e-13, qPrintable(QString::number(worstEnergy)));
        QVERIFY2(worstSpeed < 1e-13, qPrintable(QString::number(worstSpeed)));
    }

    void scatteringIsIsotropic() {
        // Post-collision directions of c_r: ⟨n⟩ = 0 and ⟨n nᵀ⟩ = I/3 on the unit sphere.
        const int draws = 200000;
        double mean[3] = {0, 0, 0}, second[3] = {0, 0, 0};
        for (int k = 0; k < draws; ++k) {
            const auto [u1, u2] =
                uniformPair(randomWords(9, RngPurpose::Collision, 1, static_cast<std::uint64_t>(k)));
            dsmc::Velocity a{1, 0, 0}, b{-1, 0, 0};
            dsmc::scatterIsotropic(a, b, 1.0, 1.0, u1, u2);
            const double n[3] = {(a.x - b.x) / 2, (a.y - b.y) / 2, (a.z - b.z) / 2};
            for (int c = 0; c < 3; ++c) {
                mean[c] += n[c] / draws;
                second[c] += n[c] * n[c] / draws;
            }
        }
        // Standard errors: 1/√(3 draws) for the means, √(4/45 / draws) for the second moments.
        for (int c = 0; c < 3; ++c) {
            QVERIFY2(std::abs(mean[c]) < 5 / std::sqrt(3.0 * draws), qPrintable(QString::number(mean[c])));
            QVERIFY2(std::abs(second[c] - 1.0 / 3) < 5 * std::sqrt(4.0 / 45 / draws),
                     qPrintable(QString::number(second[c])));
        }
    }

    void theSeedRunEndsAtTheAnalyticTemperature() {
        auto model = instantiate(loadPreset("dsmc-write-up"));
        auto* dsmc = static_cast<DsmcModel*>(model.get());
        const DsmcObservables start = dsmc->observe();
        // Moment-matched beams: T = (T_x + 2 · 5 K)/3 with T_x = 5 K + m (100 m/s)² / k = 43.49 K.
        QVERIFY2(std::abs(start.t - 17.83) < 0.005, qPrintable(QString::number(start.t)));
        for (int s = 0; s < 500; ++s) model->step();
        const DsmcObservables end = dsmc->observe();
        QVERIFY2(std::abs(end.t - 17.83) < 0.005, qPrintable(QString::number(end.t, 'g', 10)));
        QVERIFY(std::abs(end.t / start.t - 1) < 1e-12); // energy: exact to round-off over 500 steps
        QVERIFY2(std::abs(end.ux - 200.0) < 1e-9, qPrintable(QString::number(end.ux, 'g', 17)));
        QVERIFY(std::abs(end.uy) < 1e-9 && std::abs(end.uz) < 1e-9);
        // Relaxed: ~12 collisions each. Each T_i of 2000 particles scatters by √(2/2000) ≈ 3 %.
        QVERIFY(end.collisionsPerParticle > 10);
        for (double ti : {end.tx, end.ty, end.tz})
            QVERIFY2(std::abs(ti / end.t - 1) < 0.1, qPrintable(QString::number(ti)));
        QVERIFY2(std::abs(end.kurtosisVx - 3.0) < 0.4, qPrintable(QString::number(end.kurtosisVx)));
    }

    void runsAreReproducible() {
        auto a = instantiate(loadPreset("dsmc-write-up"));
        auto b = instantiate(loadPreset("dsmc-write-up"));
        for (int s = 0; s < 200; ++s) {
            a->step();
            b->step();
        }
        const auto& sa = static_cast<DsmcModel*>(a.get())->state();
        const auto& sb = static_cast<DsmcModel*>(b.get())->state();
        QVERIFY(sa.vx == sb.vx && sa.vy == sb.vy && sa.vz == sb.vz);
        a->reset();
        for (int s = 0; s < 200; ++s) a->step();
        QVERIFY(static_cast<DsmcModel*>(a.get())->state().vx == sb.vx);
        Preset other = loadPreset("dsmc-write-up");
        other.seed += 1;
        auto c = instantiate(other);
        for (int s = 0; s < 200; ++s) c->step();
        QVERIFY(static_cast<DsmcModel*>(c.get())->state().vx != sb.vx);
    }

    void badParametersAreRejectedWithTheirKey() {
        DsmcModel model;
        try {
            model.setParams({{"count_a", 1.0}, {"count_b", 0.0}});
            QFAIL("one particle cannot collide");
        } catch (const ParamError& e) {
            QCOMPARE(QString::fromStdString(e.key()), QString("count_a"));
        }
        QCOMPARE(std::get<double>(model.params().at("count_a")), 1000.0); // nothing applied
        QVERIFY_THROWS_EXCEPTION(ParamError, model.setParams({{"cross_section", std::string("soft")}}));
        QVERIFY(!model.reversible());
    }

    // The cell and the wind tunnel describe a molecule with one table (dsmc/MolecularParams.h): the same
    // keys, labels, units, ranges and timing; each keeps its own defaults, gas and panel sections.
    void theCellAndTheTunnelDescribeAMoleculeAlike() {
        const std::vector<ParamSpec>&cell = DsmcParams::describe(), &tunnel = TunnelParams::describe();
        for (const char* key : {"mass_amu", "cross_section", "diameter", "vhs_d_ref", "vhs_T_ref",
                                "vhs_omega", "maxwell_sigma_cr"}) {
            const ParamSpec *a = findSpec(cell, key), *b = findSpec(tunnel, key);
            QVERIFY2(a && b, key);
            QCOMPARE(a->label, b->label);
            QCOMPARE(a->unit, b->unit);
            QVERIFY2(a->kind == b->kind && a->min == b->min && a->max == b->max && a->step == b->step, key);
            QVERIFY2(a->choices == b->choices && a->appliesLive == b->appliesLive, key);
        }
        QVERIFY(findSpec(cell, "vhs_omega")->defaultValue == ParamValue{DsmcParams{}.vhsOmega});
        QVERIFY(findSpec(tunnel, "vhs_omega")->defaultValue == ParamValue{TunnelParams{}.vhsOmega});
        QCOMPARE(findSpec(cell, "vhs_d_ref")->tooltip, std::string("VHS reference diameter (O2: 4.07e-10)."));
        QCOMPARE(findSpec(tunnel, "vhs_d_ref")->tooltip,
                 std::string("VHS reference diameter (argon: 4.17e-10)."));
        QCOMPARE(findSpec(cell, "cross_section")->group, std::string("Collisions"));
        QCOMPARE(findSpec(tunnel, "cross_section")->group, std::string("Gas"));
    }
};

QTEST_APPLESS_MAIN(TestDsmcCollision)
#include "tst_dsmc_collision.moc"
