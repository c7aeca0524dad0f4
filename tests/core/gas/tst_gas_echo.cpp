// Time reversal measured: the Loschmidt echo grows with n in floating point and is exactly zero in the
// bit-reversible integer scheme (Levesque & Verlet 1993).
#include "gas/TimeReversal.h"

#include <QtTest>

using namespace pl::gas;

class TestGasEcho : public QObject {
    Q_OBJECT

private slots:
    // 10⁵ steps out and 10⁵ back: every coordinate returns bit for bit, although the gas went far.
    void integerSchemeReturnsExactlyAfter1e5Steps() {
        EchoSetup setup;
        setup.disks = 49;
        const IntegerVerletGas origin(setup);
        IntegerVerletGas gas = origin;
        constexpr long long kSteps = 100000;
        for (long long s = 0; s < kSteps; ++s) gas.step();
        const double away = gas.rmsDistance(origin);
        gas.reverse();
        for (long long s = 0; s < kSteps; ++s) gas.step();
        gas.reverse();
        qInfo("rms distance from the start after 1e5 steps: %.3g L (the box is 1 L)", away);
        QVERIFY(away > 1.0); // unwrapped: the disks travelled across many boxes
        QVERIFY(gas.x() == origin.x());
        QVERIFY(gas.y() == origin.y());
        // The previous configuration returned too: the next steps coincide.
        IntegerVerletGas again = origin;
        gas.step(), again.step();
        QVERIFY(gas.x() == again.x() && gas.y() == again.y());
    }

    // Floating point: round-off grows exponentially in the chaotic gas, faster in float than in double;
    // the integer scheme stays at zero.
    void echoGrowsWithRoundOff() {
        const auto points = loschmidtEcho(EchoSetup{}, {100, 1000, 3000});
        for (const auto& p : points)
            qInfo("n = %lld: double %.3g, float %.3g, integer %.3g", p.steps, p.rmsDouble, p.rmsFloat,
                  p.rmsInteger);
        for (const auto& p : points) {
            QCOMPARE(p.rmsInteger, 0.0);
            QVERIFY(p.rmsFloat > p.rmsDouble);
        }
        QVERIFY(points[2].rmsDouble > 100 * points[0].rmsDouble);
        QVERIFY(points[2].rmsFloat > 100 * points[0].rmsFloat);
    }
};

QTEST_GUILESS_MAIN(TestGasEcho)
#include "tst_gas_echo.moc"
