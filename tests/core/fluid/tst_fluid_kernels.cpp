// The PBF kernels (docs/fluid.md#kernel-normalisation): the 2D constants integrate to 1 over the plane, the
// write-up's 3D ones to 315/(256 h) and 3/(2 h); the spiky gradient is the derivative of the spiky kernel and
// antisymmetric in the pair; s_corr is −k at r = Δq h. The λ pass's and the neighbour scan's wide builds
// (AVX, AVX-512) give the SSE2 builds' bits.
#include "common/CellList.h"
#include "fluid/FluidBoundaries.h"
#include "fluid/FluidKernels.h"
#include "fluid/FluidLambdaPass.h"
#include "fluid/FluidParams.h"
#include "fluid/FluidRowScan.h"

#include <QtTest>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

using namespace pl;

namespace {

// ∫ f(r) 2π r dr over [0, h] by composite Simpson with many panels: exact to ~1e-12 for these polynomials.
template <class F> double integrateOverDisc(F f, double h) {
    constexpr int panels = 20000;
    const double step = h / panels;
    double sum = 0;
    for (int k = 0; k <= panels; ++k) {
        const double r = k * step;
        const double weight = (k == 0 || k == panels) ? 1 : (k % 2 ? 4 : 2);
        sum += weight * f(r) * 2 * std::numbers::pi * r;
    }
    return sum * step / 3;
}

} // namespace

class TestFluidKernels : public QObject {
    Q_OBJECT
private slots:
    // Akinci et al. 2013's splines (eqs. 2 and 7) up to their constants, 1 at their peaks.
    void surfaceForceSplinesAreAkincisScaledToTheirPeaks() {
        const double h = 1.3;
        const auto akinciCohesion = [&](double r) { // eq. 2 without 32/(π h⁹)
            const double a = std::pow(h - r, 3) * std::pow(r, 3);
            return 2 * r > h ? a : 2 * a - std::pow(h, 6) / 64;
        };
        const auto akinciAdhesion = [&](double r) { // eq. 7 without 0.007/h^3.25
            return std::pow(-4 * r * r / h + 6 * r - 2 * h, 0.25);
        };
        for (int k = 1; k < 100; ++k) {
            const double q = k / 100.0;
            QVERIFY(std::abs(fluid::cohesionSpline(q) - akinciCohesion(q * h) / akinciCohesion(h / 2)) <
                    1e-12);
            if (q > 0.5)
                QVERIFY(std::abs(fluid::adhesionSpline(q) -
                                 akinciAdhesion(q * h) / akinciAdhesion(0.75 * h)) < 1e-12);
            else
                QCOMPARE(fluid::adhesionSpline(q), 0.0);
        }
        QCOMPARE(fluid::cohesionSpline(0.5), 1.0);
        QCOMPARE(fluid::adhesionSpline(0.75), 1.0);
        QCOMPARE(fluid::cohesionSpline(1.0), 0.0);
        QCOMPARE(fluid::cohesionSpline(0.0), 0.0); // the particle itself: no direction, no force
        QVERIFY(fluid::cohesionSpline(1e-9) < -0.999999);
    }

    // The cohesion of a lattice at the preset's spacing on one of its particles: none inside, a pull into the
    // fluid at its surface (and so surface tension). The adhesion pulls the second layer to a wall, not the
    // first, and points to a disc's centre.
    void cohesionPullsTheSurfaceInAndLeavesTheInterior() {
        const double h = 1.0, d = 0.5;
        const auto pull = [&](bool halfPlane) {
            double ax = 0, ay = 0;
            for (int a = -4; a <= 4; ++a)
                for (int b = -4; b <= (halfPlane ? 0 : 4); ++b) {
                    const double dx = -a * d, dy = -b * d, r = std::hypot(dx, dy); // x_i − x_j, x_i at 0
                    if (r == 0) continue;
                    ax -= fluid::cohesionSpline(r / h) / r * dx;
                    ay -= fluid::cohesionSpline(r / h) / r * dy;
                }
            return std::pair{ax, ay};
        };
        const auto [insideX, insideY] = pull(false);
        QVERIFY(std::abs(insideX) < 1e-12 && std::abs(insideY) < 1e-12);
        const auto [surfaceX, surfaceY] = pull(true);
        QVERIFY(std::abs(surfaceX) < 1e-12);
        QVERIFY2(surfaceY < -0.5, qPrintable(QString::number(surfaceY))); // towards the fluid below

        const fluid::Adhesion adhesion{20, 10, h, 2.0};
        double ax = 0, ay = 0;
        adhesion.add({}, 5, 0.25, ax, ay); // the first layer, at the particle radius
        QCOMPARE(ay, 0.0);
        adhesion.add({}, 5, 0.75, ax, ay);
        QCOMPARE(ay, -2.0);
        QCOMPARE(ax, 0.0);
        Obstacle disc;
        disc.x = 10;
        disc.y = 5;
        disc.radius = 2;
        ax = ay = 0;
        adhesion.add({disc}, 10 + 0.6 * (2 + 0.75), 5 + 0.8 * (2 + 0.75), ax, ay);
        QVERIFY(std::abs(ax + 2.0 * 0.6) < 1e-12 && std::abs(ay + 2.0 * 0.8) < 1e-12);
    }

