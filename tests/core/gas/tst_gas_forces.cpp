// Force search: the cell list gives the all-pairs forces to round-off, for one and two species, and the
// total force is zero (Newton's third law, momentum conservation).
#include "GasTestScenes.h"

#include <QtTest>

using namespace pl;

class TestGasForces : public QObject {
    Q_OBJECT
private slots:
    void cellListEqualsAllPairs_data() {
        QTest::addColumn<double>("countB");
        QTest::addColumn<QString>("placement");
        QTest::newRow("one species, random") << 0.0 << "random";
        QTest::newRow("two species, random") << 300.0 << "random";
        QTest::newRow("two species, lattice") << 300.0 << "lattice";
    }
    void cellListEqualsAllPairs() {
        QFETCH(double, countB);
        QFETCH(QString, placement);
        ParamValues values{{"count_a", 1500.0},
                           {"count_b", countB},
                           {"diameter_a", 0.03},
                           {"diameter_b", 0.05},
                           {"box_width", 2.0},
                           {"box_height", 1.5},
                           {"init_placement", placement.toStdString()}};
        GasModel cells = test::makeGas(values, 17);
        values["force_method"] = std::string("all-pairs");
        GasModel pairs = test::makeGas(values, 17);
        for (int s = 0; s < 5; ++s) cells.step(), pairs.step(); // forces after motion too
        (void)cells.totalEnergy(); // steps skip the per-disk energies; observables refresh them
        (void)pairs.totalEnergy();
        const auto& a = cells.state();
        const auto& b = pairs.state();
        double scale = 0, worst = 0;
        int touching = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            scale = std::max(scale, std::hypot(b.ax[i], b.ay[i]));
            worst = std::max(worst, std::hypot(a.ax[i] - b.ax[i], a.ay[i] - b.ay[i]));
            touching += a.potential[i] > 0;
        }
        QVERIFY(touching > 50); // the comparison involves real contacts
        QVERIFY2(worst <= 1e-12 * scale, qPrintable(QString("%1 of %2").arg(worst).arg(scale)));
        QVERIFY(test::rmsDistance(a, b) < 1e-12);
    }

    void totalForceVanishes() {
        GasModel model = test::makeGas({{"count_a", 2000.0}, {"count_b", 200.0}, {"diameter_a", 0.03}}, 4);
        double fx = 0, fy = 0, scale = 0;
        const auto& s = model.state();
        const auto& p = model.parameters();
        for (std::size_t i = 0; i < s.size(); ++i) {
            const double m = s.species[i] ? p.b.mass : p.a.mass;
            fx += m * s.ax[i];
            fy += m * s.ay[i];
            scale += m * std::hypot(s.ax[i], s.ay[i]);
        }
        QVERIFY(scale > 0);
        QVERIFY(std::hypot(fx, fy) < 1e-13 * scale);
    }

    void momentumConservedAwayFromWalls() {
        // A cloud in the middle of a large box: in 200 steps no disk reaches a wall, so only pair
        // forces act and the total momentum is conserved to round-off.
        GasModel model = test::makeGas({{"count_a", 400.0},
                                        {"box_width", 20.0},
                                        {"box_height", 20.0},
                                        {"diameter_a", 0.05},
                                        {"init_velocity", std::string("maxwell-boltzmann")}});
        std::vector<GasParticle> cloud;
        for (std::size_t i = 0; i < model.state().size(); ++i)
            cloud.push_back({model.state().x[i] * 0.05, model.state().y[i] * 0.05, model.state().vx[i],
                             model.state().vy[i], 0});
        model.placeParticles(cloud);
        const auto p0 = test::totalMomentum(model);
        for (int s = 0; s < 200; ++s) model.step();
        const auto p1 = test::totalMomentum(model);
        QVERIFY(model.observe().collisionRate > 0);
        QVERIFY2(std::hypot(p1.first - p0.first, p1.second - p0.second) < 1e-12,
                 qPrintable(QString::number(std::hypot(p1.first - p0.first, p1.second - p0.second))));
    }
};

QTEST_APPLESS_MAIN(TestGasForces)
#include "tst_gas_forces.moc"
