// The sweep runner survives every failure class: a cell that throws (bad parameters, no memory, anything
// else), blows up, escapes the box, diverges or over-compresses is classified with a message, and
// nothing non-finite leaves it; the cells before and after it are unaffected.
#include "common/sweep/CellOutcome.h"
#include "fluid/FluidSweep.h"
#include "gas/StabilityMap.h"

#include <QtTest>

using namespace pl;
using methods::CellOutcome;
using methods::CellStatus;

class TestMethodsCells : public QObject {
    Q_OBJECT

private slots:
    void runnerCatchesEveryException() {
        const CellStatus a = methods::runIsolated([](CellStatus&) { throw std::bad_alloc(); });
        QCOMPARE(a.outcome, CellOutcome::Rejected);
        QCOMPARE(a.detail, std::string("not enough memory for this cell"));
        const CellStatus b = methods::runIsolated([](CellStatus&) { throw std::invalid_argument("dt < 0"); });
        QCOMPARE(b.outcome, CellOutcome::Rejected);
        QCOMPARE(b.detail, std::string("dt < 0"));
        const CellStatus c = methods::runIsolated([](CellStatus&) { throw 42; });
        QCOMPARE(c.outcome, CellOutcome::Rejected);
        QVERIFY(!c.detail.empty());
        const CellStatus d = methods::runIsolated([](CellStatus& s) {
            s.outcome = CellOutcome::Stable;
            s.steps = 3;
        });
        QCOMPARE(d.outcome, CellOutcome::Stable);
        QCOMPARE(d.steps, 3LL);
        QVERIFY(d.seconds >= 0);
    }

    void gasCellsClassifyEachFailure() {
        const double omega = gas::cagedOmega(1000.0);
        // A parameter the model refuses: classified, with the model's message.
        const gas::StabilityCell unknown = gas::runStabilityCell("leapfrog-9000", 0.1 / omega, 1000.0);
        QCOMPARE(unknown.status.outcome, CellOutcome::Rejected);
        QVERIFY(unknown.status.detail.find("leapfrog-9000") != std::string::npos);
        const gas::StabilityCell negative = gas::runStabilityCell("velocity-verlet", 0.1 / omega, -5.0);
        QCOMPARE(negative.status.outcome, CellOutcome::Rejected);
        QVERIFY(negative.status.detail.find("stiffness") != std::string::npos);
        // Growth caught by the cell, and a step so large the disk leaves the box in one go.
        const gas::StabilityCell grows = gas::runStabilityCell("velocity-verlet", 2.2 / omega, 1000.0);
        QCOMPARE(grows.status.outcome, CellOutcome::Unstable);
        const gas::StabilityCell leaps =
            gas::runStabilityCell("velocity-verlet", 200.0 / gas::cagedOmega(1e5), 1e5);
        QCOMPARE(leaps.status.outcome, CellOutcome::Unstable);
        QVERIFY(!leaps.status.detail.empty());
        for (const auto* c : {&unknown, &negative, &grows, &leaps}) QVERIFY(std::isfinite(c->energyError));
        // And the next cell runs as if nothing happened.
        QCOMPARE(gas::runStabilityCell("velocity-verlet", 0.1 / omega, 1000.0).status.outcome,
                 CellOutcome::Stable);
    }

    void fluidCellsClassifyEachFailure() {
        const Preset base = fluid::smallDamBreak();
        fluid::FluidSweepSetup setup;
        setup.duration = 0.4;
        const fluid::FluidCell fine = fluid::runFluidCell(base, 0.01, 5, setup);
        QCOMPARE(fine.status.outcome, CellOutcome::Stable);
        QVERIFY(fine.densityErrorMean > 0 && fine.densityErrorMean < setup.tolerance);
        const fluid::FluidCell coarse = fluid::runFluidCell(base, 0.08, 1, setup);
        QCOMPARE(coarse.status.outcome, CellOutcome::OverCompressed);
        QVERIFY(coarse.densityErrorMean > setup.tolerance);
        const fluid::FluidCell hot = fluid::runFluidCell(base, 0.00125, 1, setup);
        QCOMPARE(hot.status.outcome, CellOutcome::Exploded);
        QVERIFY(hot.status.detail.find("kinetic energy") != std::string::npos);
        const fluid::FluidCell refused = fluid::runFluidCell(base, 0.01, 0, setup);
        QCOMPARE(refused.status.outcome, CellOutcome::Rejected);
        QVERIFY(refused.status.detail.find("iterations") != std::string::npos);
        for (const auto* c : {&fine, &coarse, &hot, &refused})
            QVERIFY(std::isfinite(c->densityErrorMean) && std::isfinite(c->densityErrorMax) &&
                    std::isfinite(c->secondsPerTime));
    }

    void fluidErrorFallsWithIterationsAndRisesWithDt() {
        const Preset base = fluid::smallDamBreak();
        fluid::FluidSweepSetup setup;
        setup.duration = 0.4;
        double previous = 1e9;
        for (int iterations : {1, 2, 4, 8}) {
            const fluid::FluidCell c = fluid::runFluidCell(base, 0.02, iterations, setup);
            qInfo("dt 0.02, %d iterations: mean density error %.5f, %.3f s per unit time", iterations,
                  c.densityErrorMean, c.secondsPerTime);
            QVERIFY(c.densityErrorMean < previous);
            previous = c.densityErrorMean;
        }
        QVERIFY(fluid::runFluidCell(base, 0.04, 4, setup).densityErrorMean >
                fluid::runFluidCell(base, 0.01, 4, setup).densityErrorMean);
    }
};

QTEST_GUILESS_MAIN(TestMethodsCells)
#include "tst_methods_cells.moc"
