// Counter-based RNG: known-answer vectors of Philox4x32-10 and the statistics of the derived variates.
#include "common/Philox.h"
#include "common/Statistics.h"

#include <QtTest>

using namespace pl;

class TestPhilox : public QObject {
    Q_OBJECT
private slots:
    void knownAnswers() {
        // Reference vectors of Salmon et al. (Random123 kat_vectors).
        QCOMPARE(philox4x32({0, 0, 0, 0}, {0, 0}),
                 (Philox4x32{0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u}));
        QCOMPARE(philox4x32({0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu}, {0xffffffffu, 0xffffffffu}),
                 (Philox4x32{0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu}));
        QCOMPARE(philox4x32({0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u}, {0xa4093822u, 0x299f31d0u}),
                 (Philox4x32{0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u}));
    }
    void streamsDifferByPurposeSubjectAndSequence() {
        const auto a = randomWords(1, RngPurpose::InitialVelocity, 7, 0);
        QVERIFY(a != randomWords(1, RngPurpose::InitialPosition, 7, 0));
        QVERIFY(a != randomWords(1, RngPurpose::InitialVelocity, 8, 0));
        QVERIFY(a != randomWords(1, RngPurpose::InitialVelocity, 7, 1));
        QVERIFY(a != randomWords(2, RngPurpose::InitialVelocity, 7, 0));
        QCOMPARE(a, randomWords(1, RngPurpose::InitialVelocity, 7, 0));
    }
    void uniformsPassKolmogorovSmirnov() {
        std::vector<double> u;
        for (std::uint32_t i = 0; i < 20000; ++i) {
            const auto [a, b] = uniformPair(randomWords(42, RngPurpose::Spawn, i, 0));
            QVERIFY(a > 0 && a < 1 && b > 0 && b < 1);
            u.push_back(a);
            u.push_back(b);
        }
        const double d = ksDistance(u, [](double x) { return x; });
        QVERIFY2(d < ksCritical(static_cast<double>(u.size()), 0.01), qPrintable(QString::number(d)));
    }
    void gaussiansHaveUnitVarianceAndNormalTails() {
        std::vector<double> g;
        double sum = 0, sum2 = 0;
        for (std::uint32_t i = 0; i < 20000; ++i) {
            const auto [a, b] = gaussianPair(randomWords(9, RngPurpose::InitialVelocity, i, 3));
            for (double v : {a, b}) sum += v, sum2 += v * v, g.push_back(v);
        }
        const double n = static_cast<double>(g.size());
        QVERIFY(std::abs(sum / n) < 4.0 / std::sqrt(n));
        QVERIFY(std::abs(sum2 / n - 1.0) < 4.0 * std::sqrt(2.0 / n));
        const double d = ksDistance(g, [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); });
        QVERIFY2(d < ksCritical(n, 0.01), qPrintable(QString::number(d)));
    }
};

QTEST_APPLESS_MAIN(TestPhilox)
#include "tst_philox.moc"
