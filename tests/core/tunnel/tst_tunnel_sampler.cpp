// The wind tunnel's sampler on states built here, not by the model: a drifting Maxwellian of known n, u, T
// gives its moments back within the sampling noise, cut and empty cells, exact body forces and their
// window / interval / last-step bookkeeping, the fields CSV, and profiles along a line.
#include "common/Philox.h"
#include "common/SampledFields.h"
#include "dsmc/DsmcParams.h"
#include "tunnel/TunnelSampler.h"

#include <QtTest>

#include <sstream>

using namespace pl;

namespace {

constexpr int kNx = 4, kNy = 3;
constexpr double kCell = 0.01; // square cells [m]
constexpr double kFn = 1e12;   // real molecules per particle per m of depth
const double kMass = 39.948 * kAtomicMass;
constexpr double kGamma = 5.0 / 3.0;
constexpr double kUx = 500, kUy = -200, kT = 300; // the drifting Maxwellian [m/s], [K]
constexpr std::uint64_t kSeed = 20260;
constexpr std::size_t kEmptyCell = 2 * kNx + 3;    // (3, 2): no gas
constexpr std::size_t kCutCell = 1 * kNx + 1;      // (1, 1): gas in its lower half only
constexpr double kOpenCells = kNx * kNy - 1 - 0.5; // the gas's area in cells
constexpr int kParticlesPerStep = 2100;            // 200 per full cell and step
constexpr int kSteps = 100;

SamplingGrid testGrid() {
    SamplingGrid grid;
    grid.nx = kNx, grid.ny = kNy;
    grid.left = 0, grid.bottom = 0, grid.right = kNx * kCell, grid.top = kNy * kCell;
    grid.fn = kFn, grid.mass = kMass, grid.gamma = kGamma;
    return grid;
}

std::uint32_t cellOf(double x, double y) {
    return std::uint32_t(int(y / kCell) * kNx + int(x / kCell));
}

bool holdsGas(double x, double y) {
    const std::uint32_t c = cellOf(x, y);
    if (c == kEmptyCell) return false;
    return c != kCutCell || y - std::floor(y / kCell) * kCell < 0.5 * kCell;
}

// One step's particles: uniform over the gas's area, velocities from the drifting Maxwellian (Bird 1994
// eq. 4.1), independent of every other step's.
TunnelState maxwellianState(std::uint64_t step, std::vector<double>& counts) {
    const double sigma = std::sqrt(kBoltzmann * kT / kMass);
    TunnelState state;
    for (std::uint32_t draw = 0; int(state.size()) < kParticlesPerStep; ++draw) {
        const auto [a, b] = uniformPair(randomWords(kSeed, RngPurpose::InitialPosition, draw, step));
        const double x = a * kNx * kCell, y = b * kNy * kCell;
        if (!holdsGas(x, y)) continue;
        const auto [g1, g2] = gaussianPair(randomWords(kSeed, RngPurpose::InitialVelocity, draw, 2 * step));
        const auto [g3, unused] =
            gaussianPair(randomWords(kSeed, RngPurpose::InitialVelocity, draw, 2 * step + 1));
        state.append(x, y, {kUx + sigma * g1, kUy + sigma * g2, sigma * g3});
        state.cell.back() = cellOf(x, y);
        counts[state.cell.back()] += 1;
    }
    return state;
}

// Within `sigmas` standard errors, with the values in the message.
bool near(double value, double expected, double standardError, QString& why, const char* what, int cell) {
    constexpr double sigmas = 5;
    if (std::abs(value - expected) <= sigmas * standardError) return true;
    why = QString("cell %1 %2: %3, theory %4 ± %5")
              .arg(cell)
              .arg(what)
              .arg(value)
              .arg(expected)
              .arg(standardError);
    return false;
}

std::vector<double> fieldValues(const TunnelSampler& sampler, const char* name) {
    return sampler.field(name).values;
}

std::vector<BodyForce> forcesOf(std::initializer_list<BodyForce> list) {
    return list;
}

void compareForces(const std::vector<BodyForce>& got, const std::vector<BodyForce>& expected) {
    QCOMPARE(got.size(), expected.size());
    for (std::size_t b = 0; b < got.size(); ++b) {
        const double scale = std::max({std::abs(expected[b].drag), std::abs(expected[b].lift), 1e-300});
        QVERIFY2(std::abs(got[b].drag - expected[b].drag) <= 1e-14 * scale &&
                     std::abs(got[b].lift - expected[b].lift) <= 1e-14 * scale,
                 qPrintable(QString("body %1: %2, %3 instead of %4, %5")
                                .arg(b)
                                .arg(got[b].drag)
                                .arg(got[b].lift)
                                .arg(expected[b].drag)
                                .arg(expected[b].lift)));
    }
}

} // namespace