    void twoDimensionalConstantsIntegrateToOne_data() {
        QTest::addColumn<double>("h");
        QTest::newRow("write-up h") << 1.1;
        QTest::newRow("small") << 0.25;
        QTest::newRow("large") << 3.0;
    }
    void twoDimensionalConstantsIntegrateToOne() {
        QFETCH(double, h);
        const auto k = fluid::Kernels::make(h, FluidKernelConstants::Normalised2d, true);
        // W at r = 0 through the self weight (pairs at r = 0 weigh nothing, as in the write-up).
        const auto poly6 = [&](double r) { return r > 0 ? k.w(r * r) : k.selfWeight(); };
        QVERIFY(std::abs(integrateOverDisc(poly6, h) - 1.0) < 1e-9);
        QVERIFY(std::abs(integrateOverDisc([&](double r) { return k.wSpiky(r); }, h) - 1.0) < 1e-9);
    }

    void seedConstantsAreTheThreeDimensionalOnes() {
        const double h = 1.1;
        const auto k = fluid::Kernels::make(h, FluidKernelConstants::Unnormalised3d, true);
        const auto poly6 = [&](double r) { return r > 0 ? k.w(r * r) : k.selfWeight(); };
        QVERIFY(std::abs(integrateOverDisc(poly6, h) - 315.0 / (256.0 * h)) < 1e-9);
        QVERIFY(std::abs(integrateOverDisc([&](double r) { return k.wSpiky(r); }, h) - 1.5 / h) < 1e-9);
        // The write-up's code: poly6Value(r) = 315/(64π) ((h² − r²)/h³)³.
        const double r = 0.6;
        const double x = (h * h - r * r) / (h * h * h);
        QCOMPARE(k.w(r * r), 315.0 / (64.0 * std::numbers::pi) * x * x * x);
        QCOMPARE(fluid::Kernels::make(h, FluidKernelConstants::Unnormalised3d, false).selfWeight(), 0.0);
        QCOMPARE(k.w(0.0), 0.0);
        QCOMPARE(k.w(h * h), 0.0);
    }

    void spikyGradientIsTheKernelsDerivative_data() {
        QTest::addColumn<QString>("normalisation");
        QTest::newRow("2d") << "2d";
        QTest::newRow("3d") << "3d";
    }
    void spikyGradientIsTheKernelsDerivative() {
        QFETCH(QString, normalisation);
        const double h = 1.1;
        const auto k =
            fluid::Kernels::make(h, *choiceNamed<FluidKernelConstants>(normalisation.toStdString()), false);
        for (double r : {0.05, 0.3, 0.7, 1.0, 1.09}) {
            const double dr = 1e-6;
            const double numeric = (k.wSpiky(r + dr) - k.wSpiky(r - dr)) / (2 * dr);
            // ∇W = gradFactor · (x_i − x_j); along r̂ its length is gradFactor · r.
            QVERIFY2(std::abs(k.gradFactor(r * r) * r - numeric) < 1e-6 * std::abs(numeric) + 1e-9,
                     qPrintable(QString("r = %1").arg(r)));
        }
        QCOMPARE(k.gradFactor(0.0), 0.0);
        QCOMPARE(k.gradFactor(h * h), 0.0);
    }

    void spikyGradientIsAntisymmetric() {
        const auto k = fluid::Kernels::make(1.1, FluidKernelConstants::Normalised2d, true);
        const double xi = 0.31, yi = -0.12, xj = -0.27, yj = 0.45;
        const double dx = xi - xj, dy = yi - yj, r2 = dx * dx + dy * dy;
        const double gijx = k.gradFactor(r2) * dx, gijy = k.gradFactor(r2) * dy;
        const double gjix = k.gradFactor(r2) * -dx, gjiy = k.gradFactor(r2) * -dy;
        QCOMPARE(gijx + gjix, 0.0);
        QCOMPARE(gijy + gjiy, 0.0);
        QVERIFY(gijx < 0); // ∇_i W points from i towards j: W falls as i moves away
    }

