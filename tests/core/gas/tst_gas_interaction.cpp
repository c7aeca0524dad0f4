// What the user does between steps: static obstacles, spawning and removing disks, gravity. Checked
// against elementary mechanics (the dragged bodies and the piston: tst_gas_tools).
#include "GasTestScenes.h"
#include "catalog/ModelCatalog.h"

#include <QtTest>

using namespace pl;

namespace {

GasModel emptyBox(const ParamValues& extra = {}) {
    ParamValues values{{"count_a", 1.0}, {"diameter_a", 0.02}, {"stiffness", 1e5}, {"dt", 1e-3}};
    for (const auto& [k, v] : extra) values[k] = v;
    return test::makeGas(values);
}

} // namespace

class TestGasInteraction : public QObject {
    Q_OBJECT
private slots:
    void discObstacleReflectsHeadOn() {
        GasModel model = emptyBox();
        model.addObstacle({Obstacle::Shape::Disc, 0.5, 0.0, 0.1});
        model.placeParticles({{0.0, 0.0, 1.0, 0.0, 0}});
        for (int s = 0; s < 800; ++s) {
            model.step();
            QVERIFY(std::hypot(model.state().x[0] - 0.5, model.state().y[0]) >= 0.11 - 1e-12);
        }
        QVERIFY(std::abs(model.state().vx[0] + 1.0) < 1e-12); // reversed, speed kept
        QVERIFY(std::abs(model.state().vy[0]) < 1e-12);
        // Once removed, the obstacle no longer stops the disk.
        model.removeObstacle(0);
        QVERIFY(model.obstacles().empty());
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, model.removeObstacle(0));
        model.placeParticles({{0.0, 0.0, 1.0, 0.0, 0}});
        for (int s = 0; s < 800; ++s) model.step();
        QVERIFY(std::abs(model.state().x[0] - 0.8) < 1e-9);
    }

    void spawningHonoursCapOverlapAndWalls() {
        GasModel model = emptyBox({{"max_particles", 50.0}});
        model.placeParticles({{0.0, 0.0, 0.0, 0.0, 0}});
        // 10 × 10 lattice at 1.05 d, one site on the existing disk, capped at 50 disks.
        const auto r = model.spawnRectangle(-0.0945, -0.0945, 0.0945, 0.0945, 0, 0.5);
        QCOMPARE(r.added, 49LL);
        QVERIFY(r.refusedOverlap + r.refusedCap == 51);
        QVERIFY(r.refusedCap > 0);
        QVERIFY(r.message().find("Particle cap") != std::string::npos);
        QCOMPARE(model.particleCount(), 50u);
        QCOMPARE(model.parameters().a.count, 50LL);
        // Nothing lands outside the box.
        GasModel other = emptyBox();
        const auto outside = other.spawnRectangle(0.9, 0.9, 1.5, 1.5, 0, 0.5);
        QVERIFY(outside.refusedOutside > 0);
        for (std::size_t i = 0; i < other.state().size(); ++i) QVERIFY(other.state().x[i] <= 1.0);
    }

    void spawnedDisksCarryTheRequestedTemperature() {
        GasModel model = emptyBox({{"count_a", 0.0}, {"count_b", 0.0}, {"mass_b", 3.0}});
        const auto r = model.spawnRectangle(-0.9, -0.9, 0.9, 0.9, 1, 2.0);
        QVERIFY(r.added > 1500);
        const auto o = model.observe();
        QVERIFY(std::abs(o.kTSpecies[1] / 2.0 - 1) < 4.0 / std::sqrt(double(r.added)));
        QCOMPARE(model.parameters().b.count, r.added);
    }

    void removingDisks() {
        GasModel model;
        model.reset(loadPreset("gas-classroom"));
        const auto before = model.particleCount();
        const auto removed = model.removeInRectangle(-1, -1, 0, 1);
        QVERIFY(removed > 1000);
        QCOMPARE(model.particleCount(), before - removed);
        for (std::size_t i = 0; i < model.state().size(); ++i) QVERIFY(model.state().x[i] > 0);
        QVERIFY(model.removeNear(0.5, 0.0, 0.2) > 0);
        QCOMPARE(static_cast<std::size_t>(model.parameters().a.count), model.particleCount());
    }

    void gravityIsExactForVerlet() {
        // A constant force is integrated exactly by velocity Verlet: y = y₀ − g t²/2.
        GasModel model = emptyBox({{"gravity", 2.0}});
        model.placeParticles({{0.0, 0.8, 0.0, 0.0, 0}});
        for (int s = 0; s < 500; ++s) model.step();
        QVERIFY(std::abs(model.state().y[0] - (0.8 - 0.5 * 2.0 * 0.25)) < 1e-12);
        QVERIFY(std::abs(model.state().vy[0] + 1.0) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestGasInteraction)
#include "tst_gas_interaction.moc"