class TestTunnelSampler : public QObject {
    Q_OBJECT
private slots:
    void driftingMaxwellianGivesItsMoments() {
        TunnelSampler sampler;
        sampler.configure(testGrid());
        std::vector<double> counts(kNx * kNy, 0.0);
        for (int s = 0; s < kSteps; ++s) sampler.addState(maxwellianState(std::uint64_t(s), counts));
        QCOMPARE(sampler.sampledSteps(), std::int64_t(kSteps));

        // Without open fractions the cut cell's half of the gas reads as half the density; telling the
        // sampler the cell is half open doubles it (to round-off) and leaves every other field as it was.
        const std::vector<double> nWhole = fieldValues(sampler, "n");
        const std::vector<double> TWhole = fieldValues(sampler, "T");
        std::vector<double> open(kNx * kNy, 1.0);
        open[kCutCell] = 0.5;
        sampler.setOpenFraction(open);
        const std::vector<double> nCut = fieldValues(sampler, "n");
        QVERIFY(std::abs(nCut[kCutCell] / nWhole[kCutCell] - 2.0) < 1e-15);
        const std::vector<double> TCut = fieldValues(sampler, "T");
        for (std::size_t c = 0; c < TCut.size(); ++c)
            QVERIFY(TCut[c] == TWhole[c] || (std::isnan(TCut[c]) && std::isnan(TWhole[c])));
        for (std::size_t c = 0; c < nCut.size(); ++c)
            if (c != kCutCell && c != kEmptyCell) QCOMPARE(nCut[c], nWhole[c]);

        // Theory per cell; the standard errors come from the samples the cell holds (all independent:
        // each step is a fresh draw). The count in a cell is binomial, relative error ≤ 1/√(expected
        // count); a mean velocity component has σ/√N with σ² = kT/m; T_x and T_y, sample variances of
        // normal deviates, have T √(2/N); T, the mean of three, T √(2/(3N)); Mach = |u|/a carries both,
        // δM/M = √((σ/(|u|√N))² + (δT/2T)²). Five standard errors: over 11 cells × 7 fields a false alarm
        // is below 10⁻⁴ for any seed. The moment's 1/N bias (T from the same sample's mean) is 10⁻⁴ of T.
        const double n0 = kParticlesPerStep * kFn / (kOpenCells * kCell * kCell);
        const double sigma = std::sqrt(kBoltzmann * kT / kMass), speed = std::hypot(kUx, kUy);
        const double mach = speed / std::sqrt(kGamma * kBoltzmann * kT / kMass);
        const auto n = fieldValues(sampler, "n"), ux = fieldValues(sampler, "ux"),
                   uy = fieldValues(sampler, "uy"), T = fieldValues(sampler, "T"),
                   Tx = fieldValues(sampler, "Tx"), Ty = fieldValues(sampler, "Ty"),
                   M = fieldValues(sampler, "mach"), U = fieldValues(sampler, "speed");
        QString why;
        for (int c = 0; c < kNx * kNy; ++c) {
            if (std::size_t(c) == kEmptyCell) continue;
            const double N = counts[std::size_t(c)];
            const double expectedCount =
                kSteps * kParticlesPerStep * (c == int(kCutCell) ? 0.5 : 1.0) / kOpenCells;
            QVERIFY(N > 5000);
            const double dT = kT * std::sqrt(2.0 / (3.0 * N));
            QVERIFY2(near(n[c], n0, n0 / std::sqrt(expectedCount), why, "n", c), qPrintable(why));
            QVERIFY2(near(ux[c], kUx, sigma / std::sqrt(N), why, "ux", c), qPrintable(why));
            QVERIFY2(near(uy[c], kUy, sigma / std::sqrt(N), why, "uy", c), qPrintable(why));
            QVERIFY2(near(U[c], speed, sigma / std::sqrt(N), why, "speed", c), qPrintable(why));
            QVERIFY2(near(Tx[c], kT, kT * std::sqrt(2.0 / N), why, "Tx", c), qPrintable(why));
            QVERIFY2(near(Ty[c], kT, kT * std::sqrt(2.0 / N), why, "Ty", c), qPrintable(why));
            QVERIFY2(near(T[c], kT, dT, why, "T", c), qPrintable(why));
            const double dM = mach * std::hypot(sigma / (speed * std::sqrt(N)), dT / (2 * kT));
            QVERIFY2(near(M[c], mach, dM, why, "mach", c), qPrintable(why));
        }

        // The empty cell, and a sampled cell with no open area, give NaN in every field.
        for (const FieldChoice& choice : sampler.fieldChoices())
            QVERIFY(std::isnan(sampler.field(choice.name).values[kEmptyCell]));
        open[0] = 0.0;
        sampler.setOpenFraction(open);
        for (const FieldValue& value : sampler.probe(0.5 * kCell, 0.5 * kCell))
            QVERIFY(std::isnan(value.value));
    }

