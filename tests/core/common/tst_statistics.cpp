// Statistics helpers: the Rayleigh (2D Maxwell–Boltzmann) moments of
// docs/gas.md#maxwell-boltzmann-speeds-in-2d, the KS test against exact samples and the power-law fit used
// for convergence orders; histogram normalisation.
#include "common/Histogram.h"
#include "common/Philox.h"
#include "common/Statistics.h"

#include <QtTest>

using namespace pl;

class TestStatistics : public QObject {
    Q_OBJECT
private slots:
    void rayleighMatchesReferenceMoments() {
        // In units of √(kT/m): median 1.17741 (docs/gas.md#maxwell-boltzmann-speeds-in-2d), most probable 1.
        QVERIFY(std::abs(rayleighCdf(1.17741, 1.0, 1.0) - 0.5) < 1e-5);
        QVERIFY(rayleighPdf(1.0, 1.0, 1.0) > rayleighPdf(0.99, 1.0, 1.0));
        QVERIFY(rayleighPdf(1.0, 1.0, 1.0) > rayleighPdf(1.01, 1.0, 1.0));
        // Mean 1.25331 = √(π/2) by quadrature of v f(v).
        double mean = 0, norm = 0;
        const double dv = 1e-4;
        for (double v = 0.5 * dv; v < 12; v += dv)
            mean += v * rayleighPdf(v, 2.0, 2.0) * dv, norm += rayleighPdf(v, 2.0, 2.0) * dv;
        QVERIFY(std::abs(norm - 1) < 1e-6);
        QVERIFY(std::abs(mean - 1.25331) < 1e-5);
    }

    void ksAcceptsExactSamplesAndRejectsWrongTemperature() {
        std::vector<double> v, copy;
        for (std::uint32_t i = 0; i < 4000; ++i) {
            const auto [u, w] = uniformPair(randomWords(3, RngPurpose::Spawn, i, 0));
            (void)w;
            v.push_back(std::sqrt(-2.0 * 0.7 * std::log(u))); // inverse CDF, kT/m = 0.7
        }
        copy = v;
        const double crit = ksCritical(4000, 0.01);
        QVERIFY(ksDistance(v, [](double s) { return rayleighCdf(s, 0.7, 1.0); }) < crit);
        QVERIFY(ksDistance(copy, [](double s) { return rayleighCdf(s, 0.8, 1.0); }) > crit);
    }

    void twoSampleKsDistanceAndPValue() {
        // Exact distances of small samples: interleaved, shifted, identical.
        std::vector<double> a{1, 3, 5, 7}, b{2, 4, 6, 8};
        QCOMPARE(ksTwoSampleDistance(a, b), 0.25);
        std::vector<double> c{1, 2, 3, 4}, d{5, 6, 7, 8};
        QCOMPARE(ksTwoSampleDistance(c, d), 1.0);
        std::vector<double> e{1, 1, 2}, f{1, 1, 2};
        QCOMPARE(ksTwoSampleDistance(e, f), 0.0);
        // Q_KS at the tabulated points: λ = 1.358 gives 0.05, 1.628 gives 0.01.
        const double n = 1e8; // λ ≈ √(n/2) D for large equal samples
        QVERIFY(std::abs(ksTwoSamplePValue(1.358 / std::sqrt(n / 2), n, n) - 0.05) < 1e-3);
        QVERIFY(std::abs(ksTwoSamplePValue(1.628 / std::sqrt(n / 2), n, n) - 0.01) < 2e-4);
        QCOMPARE(ksTwoSamplePValue(0.0, 100, 100), 1.0);
        // Two samples of one distribution pass; a shifted one fails.
        std::vector<double> x, y, z;
        for (std::uint32_t i = 0; i < 2000; ++i) {
            x.push_back(uniformPair(randomWords(5, RngPurpose::Spawn, i, 0)).a);
            y.push_back(uniformPair(randomWords(5, RngPurpose::Spawn, i, 1)).a);
            z.push_back(uniformPair(randomWords(5, RngPurpose::Spawn, i, 2)).a + 0.1);
        }
        std::vector<double> x2 = x;
        QVERIFY(ksTwoSamplePValue(ksTwoSampleDistance(x, y), 2000, 2000) > 0.01);
        QVERIFY(ksTwoSamplePValue(ksTwoSampleDistance(x2, z), 2000, 2000) < 1e-6);
    }

    void kurtosisOfKnownSamples() {
        QCOMPARE(kurtosis({-1, 1, -1, 1}), 1.0);            // two spikes
        QCOMPARE(kurtosis({-2, 0, 0, 0, 0, 0, 0, 2}), 4.0); // ⟨x⁴⟩ = 4, ⟨x²⟩ = 1
        QVERIFY(std::isnan(kurtosis({5, 5, 5})));
    }

    void powerLawFitRecoversExponent() {
        std::vector<double> x{0.1, 0.05, 0.025, 0.0125}, y;
        for (double h : x) y.push_back(3.0 * h * h * h * h);
        const auto fit = fitPowerLaw(x, y);
        QVERIFY(std::abs(fit.exponent - 4.0) < 1e-10);
        QVERIFY(std::abs(fit.prefactor - 3.0) < 1e-8);
    }

    void histogramDensityIntegratesToInRangeFraction() {
        Histogram h(0.0, 1.0, 10);
        for (int i = 0; i < 90; ++i) h.add((i + 0.5) / 90.0);
        h.add(-1.0);
        h.add(5.0);
        double integral = 0;
        for (std::size_t b = 0; b < h.bins(); ++b) integral += h.density(b) * h.binWidth();
        QCOMPARE(h.total(), 92.0);
        QVERIFY(std::abs(integral - 90.0 / 92.0) < 1e-12);
        QCOMPARE(h.count(0), 9.0);
    }
};

QTEST_APPLESS_MAIN(TestStatistics)
#include "tst_statistics.moc"
