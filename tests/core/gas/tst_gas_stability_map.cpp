// The gas's stability map: on the caged harmonic disk each integrator blows up where the linear theory
// says (ω dt = 2 for Verlet and symplectic Euler, 2√2 for RK4, 1.5734 for Forest–Ruth, at once for
// explicit Euler), at any stiffness, and its bounded energy error is the analytic one.
#include "gas/GasModel.h"
#include "gas/StabilityMap.h"

#include <QtTest>

using namespace pl;
using namespace pl::gas;
using methods::CellOutcome;

namespace {
std::vector<StabilityCell> row(const std::string& integrator, double stiffness, double from, double to,
                               double step) {
    std::vector<StabilityCell> cells;
    for (double w = from; w <= to + 1e-9; w += step)
        cells.push_back(runStabilityCell(integrator, w / cagedOmega(stiffness), stiffness));
    return cells;
}
} // namespace

class TestGasStabilityMap : public QObject {
    Q_OBJECT

private slots:
    void verletBoundaryIsOmegaDtTwo() {
        for (double k : {100.0, 1e4}) {
            const auto cells = row("velocity-verlet", k, 1.0, 3.0, 0.05);
            const double limit = measuredLimit(cells);
            qInfo("velocity Verlet, k = %g: stable up to ω dt = %.3f", k, limit);
            QVERIFY(std::abs(limit - 2.0) <= 0.2); // the 10 %
            for (const auto& c : cells) {
                QVERIFY(std::isfinite(c.energyError));
                if (c.omegaDt < 1.95) QVERIFY(c.status.outcome != CellOutcome::Unstable);
                if (c.omegaDt > 2.05) QCOMPARE(c.status.outcome, CellOutcome::Unstable);
            }
        }
    }

    void everySchemeMeetsItsLinearLimit() {
        for (const std::string name : {"symplectic-euler", "rk4", "forest-ruth"}) {
            const double theory = stabilityLimit(integratorFromName(name));
            const double limit = measuredLimit(row(name, 1000.0, 0.5 * theory, 1.5 * theory, 0.025 * theory));
            qInfo("%-16s stable up to ω dt = %.3f (theory %.4f)", name.c_str(), limit, theory);
            QVERIFY2(std::abs(limit - theory) <= 0.1 * theory, name.c_str());
        }
        // Explicit Euler has no stable dt: the energy grows by 1 + ω²dt² per step.
        const auto euler = row("explicit-euler", 1000.0, 0.1, 1.0, 0.3);
        for (const auto& c : euler) QCOMPARE(c.status.outcome, CellOutcome::Unstable);
    }

    void verletEnergyErrorIsAnalytic() {
        // Verlet conserves v² + ω²x²(1 − q) exactly, q = (ω dt)²/4, so from rest at x = A we have |x| ≤ A
        // and E = ½v² + ½ω²x² = E₀ (1 − q) + q ½ω²x²: E lies in [E₀ (1 − q), E₀], reaching the bottom
        // at a step that lands on x = 0. At ω dt = 1 (six steps a period) the nearest is x = A/2: 3q/4.
        for (const auto& [w, expected] : {std::pair{0.1, 0.0025}, {0.5, 0.0625}, {1.0, 0.1875}}) {
            const StabilityCell c = runStabilityCell("velocity-verlet", w / cagedOmega(1000.0), 1000.0);
            qInfo("ω dt = %.1f: energy error %.6f (analytic %.6f)", w, c.energyError, expected);
            QVERIFY2(std::abs(c.energyError - expected) < 1e-3 * expected, std::to_string(w).c_str());
        }
    }

    void classifiesByTolerance() {
        StabilitySetup strict;
        strict.tolerance = 1e-4;
        const double dt = 0.1 / cagedOmega(1000.0);
        QCOMPARE(runStabilityCell("velocity-verlet", dt, 1000.0).status.outcome, CellOutcome::Stable);
        QCOMPARE(runStabilityCell("velocity-verlet", dt, 1000.0, strict).status.outcome,
                 CellOutcome::Inaccurate);
    }
};

QTEST_GUILESS_MAIN(TestGasStabilityMap)
#include "tst_gas_stability_map.moc"