    void artificialPressureIsMinusKAtTheReferenceDistance() {
        const double h = 1.1;
        const auto k = fluid::Kernels::make(h, FluidKernelConstants::Unnormalised3d, false);
        const double dq = 0.3 * h;
        fluid::ArtificialPressure s{0.001, 1.0 / k.w(dq * dq), 4};
        QVERIFY(std::abs(s(k.w(dq * dq)) + 0.001) < 1e-15);
        QVERIFY(s(k.w(0.9 * 0.9)) > -0.001 && s(k.w(0.9 * 0.9)) < 0); // weaker further out
        QCOMPARE(s(0.0), 0.0);
    }

    // The λ pass in AVX (two slots of a block per instruction) and in AVX-512 (four) gives the SSE2 pass's
    // bits: blocks of 0 to 9 slots (so the wide loops' tails of one to three slots run), padded slots (the
    // particle itself), pairs inside and beyond h, a coincident pair, an odd particle count, with and
    // without s_corr.
    void lambdaPassWideBuildsGiveTheSse2Bits_data() {
        QTest::addColumn<QString>("build");
        QTest::addColumn<double>("scorrK");
        for (const char* build : {"AVX", "AVX-512"}) {
            QTest::addRow("%s, s_corr on", build) << QString(build) << 0.001;
            QTest::addRow("%s, s_corr off", build) << QString(build) << 0.0;
        }
    }
    void lambdaPassWideBuildsGiveTheSse2Bits() {
        QFETCH(QString, build);
        QFETCH(double, scorrK);
        const fluid::LambdaBlocksFunction wide =
            build == "AVX" ? fluid::lambdaBlocksAvx() : fluid::lambdaBlocksAvx512();
        if (!wide) QSKIP("this CPU lacks the instructions: the SSE2 pass runs instead");
        const double h = 1.1;
        const auto kernels = fluid::Kernels::make(h, FluidKernelConstants::Unnormalised3d, false);
        const double dq = 0.3 * h;
        const fluid::ArtificialPressure scorr{scorrK, 1.0 / kernels.w(dq * dq), 4};
        const long long count = 301, blocks = (count + 1) / 2;
        std::mt19937_64 random(7);
        std::uniform_real_distribution<double> position(0.0, 1.6); // most pairs within h, some beyond
        std::vector<double> px(count), py(count);
        for (long long i = 0; i < count; ++i) px[i] = position(random), py[i] = position(random);
        px[1] = px[0], py[1] = py[0]; // a coincident pair: r = 0, where every term is 0
        std::vector<std::uint32_t> blockStart{0}, lanes;
        for (long long b = 0; b < blocks; ++b) {
            const auto slotCount = static_cast<std::uint32_t>(b == 0 ? 3 : b % 10);
            for (std::uint32_t t = 0; t < slotCount; ++t)
                for (long long lane = 0; lane < 2; ++lane) {
                    const long long self = std::min(2 * b + lane, count - 1);
                    const bool padded = random() % 5 == 0;
                    lanes.push_back(static_cast<std::uint32_t>(padded ? self : random() % count));
                }
            blockStart.push_back(blockStart.back() + slotCount);
        }
        lanes[0] = 1, lanes[1] = 0; // the first slot of block 0: particles 0 and 1, coincident
        struct Outputs {
            std::vector<double> values[8]; // pair gradients x, y; λ, C; G x, y; S x, y
        };
        auto run = [&](fluid::LambdaBlocksFunction blocksFunction) {
            Outputs o;
            for (int a = 0; a < 8; ++a) o.values[a].assign(a < 2 ? lanes.size() : std::size_t(count), -1.0);
            const fluid::LambdaArrays arrays{px.data(),
                                             py.data(),
                                             blockStart.data(),
                                             lanes.data(),
                                             o.values[2].data(),
                                             o.values[3].data(),
                                             o.values[0].data(),
                                             o.values[1].data(),
                                             o.values[4].data(),
                                             o.values[5].data(),
                                             o.values[6].data(),
                                             o.values[7].data(),
                                             count,
                                             nullptr};
            const fluid::LambdaConstants constants{fluid::LaneKernels(kernels, scorr), kernels.selfWeight(),
                                                   1.0 / 1.3, 100.0, false};
            blocksFunction(arrays, constants, 0, blocks);
            return o;
        };
        const Outputs sse2 = run(fluid::lambdaBlocksSse2()), avx = run(wide);
        int inside = 0, pairs = 0; // the case has pairs inside h and beyond it
        for (double g : sse2.values[0]) inside += g != 0.0, ++pairs;
        QVERIFY(inside > pairs / 3 && inside < pairs);
        for (int a = 0; a < 8; ++a)
            QVERIFY2(std::memcmp(sse2.values[a].data(), avx.values[a].data(),
                                 sse2.values[a].size() * sizeof(double)) == 0,
                     qPrintable(QString("output array %1 differs").arg(a)));
    }

