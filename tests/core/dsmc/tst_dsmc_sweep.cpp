// DSMC's accuracy against cost: against the exact BKW curves the moment error falls like 1/√N with the
// particles per cell, while ν dt hardly matters in one homogeneous cell; cells that cannot be measured are
// classified, not thrown.
#include "catalog/ModelCatalog.h"
#include "dsmc/DsmcSweep.h"

#include <QtTest>

using namespace pl;
using methods::CellOutcome;

class TestDsmcSweep : public QObject {
    Q_OBJECT
private slots:
    void errorFallsWithParticles() {
        const Preset base = loadPreset("dsmc-bkw");
        double small = 0, large = 0;
        for (double nuDt : {0.03, 0.3, 1.0}) {
            const dsmc::DsmcCell a = dsmc::runDsmcCell(base, 1000, nuDt);
            const dsmc::DsmcCell b = dsmc::runDsmcCell(base, 64000, nuDt);
            QCOMPARE(a.status.outcome, CellOutcome::Stable);
            QCOMPARE(b.status.outcome, CellOutcome::Stable);
            QVERIFY(std::abs(a.dt / nuDt - 1e-5 / 0.03) < 1e-15); // the preset: ν dt = 0.03 at 1e-5 s
            qInfo("ν dt %.2f: moment error %.4f at 1000 particles, %.4f at 64000", nuDt, a.momentError,
                  b.momentError);
            small += a.momentError;
            large += b.momentError;
        }
        QVERIFY(large < small / 3); // √64 = 8 expected; noise in the noise allows less
    }

    void unmeasurableCellsAreClassified() {
        const dsmc::DsmcCell wrongStart = dsmc::runDsmcCell(loadPreset("dsmc-write-up"), 1000, 0.1);
        QCOMPARE(wrongStart.status.outcome, CellOutcome::Rejected);
        QVERIFY(wrongStart.status.detail.find("BKW") != std::string::npos);
        const dsmc::DsmcCell one = dsmc::runDsmcCell(loadPreset("dsmc-bkw"), 1, 0.1);
        QCOMPARE(one.status.outcome, CellOutcome::Rejected);
        QVERIFY(std::isfinite(one.momentError));
    }
};

QTEST_GUILESS_MAIN(TestDsmcSweep)
#include "tst_dsmc_sweep.moc"
