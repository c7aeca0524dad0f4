// Statistical physics of the gas against theory (docs/gas.md#reference-formulas): Maxwell–Boltzmann speeds
// (KS test on decorrelated snapshots), virial pressure = wall pressure, equipartition between species,
// thermal walls setting the temperature, and the collision rate of kinetic theory.
#include "../BackendRows.h"
#include "GasTestScenes.h"
#include "catalog/ModelCatalog.h"
#include "common/Statistics.h"

#include <QtTest>
#include <numbers>

using namespace pl;

namespace {

void run(GasModel& model, int steps) {
    for (int s = 0; s < steps; ++s) model.step();
    QVERIFY2(!model.failure(), model.failure() ? model.failure()->message().c_str() : "");
}

} // namespace

class TestGasThermodynamics : public QObject {
    Q_OBJECT
private slots:
    void classroomReachesMaxwellBoltzmann_data() {
        QTest::addColumn<QString>("backend");
        QTest::addColumn<bool>("quarter");
        QTest::addColumn<int>("snapshots");
        QTest::newRow("cpu") << QStringLiteral("cpu") << false << 10;
        // llvmpipe costs ~3–8 ms a step whatever the size (dispatch overhead), so the gl row keeps the
        // steps and shrinks the rest: a quarter of the classroom (625 disks in the 1 × 1 box, the same
        // density, so the same contact rate per disk and the same thermalisation time) and 4 snapshots.
        QTest::newRow("gl") << QStringLiteral("gl") << true << 4;
    }

    // The same KS bound on the GL row: its float32 trajectory differs from the CPU's, but a gas in
    // equilibrium has the same speed distribution, and the test is statistical, not a comparison
    // (the critical value scales with the number of speeds, so fewer snapshots are as strict).
    void classroomReachesMaxwellBoltzmann() {
        QFETCH(bool, quarter);
        QFETCH(int, snapshots);
        Preset preset = loadPreset("gas-classroom");
        if (quarter) {
            preset.params["box_width"] = 1.0;
            preset.params["box_height"] = 1.0;
            preset.params["count_a"] = 625.0;
        }
        PL_MODEL_ON_ROW_BACKEND(made, preset);
        auto& model = made.as<GasModel>();
        // The start (all speeds equal) is far from Maxwell–Boltzmann.
        QVERIFY(model.observe().ksDistance[0] > 0.3);
        // About 25 contacts per disk per unit time: 3000 steps (t ≈ 1) thermalise, and snapshots
        // 300 steps apart (≈ 2.6 contacts per disk) are decorrelated.
        run(model, 3000);
        std::vector<double> scaled; // speeds in units of √(kT/m), kT from each snapshot's kinetic energy
        for (int snapshot = 0; snapshot < snapshots; ++snapshot) {
            run(model, 300);
            const auto o = model.observe();
            const auto& s = model.state();
            for (std::size_t i = 0; i < s.size(); ++i)
                scaled.push_back(std::hypot(s.vx[i], s.vy[i]) / std::sqrt(o.kT));
        }
        const double n = static_cast<double>(scaled.size());
        const double d = ksDistance(scaled, [](double v) { return rayleighCdf(v, 1.0, 1.0); });
        QVERIFY2(d < ksCritical(n, 0.01),
                 qPrintable(QString("D = %1, critical %2").arg(d).arg(ksCritical(n, 0.01))));
        // Moments of the Rayleigh distribution: <v⁴>/<v²>² = 2 in 2D. v² is exponential, so the ratio's
        // sampling error is ≈ 2 √(5/n): the bound 0.05 at the cpu row's 25 000 speeds is kept at the same
        // significance (1.8 standard errors) for the gl row's fewer speeds.
        double m2 = 0, m4 = 0;
        for (double v : scaled) m2 += v * v, m4 += v * v * v * v;
        const double ratio = m4 * n / (m2 * m2), bound = 0.05 * std::sqrt(25000 / n);
        QVERIFY2(std::abs(ratio - 2.0) < bound,
                 qPrintable(QString("%1, bound 2 ± %2").arg(ratio).arg(bound)));
    }

