// Determinism: the same preset and seed give bit-identical states at 1 and 2 OpenMP threads, including
// the random draws of thermal walls and spawning.
#include "GasTestScenes.h"
#include "catalog/ModelCatalog.h"
#include "common/Parallel.h"

#include <QtTest>
#include <omp.h>

using namespace pl;

namespace {

GasState runWithThreads(int threads, const Preset& preset, int steps) {
    omp_set_num_threads(threads);
    GasModel model;
    model.reset(preset);
    for (int s = 0; s < steps; ++s) {
        model.step();
        if (s == steps / 2) model.spawnRectangle(-0.2, -0.2, 0.2, 0.2, 1, 0.5);
    }
    (void)model.observe();
    return model.state();
}

} // namespace

class TestGasDeterminism : public QObject {
    Q_OBJECT
private slots:
    void bitIdenticalAcrossThreadCounts_data() {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QString>("integrator");
        QTest::newRow("write-up, verlet") << "gas-write-up"
                                          << "velocity-verlet";
        QTest::newRow("mixture, rk4") << "gas-mixture"
                                      << "rk4";
        QTest::newRow("mixture, forest-ruth") << "gas-mixture"
                                              << "forest-ruth";
    }
    void bitIdenticalAcrossThreadCounts() {
        QFETCH(QString, preset);
        QFETCH(QString, integrator);
        Preset p = loadPreset(preset.toStdString());
        p.params["count_a"] = 4000.0; // above the size at which loops go parallel
        p.params["integrator"] = integrator.toStdString();
        p.params["wall_mode"] = std::string("thermal");
        p.params["wall_kT"] = 0.8;
        p.params["gravity"] = 0.3;
        const GasState one = runWithThreads(1, p, 200);
        const GasState two = runWithThreads(2, p, 200);
        QVERIFY(static_cast<long long>(one.size()) >= kParallelMinParticles);
        QVERIFY(one.x == two.x);
        QVERIFY(one.y == two.y);
        QVERIFY(one.vx == two.vx);
        QVERIFY(one.vy == two.vy);
        QVERIFY(one.id == two.id);
    }
};

QTEST_APPLESS_MAIN(TestGasDeterminism)
#include "tst_gas_determinism.moc"