    // The neighbour rows' scan in AVX-512 (eight candidates per compare, packed by a compress) writes the
    // SSE2 scan's rows and counts: cells of 0 to ~12 particles (so every masked tail length runs), pairs
    // at the radius to rounding, coincident pairs, the particle itself among its candidates, and a clump that
    // overflows a small row capacity (the count is still exact, which is what makes the search repeat).
    void rowScanAvx512GivesTheSse2Rows_data() {
        QTest::addColumn<std::uint32_t>("capacity");
        QTest::addColumn<bool>("overflows");
        QTest::newRow("rows large enough") << std::uint32_t{64} << false;
        QTest::newRow("rows that overflow") << std::uint32_t{16} << true;
    }
    void rowScanAvx512GivesTheSse2Rows() {
        QFETCH(std::uint32_t, capacity);
        QFETCH(bool, overflows);
        if (!fluid::rowScanAvx512()) QSKIP("this CPU has no AVX-512F: the SSE2 scan is the only one");
        const double reach = 1.0, width = 12.0, height = 9.0;
        const std::size_t count = 500;
        std::mt19937_64 random(11);
        std::uniform_real_distribution<double> along(0.0, width), up(0.0, height), clump(4.0, 4.6);
        std::vector<double> x(count), y(count);
        for (std::size_t i = 0; i < count; ++i) {
            const bool inClump = i % 25 == 0;
            x[i] = inClump ? clump(random) : along(random);
            y[i] = inClump ? clump(random) : up(random);
        }
        x[1] = x[0], y[1] = y[0];                              // coincident
        x[3] = x[2] + reach, y[3] = y[2];                      // at the radius, to rounding
        x[5] = x[4] + std::nextafter(reach, 0.0), y[5] = y[4]; // a rounding inside it
        CellList cells;
        cells.configure(0.0, 0.0, width, height, reach);
        cells.build(x.data(), y.data(), count);
        std::vector<double> sortedX(count), sortedY(count);
        for (std::size_t k = 0; k < count; ++k)
            sortedX[k] = x[cells.order()[k]], sortedY[k] = y[cells.order()[k]];
        auto run = [&](fluid::RowScanFunction scan, std::vector<std::uint32_t>& rows,
                       std::vector<std::uint32_t>& counts) {
            rows.assign(count * (capacity + 1), 0xFFFFFFFFu);
            counts.assign(count, 0);
            const fluid::RowScanInputs in{sortedX.data(),
                                          sortedY.data(),
                                          cells.order().data(),
                                          cells.cellOfParticle().data(),
                                          cells.cellStart().data(),
                                          cells.cellsX(),
                                          cells.cellsY(),
                                          reach * reach,
                                          capacity,
                                          rows.data(),
                                          counts.data()};
            return scan(in, 0, static_cast<long long>(count));
        };
        std::vector<std::uint32_t> sse2Rows, sse2Counts, wideRows, wideCounts;
        const std::uint32_t sse2Largest = run(fluid::rowScanSse2(), sse2Rows, sse2Counts);
        const std::uint32_t wideLargest = run(fluid::rowScanAvx512(), wideRows, wideCounts);
        QCOMPARE(wideLargest, sse2Largest);
        QVERIFY(wideCounts == sse2Counts);
        int overflowed = 0;
        for (std::size_t k = 0; k < count; ++k) {
            if (sse2Counts[k] > capacity) {
                ++overflowed;
                continue; // an overflowed row's entries are not used: the search repeats
            }
            const auto* a = sse2Rows.data() + k * (capacity + 1);
            const auto* b = wideRows.data() + k * (capacity + 1);
            QVERIFY2(std::equal(a, a + sse2Counts[k], b), qPrintable(QString("row %1 differs").arg(k)));
        }
        qInfo("largest row %u, %d of %zu rows past a capacity of %u", sse2Largest, overflowed, count,
              capacity);
        QCOMPARE(overflowed > 0, overflows);
        QVERIFY(overflowed < static_cast<int>(count) / 2); // most rows are compared
    }
};

QTEST_APPLESS_MAIN(TestFluidKernels)
#include "tst_fluid_kernels.moc"