    void virialPressureEqualsWallPressure() {
        Preset p = loadPreset("gas-classroom");
        p.params["pressure_window"] = 100.0; // one window over the whole measurement
        GasModel model;
        model.reset(p);
        run(model, 2000);
        (void)model.observe(); // start the wall window after thermalisation
        model.setParams({{"pressure_window", 100.0}});
        double virial = 0, ideal = 0;
        int samples = 0;
        GasObservables o;
        for (int block = 0; block < 120; ++block) {
            run(model, 50);
            o = model.observe();
            virial += o.pressureVirial;
            ideal += o.pressureIdeal;
            ++samples;
        }
        virial /= samples;
        ideal /= samples;
        // The dense gas is far from ideal (area fraction 0.2), so agreement is a real check.
        QVERIFY(virial > 1.2 * ideal);
        // ~40 000 wall hits: the wall estimate carries ~1 % noise; 3 % is the bound.
        QVERIFY2(
            std::abs(o.pressureWall - virial) < 0.03 * virial,
            qPrintable(QString("wall %1, virial %2, ideal %3").arg(o.pressureWall).arg(virial).arg(ideal)));
    }

    void speciesShareEnergyEqually() {
        GasModel model;
        model.reset(loadPreset("gas-mixture"));
        auto o = model.observe();
        QVERIFY(o.kTSpecies[1] > 3.5 * o.kTSpecies[0]); // heavy disks start four times hotter
        run(model, 6000);
        double a = 0, b = 0;
        for (int k = 0; k < 20; ++k) {
            run(model, 100);
            o = model.observe();
            a += o.kTSpecies[0];
            b += o.kTSpecies[1];
        }
        QVERIFY2(std::abs(a - b) < 0.06 * (a + b) / 2,
                 qPrintable(QString("kT_a %1, kT_b %2").arg(a / 20).arg(b / 20)));
    }

    void thermalWallsSetTheTemperature() {
        // A near-ideal gas (tiny disks) between walls at kT = 1.2: a disk that has left a thermal wall
        // carries the wall's distribution, so kT → 1.2. Canonical fluctuations of kT are 1/√N ≈ 2 % per
        // snapshot; 10 snapshots half a wall-crossing time apart average them to ≈ 0.7 %.
        GasModel model = test::makeGas({{"count_a", 2000.0},
                                        {"box_width", 1.0},
                                        {"box_height", 1.0},
                                        {"diameter_a", 0.001},
                                        {"dt", 1e-3},
                                        {"wall_mode", std::string("thermal")},
                                        {"wall_kT", 1.2}});
        QVERIFY(std::abs(model.observe().kT - 0.5) < 1e-12);
        run(model, 5000); // t = 5: every disk has met the walls several times
        double kT = 0;
        for (int k = 0; k < 10; ++k) {
            run(model, 500);
            kT += model.observe().kT / 10;
        }
        QVERIFY2(std::abs(kT / 1.2 - 1) < 0.03, qPrintable(QString::number(kT)));
    }

    void collisionRateMatchesKineticTheory() {
        // Dilute hard-ish disks (area fraction φ = 0.05): contacts per disk per unit time
        // n · 2d · <v_rel> · χ(φ) with <v_rel> = √(π kT/m) and the 2D contact value
        // χ = (1 − 7φ/16) / (1 − φ)² (Henderson 1975).
        const double count = 1000, side = 2.5, d = 0.02;
        GasModel model = test::makeGas({{"count_a", count},
                                        {"box_width", side},
                                        {"box_height", side},
                                        {"diameter_a", d},
                                        {"stiffness", 1e5},
                                        {"dt", 3.5e-4},
                                        {"init_placement", std::string("lattice")},
                                        {"init_velocity", std::string("maxwell-boltzmann")},
                                        {"init_kT", 0.5}});
        run(model, 1000);
        (void)model.observe();
        run(model, 6000);
        const auto o = model.observe();
        const double n = count / (side * side);
        const double phi = n * std::numbers::pi * d * d / 4;
        const double chi = (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi));
        const double theory = n * 2 * d * std::sqrt(std::numbers::pi * o.kT) * chi;
        const double measured = 2 * o.collisionRate / count;
        QVERIFY2(std::abs(measured / theory - 1) < 0.06,
                 qPrintable(QString("%1 vs %2").arg(measured).arg(theory)));
    }
};

QTEST_APPLESS_MAIN(TestGasThermodynamics)
#include "tst_gas_thermodynamics.moc"
