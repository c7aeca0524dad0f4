// What the user does between steps: obstacles (static and dragged), the piston, spawning and removing
// disks, gravity. Checked against elementary mechanics.
#include "MdTestScenes.h"
#include "catalog/ModelCatalog.h"

#include <QtTest>

using namespace pl;

namespace {

MdModel emptyBox(const ParamValues& extra = {}) {
    ParamValues values{{"count_a", 1.0}, {"diameter_a", 0.02}, {"stiffness", 1e5}, {"dt", 1e-3}};
    for (const auto& [k, v] : extra) values[k] = v;
    return test::makeGas(values);
}

} // namespace

class TestMdInteraction : public QObject {
    Q_OBJECT
private slots:
    void discObstacleReflectsHeadOn() {
        MdModel model = emptyBox();
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

    void draggedObstacleImpartsItsVelocity() {
        // A disk at rest struck by a wall moving at u leaves at 2u (elastic reflection off a massive wall).
        MdModel model = emptyBox();
        model.addObstacle({Obstacle::Shape::Box, -0.2, 0.0, 0.1, 0.1, 0.2});
        model.placeParticles({{0.0, 0.0, 0.0, 0.0, 0}});
        const double u = 0.5; // reaches the disk after ≈ 160 steps
        for (int s = 0; s < 400; ++s) {
            const Obstacle& o = model.obstacles()[0];
            model.moveObstacle(0, o.x + u * 1e-3, o.y, u, 0.0);
            model.step();
        }
        QVERIFY(std::abs(model.state().vx[0] - 2 * u) < 1e-12);
        QVERIFY(model.state().x[0] > model.obstacles()[0].x + 0.11);
    }

    void draggingAnObstaclePushesTheGas() {
        MdModel model;
        model.reset(loadPreset("gas-classroom"));
        model.addObstacle({Obstacle::Shape::Disc, -0.6, 0.0, 0.15});
        const double px0 = test::totalMomentum(model).first;
        for (int s = 0; s < 300; ++s) {
            const Obstacle& o = model.obstacles()[0];
            model.moveObstacle(0, o.x + 2.0 * 3.5e-4, o.y, 2.0, 0.0);
            model.step();
        }
        QVERIFY(!model.failure());
        QVERIFY(test::totalMomentum(model).first - px0 > 10.0); // the gas is swept to +x
    }

    void pistonCompressionHeatsTheGas() {
        // Quasi-static compression of a dilute 2D gas (γ = 2): kT · A is constant, so halving the area
        // doubles kT. The piston moves at 0.03, much slower than the disks (≈ 1).
        MdModel model = test::makeGas({{"count_a", 600.0},
                                       {"diameter_a", 0.02},
                                       {"stiffness", 1e5},
                                       {"dt", 5e-4},
                                       {"init_placement", std::string("lattice")},
                                       {"piston_enabled", true},
                                       {"init_velocity", std::string("maxwell-boltzmann")},
                                       {"init_kT", 0.5}});
        const double kT0 = model.observe().kT;
        const double speed = 0.03, dt = 5e-4;
        while (model.parameters().pistonX > 0.0) {
            model.movePiston(model.parameters().pistonX - speed * dt, -speed);
            model.step();
        }
        QVERIFY(!model.failure());
        double kT = 0;
        for (int k = 0; k < 10; ++k) {
            model.movePiston(0.0, 0.0);
            for (int s = 0; s < 200; ++s) model.step();
            kT += model.observe().kT / 10;
        }
        for (std::size_t i = 0; i < model.state().size(); ++i) QVERIFY(model.state().x[i] <= 0.0);
        QVERIFY2(std::abs(kT / (2 * kT0) - 1) < 0.1, qPrintable(QString("kT %1 from %2").arg(kT).arg(kT0)));
    }

    void spawningHonoursCapOverlapAndWalls() {
        MdModel model = emptyBox({{"max_particles", 50.0}});
        model.placeParticles({{0.0, 0.0, 0.0, 0.0, 0}});
        // 10 × 10 lattice at 1.05 d, one site on the existing disk, capped at 50 disks.
        const auto r = model.spawnRectangle(-0.0945, -0.0945, 0.0945, 0.0945, 0, 0.5);
        QCOMPARE(r.added, 49LL);
        QVERIFY(r.refusedOverlap + r.refusedCap == 51);
        QVERIFY(r.refusedCap > 0);
        QVERIFY(r.message().find("max_particles") != std::string::npos);
        QCOMPARE(model.particleCount(), 50u);
        QCOMPARE(model.parameters().a.count, 50LL);
        // Nothing lands outside the box.
        MdModel other = emptyBox();
        const auto outside = other.spawnRectangle(0.9, 0.9, 1.5, 1.5, 0, 0.5);
        QVERIFY(outside.refusedOutside > 0);
        for (std::size_t i = 0; i < other.state().size(); ++i) QVERIFY(other.state().x[i] <= 1.0);
    }

    void spawnedDisksCarryTheRequestedTemperature() {
        MdModel model = emptyBox({{"count_a", 0.0}, {"count_b", 0.0}, {"mass_b", 3.0}});
        const auto r = model.spawnRectangle(-0.9, -0.9, 0.9, 0.9, 1, 2.0);
        QVERIFY(r.added > 1500);
        const auto o = model.observe();
        QVERIFY(std::abs(o.kTSpecies[1] / 2.0 - 1) < 4.0 / std::sqrt(double(r.added)));
        QCOMPARE(model.parameters().b.count, r.added);
    }

    void removingDisks() {
        MdModel model;
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
        MdModel model = emptyBox({{"gravity", 2.0}});
        model.placeParticles({{0.0, 0.8, 0.0, 0.0, 0}});
        for (int s = 0; s < 500; ++s) model.step();
        QVERIFY(std::abs(model.state().y[0] - (0.8 - 0.5 * 2.0 * 0.25)) < 1e-12);
        QVERIFY(std::abs(model.state().vy[0] + 1.0) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestMdInteraction)
#include "tst_md_interaction.moc"
