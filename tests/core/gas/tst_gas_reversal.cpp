// Time reversal: velocity Verlet run n steps forward, then n steps with −dt, retraces the trajectory;
// in floating point the return error is round-off amplified by the gas's chaos
// (docs/gas.md#reversibility-in-floating-point).
#include "GasTestScenes.h"
#include "catalog/ModelCatalog.h"

#include <QtTest>

using namespace pl;

namespace {

// Hard-ish disks (20 steps per contact) that hit the walls and, if given, obstacles.
GasModel hardDisks(std::vector<Obstacle> obstacles = {}) {
    return test::makeGas({{"count_a", 300.0},
                          {"box_width", 0.8},
                          {"box_height", 0.8},
                          {"diameter_a", 0.02},
                          {"stiffness", 1e5},
                          {"dt", 3.5e-4},
                          {"init_placement", std::string("lattice")}},
                         3, std::move(obstacles));
}

double returnError(GasModel& model, int steps) {
    const GasState start = model.state();
    const double dt = model.parameters().dt;
    for (int s = 0; s < steps; ++s) model.step();
    model.setParams({{"dt", -dt}});
    for (int s = 0; s < steps; ++s) model.step();
    return test::rmsDistance(start, model.state());
}

} // namespace

class TestGasReversal : public QObject {
    Q_OBJECT
private slots:
    void seedGasRetracesItsPath() {
        // The write-up's soft disks: each moves 0.04 (4 diameters) in 400 steps, many hit the walls, few
        // bounce off each other, so round-off (1e-16 of positions of order 1) barely grows: measured
        // 9e-17. The bound 1e-14 leaves a factor 100.
        GasModel model;
        model.reset(loadPreset("gas-write-up"));
        const double error = returnError(model, 400);
        QVERIFY2(error < 1e-14, qPrintable(QString::number(error)));
        QCOMPARE(model.stepCount(), 800LL);
        QVERIFY(std::abs(model.time()) < 1e-15);
    }

    void hardDisksRetraceWithWallsAndObstacles() {
        // Hard-ish disks hitting walls and a disc obstacle: 2.4 collisions per disk in 300 steps. Each
        // collision amplifies a perturbation by about free path / diameter ≈ 9 (measured: 1.6e-15 after
        // 300 steps, 5e-9 after 1000), so 1e-16 grows to ~1e-15; the bound 1e-13 leaves a factor 60.
        GasModel model = hardDisks({{Obstacle::Shape::Disc, 0.1, 0.1, 0.08}});
        const double error = returnError(model, 300);
        QVERIFY2(error < 1e-13, qPrintable(QString::number(error)));
    }

    void chaosAmplifiesRoundOff() {
        // The same gas run longer returns worse: the error grows exponentially with n (Loschmidt echo;
        // measured 6e-17 after 100 steps, 1e-5 after 1500), so a return bound is a statement about the
        // horizon, not about the integrator.
        auto run = [](int steps) {
            GasModel model = hardDisks();
            return returnError(model, steps);
        };
        const double shortRun = run(100), longRun = run(1500);
        QVERIFY2(longRun > 1e6 * shortRun, qPrintable(QString("%1 %2").arg(shortRun).arg(longRun)));
    }
};

QTEST_APPLESS_MAIN(TestGasReversal)
#include "tst_gas_reversal.moc"