    void probeGivesEveryFieldOfTheCell() {
        TunnelSampler sampler;
        sampler.configure(testGrid());
        std::vector<double> counts(kNx * kNy, 0.0);
        sampler.addState(maxwellianState(0, counts));
        const auto choices = sampler.fieldChoices();
        QStringList names;
        for (const FieldChoice& c : choices) names << QString::fromStdString(c.name);
        QCOMPARE(names, QStringList({"n", "ux", "uy", "speed", "T", "Tx", "Ty", "mach"}));
        const auto values = sampler.probe(2.5 * kCell, 0.2 * kCell); // cell (2, 0)
        QCOMPARE(values.size(), choices.size());
        for (std::size_t k = 0; k < values.size(); ++k) {
            QCOMPARE(values[k].choice.name, choices[k].name);
            QCOMPARE(values[k].value, sampler.field(choices[k].name).values[2]);
        }
        QVERIFY(sampler.probe(-1e-9, 0.01).empty());
        QVERIFY(sampler.probe(0.01, kNy * kCell + 1e-9).empty());
        QCOMPARE(sampler.probe(kNx * kCell, kNy * kCell).size(), choices.size()); // corner: the last cell
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sampler.field("pressure"));
        // restart() empties the window: nothing sampled, every field NaN.
        sampler.restart();
        QCOMPARE(sampler.sampledSteps(), std::int64_t(0));
        for (double v : fieldValues(sampler, "n")) QVERIFY(std::isnan(v));
    }

    // Sums gathered elsewhere (the GL backend's) give the fields addState() gives for the same steps.
    void cellSumsAddLikeStates() {
        TunnelSampler direct, summed;
        direct.configure(testGrid());
        summed.configure(testGrid());
        std::vector<double> counts(kNx * kNy, 0.0);
        std::vector<TunnelSampler::CellSums> sums(kNx * kNy);
        for (std::uint64_t s = 0; s < 3; ++s) {
            const TunnelState state = maxwellianState(s, counts);
            direct.addState(state);
            for (std::size_t i = 0; i < state.size(); ++i) {
                TunnelSampler::CellSums& c = sums[state.cell[i]];
                c.count += 1;
                c.mx += state.vx[i], c.my += state.vy[i], c.mz += state.vz[i];
                c.ex += state.vx[i] * state.vx[i], c.ey += state.vy[i] * state.vy[i];
                c.ez += state.vz[i] * state.vz[i];
            }
        }
        summed.addCellSums(sums, 3);
        QCOMPARE(summed.sampledSteps(), direct.sampledSteps());
        for (const FieldChoice& choice : direct.fieldChoices()) {
            const auto a = direct.field(choice.name).values, b = summed.field(choice.name).values;
            for (std::size_t c = 0; c < a.size(); ++c)
                QVERIFY(std::abs(a[c] - b[c]) <= 1e-12 * std::abs(a[c]) ||
                        (std::isnan(a[c]) && std::isnan(b[c])));
        }
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, summed.addCellSums({}, 1));
    }

    void impulsesGiveTheExactForces() {
        TunnelSampler sampler;
        sampler.configure(testGrid());
        const double dt = 2e-7;
        // A molecule at 1000 m/s reversed by body 0's front (its Δv_x = −2000 m/s) pushes the body
        // downstream: F = −fn m Δv / dt = +fn · 2000 m / dt; one deflected upwards by body 1 lifts it down.
        auto impulse = [&](double scale) {
            sampler.addSurfaceImpulse(0, -2000.0 * kMass * scale, 0.0);
            sampler.addSurfaceImpulse(0, 0.0, 300.0 * kMass * scale);
            sampler.addSurfaceImpulse(1, 100.0 * kMass * scale, 700.0 * kMass * scale);
        };
        auto force = [&](double scale) {
            const double f = kFn * kMass * scale / dt;
            return forcesOf({{2000.0 * f, -300.0 * f}, {-100.0 * f, -700.0 * f}});
        };
        auto mean = [](const std::vector<BodyForce>& a, const std::vector<BodyForce>& b) {
            std::vector<BodyForce> m(a.size());
            for (std::size_t k = 0; k < a.size(); ++k)
                m[k] = {(a[k].drag + b[k].drag) / 2, (a[k].lift + b[k].lift) / 2};
            return m;
        };
        const TunnelState empty;
        const std::vector<BodyForce> zero(2);

        // Step 1, before the window opens: the last step and the interval see it, the window does not.
        impulse(1.0);
        sampler.endStep(2, dt);
        compareForces(sampler.lastForces(), force(1.0));
        compareForces(sampler.averageForces(), zero);
        // Steps 2 and 3 inside the window.
        sampler.addState(empty);
        impulse(3.0);
        sampler.endStep(2, dt);
        compareForces(sampler.takeIntervalForces(), mean(force(1.0), force(3.0)));
        sampler.addState(empty);
        impulse(-2.0);
        sampler.endStep(2, dt);
        compareForces(sampler.lastForces(), force(-2.0));
        compareForces(sampler.averageForces(), mean(force(3.0), force(-2.0)));
        compareForces(sampler.takeIntervalForces(), force(-2.0));
        // No step since the previous call: the same state, so the same interval as that call.
        compareForces(sampler.takeIntervalForces(), force(-2.0));

        // restart() empties the window, not the interval or the last step; until addState() the window
        // stays closed.
        sampler.restart();
        compareForces(sampler.averageForces(), zero);
        compareForces(sampler.lastForces(), force(-2.0));
        impulse(5.0);
        sampler.endStep(2, dt);
        compareForces(sampler.averageForces(), zero);
        compareForces(sampler.takeIntervalForces(), force(5.0));
        // A step without impulses is a zero force, and it counts.
        sampler.addState(empty);
        sampler.endStep(2, dt);
        compareForces(sampler.lastForces(), zero);
        compareForces(sampler.averageForces(), zero);
        sampler.addState(empty);
        impulse(4.0);
        sampler.endStep(2, dt);
        compareForces(sampler.averageForces(), mean(zero, force(4.0)));
    }

    void fieldsCsvHasTheHeaderAndExactRows() {
        // Two molecules in cell (1, 0) for one step: every moment is known in closed form.
        SamplingGrid grid = testGrid();
        grid.nx = 2, grid.ny = 2, grid.left = -0.1, grid.right = 0.1, grid.bottom = 0.0, grid.top = 0.3;
        TunnelSampler sampler;
        sampler.configure(grid);
        TunnelState state;
        state.append(0.05, 0.1, {600.0, 100.0, 30.0});
        state.append(0.02, 0.05, {200.0, -100.0, -30.0});
        state.cell = {1, 1};
        sampler.addState(state);
        std::ostringstream csv;
        sampler.writeFieldsCsv(csv);
        const QStringList lines = QString::fromStdString(csv.str()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + 4);
        QCOMPARE(lines[0], QString("i,j,x,y,n,ux,uy,T,Tx,Ty,mach"));
        const QStringList row = lines[2].split(','); // row-major: (0,0), (1,0), (0,1), (1,1)
        QCOMPARE(row.size(), 11);
        QCOMPARE(row[0], QString("1"));
        QCOMPARE(row[1], QString("0"));
        // Cell centres, written with enough digits to read back the same double.
        QCOMPARE(row[2].toDouble(), -0.1 + 1.5 * (0.2 / 2));
        QCOMPARE(row[3].toDouble(), 0.0 + 0.5 * (0.3 / 2));
        // Two samples (a ± d): mean a, variance d², per component; T the mean of the three.
        const double kOverM = kBoltzmann / kMass;
        const double Tx = 200.0 * 200.0 / kOverM, Ty = 100.0 * 100.0 / kOverM, Tz = 30.0 * 30.0 / kOverM;
        const double T = (Tx + Ty + Tz) / 3;
        const double expected[] = {
            2 * kFn / (0.1 * 0.15), 400.0, 0.0, T, Tx, Ty, 400.0 / std::sqrt(kGamma * kOverM * T)};
        for (int k = 0; k < 7; ++k) {
            const double value = row[4 + k].toDouble();
            QVERIFY2(std::abs(value - expected[k]) <= 1e-12 * std::max(1.0, std::abs(expected[k])),
                     qPrintable(
                         QString("column %1: %2 instead of %3").arg(k + 4).arg(row[4 + k]).arg(expected[k])));
        }
        // The cells without samples write nan.
        for (int line : {1, 3, 4})
            for (const QString& field : lines[line].split(',').mid(4)) QCOMPARE(field, QString("nan"));
    }

    void profileAlongReadsTheCellsOnTheLine() {
        // A linear field f = 3x + 2y at the cell centres of a 10 × 5 grid on [0, 1] × [0, 0.5].
        FieldGrid grid;
        grid.choice = {"T", "Temperature", "K"};
        grid.nx = 10, grid.ny = 5, grid.left = 0, grid.right = 1, grid.bottom = 0, grid.top = 0.5;
        auto f = [](double x, double y) { return 3 * x + 2 * y; };
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i)
                grid.values.push_back(f((i + 0.5) * grid.dx(), (j + 0.5) * grid.dy()));
        // Through the centres of a row: the exact values.
        FieldProfile row = profileAlong(grid, 0.05, 0.25, 0.95, 0.25, 10);
        QCOMPARE(row.choice.name, std::string("T"));
        QCOMPARE(row.values.size(), std::size_t(10));
        for (int k = 0; k < 10; ++k) {
            QVERIFY(std::abs(row.values[k] - f(0.05 + 0.1 * k, 0.25)) < 1e-12);
            QVERIFY(std::abs(row.distance[k] - 0.1 * k) < 1e-12);
        }
        // Along a diagonal the nearest cell's value is within half a cell's change of the line's:
        // |f(cell) − f(point)| ≤ 3 dx/2 + 2 dy/2; from the start the distance grows evenly.
        FieldProfile diagonal = profileAlong(grid, 0.0, 0.0, 1.0, 0.5, 41);
        const double bound = 3 * grid.dx() / 2 + 2 * grid.dy() / 2 + 1e-12;
        for (int k = 0; k <= 40; ++k) {
            const double t = k / 40.0;
            QVERIFY(std::abs(diagonal.values[k] - f(t, 0.5 * t)) <= bound);
            QVERIFY(std::abs(diagonal.distance[k] - t * std::hypot(1.0, 0.5)) < 1e-12);
        }
        QCOMPARE(diagonal.values.back(), grid.values.back()); // the end on the corner: the last cell
        // Beyond the grid: NaN.
        FieldProfile outside = profileAlong(grid, 0.5, 0.25, 1.5, 0.25, 11);
        QCOMPARE(outside.values[5], grid.at(1.0, 0.25));
        for (int k = 6; k <= 10; ++k) QVERIFY(std::isnan(outside.values[k]));
        QVERIFY(std::isnan(grid.at(0.5, -1e-12)));
        QVERIFY(std::isnan(grid.at(std::nan(""), 0.1)));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, profileAlong(grid, 0, 0, 1, 1, 1));
    }

    // A moving window of 6 steps for flows that change. One particle per cell moves at the step's number
    // s, and the bodies feel a drag of s: after every step the fields and the mean force are the mean of
    // exactly the last 3 to 5 steps, and a sampler restored from a snapshot in between goes on the same.
    void aMovingWindowAveragesTheRecentSteps() {
        const auto stepOf = [](TunnelSampler& sampler, int s) {
            TunnelState state;
            for (int c = 0; c < kNx * kNy; ++c) {
                state.append((c % kNx + 0.5) * kCell, (c / kNx + 0.5) * kCell, {double(s), 0.0, 0.0});
                state.cell.back() = std::uint32_t(c);
            }
            sampler.addState(state);
            sampler.addSurfaceImpulse(0, -double(s) / kFn, 0.0); // the body feels +s over dt = 1 s
            sampler.endStep(1, 1.0);
        };
        TunnelSampler sampler;
        sampler.configure(testGrid());
        sampler.setWindow(6);
        for (int s = 1; s <= 20; ++s) {
            stepOf(sampler, s);
            const std::int64_t k = sampler.sampledSteps();
            QCOMPARE(k, std::int64_t(s < 3 ? s : 3 + s % 3)); // the older half of 3 and the newer one
            const double mean = s - 0.5 * double(k - 1);      // of s − k + 1 … s
            QCOMPARE(fieldValues(sampler, "ux")[0], mean);
            QCOMPARE(sampler.averageForces()[0].drag, mean);
        }
        StateRecord record;
        sampler.save(record);
        TunnelSampler resumed;
        resumed.configure(testGrid());
        resumed.setWindow(6);
        resumed.restore(record);
        QCOMPARE(resumed.sampledSteps(), sampler.sampledSteps());
        for (int s = 21; s <= 25; ++s) {
            stepOf(sampler, s);
            stepOf(resumed, s);
            QCOMPARE(resumed.sampledSteps(), sampler.sampledSteps());
            QCOMPARE(fieldValues(resumed, "ux"), fieldValues(sampler, "ux"));
            QCOMPARE(resumed.averageForces()[0].drag, sampler.averageForces()[0].drag);
        }
        // A window over the whole run keeps every step.
        sampler.setWindow(0);
        for (int s = 1; s <= 20; ++s) stepOf(sampler, s);
        QCOMPARE(sampler.sampledSteps(), std::int64_t(20));
        QCOMPARE(fieldValues(sampler, "ux")[0], 10.5);
    }
};

QTEST_GUILESS_MAIN(TestTunnelSampler)
#include "tst_tunnel_sampler.moc"
