// The wind tunnel's CPU model: what collisions and walls must conserve, the periodic wrap, the
// inflow's flux and its flux-weighted velocity distribution against the exact half-range theory,
// determinism at 1 and 2 threads and across a snapshot (the sampling window included), dragged bodies at
// bounded speed, and refused parameters naming their key.
#include "catalog/ModelCatalog.h"
#include "common/PhysicalConstants.h"
#include "common/Snapshot.h"
#include "common/StopRequest.h"
#include "tunnel/TunnelKernels.h"
#include "tunnel/TunnelModel.h"
#include "tunnel/TunnelTheory.h"

#include <QtTest>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <omp.h>
#include <sstream>
#include <thread>

using namespace pl;

namespace {

// Reaches the protected state to set up single molecules.
class Probe : public TunnelModel {
public:
    using TunnelModel::state_;
};

// Counts what a refusal or a stop costs: the builds of the state and the whole-state copies.
class Counting : public TunnelModel {
public:
    int resets = 0;
    mutable int saves = 0;
    int restores = 0;
    using TunnelModel::reset;
    void reset() override {
        ++resets;
        TunnelModel::reset();
    }
    StateRecord saveState() const override {
        ++saves;
        return TunnelModel::saveState();
    }
    void restoreState(const StateRecord& state) override {
        ++restores;
        TunnelModel::restoreState(state);
    }
};

// A small tunnel (a few thousand molecules): the defaults with these overrides.
Preset tunnelPreset(const ParamValues& overrides, std::vector<Obstacle> obstacles = {}) {
    Preset p;
    p.model = "tunnel";
    p.seed = 7;
    p.params = {{"box_width", 0.04}, {"box_height", 0.03}, {"cells_x", 20.0},      {"cells_y", 15.0},
                {"fn", 2e14},        {"dt", 2e-7},         {"stream_speed", 600.0}};
    for (const auto& [key, value] : overrides) p.params[key] = value;
    p.obstacles = std::move(obstacles);
    return p;
}

Obstacle disc(double x, double y, double r) {
    Obstacle o;
    o.x = x, o.y = y, o.radius = r;
    return o;
}

struct Totals {
    double px = 0, py = 0, pz = 0, energy = 0;
};

Totals totalsOf(const TunnelModel& model) {
    const TunnelState& s = model.state();
    Totals t;
    for (std::size_t i = 0; i < s.size(); ++i) {
        t.px += s.vx[i], t.py += s.vy[i], t.pz += s.vz[i];
        t.energy += s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i];
    }
    return t;
}

void requireSameState(const TunnelModel& a, const TunnelModel& b) {
    const TunnelState &s = a.state(), &t = b.state();
    QCOMPARE(s.size(), t.size());
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.x[i] != t.x[i] || s.y[i] != t.y[i] || s.vx[i] != t.vx[i] || s.vy[i] != t.vy[i] ||
            s.vz[i] != t.vz[i])
            QFAIL(qPrintable(QString("molecule %1 differs").arg(i)));
}

// Sample moments of x with density ∝ x exp(−(x − s)²) on x > 0, by the midpoint rule.
struct Moments {
    double mean, meanSquare;
};
Moments inflowMoments(double s) {
    double m0 = 0, m1 = 0, m2 = 0;
    const double dx = 1e-4;
    for (double x = 0.5 * dx; x < std::max(s, 0.0) + 12.0; x += dx) {
        const double f = x * std::exp(-(x - s) * (x - s));
        m0 += f, m1 += f * x, m2 += f * x * x;
    }
    return {m1 / m0, m2 / m0};
}

std::string fieldsCsv(const TunnelModel& model) {
    std::ostringstream out;
    model.sampler().writeFieldsCsv(out);
    return out.str();
}

// The series row as text, so a difference names its column and every bit counts (NaN equals NaN).
QString rowText(Model& model) {
    const std::vector<double> row = model.sampleSeries();
    const std::vector<std::string> columns = model.seriesColumns();
    QStringList cells;
    for (std::size_t k = 0; k < row.size(); ++k)
        cells << QString::fromStdString(columns[k]) + "=" + QString::number(row[k], 'g', 17);
    return cells.join(", ");
}

// The model as a snapshot file would bring it back: saved as text, parsed, and restored into a new model.
std::unique_ptr<Model> throughSnapshotFile(const Model& model) {
    const std::string text = serializeSnapshot(takeSnapshot(model), model.paramSpecs());
    const Snapshot snapshot = parseSnapshot(text, specsForModel, "resume");
    std::unique_ptr<Model> resumed = instantiate(snapshot.preset);
    resumed->restoreState(snapshot.state);
    return resumed;
}

} // namespace

class TestTunnelModel : public QObject {
    Q_OBJECT

private slots:
    // One thread except where the thread count is the point: on a busy machine OpenMP's barriers make
    // two threads many times slower than one.
    void initTestCase() { omp_set_num_threads(1); }

    // All sides periodic: collisions are the only interaction, and each conserves momentum and energy
    // exactly (Bird 1994 §2.4) up to rounding, ~1e-16 per collision of the totals' scale.
    void collisionsConserveMomentumAndEnergy() {
        TunnelModel model;
        model.reset(tunnelPreset(
            {{"left", "periodic"}, {"right", "periodic"}, {"bottom", "periodic"}, {"top", "periodic"}}));
        const Totals before = totalsOf(model);
        const std::size_t n = model.particleCount();
        long long collisions = 0;
        for (int k = 0; k < 40; ++k) {
            model.step();
            collisions += model.lastCollisions();
        }
        const Totals after = totalsOf(model);
        QCOMPARE(model.particleCount(), n);
        QVERIFY2(collisions > 1000, qPrintable(QString::number(collisions)));
        const double scale = std::sqrt(before.energy * double(n)); // Σ|v| bound of a momentum sum
        QVERIFY(std::abs(after.px - before.px) < 1e-11 * scale);
        QVERIFY(std::abs(after.py - before.py) < 1e-11 * scale);
        QVERIFY(std::abs(after.pz - before.pz) < 1e-11 * scale);
        QVERIFY(std::abs(after.energy - before.energy) < 1e-11 * before.energy);
    }

    // In equilibrium NTC collides ½ N ν Δt pairs a step, ν = n ⟨σ c_r⟩ the kinetic-theory collision
    // frequency (Bird 1994 eq. 4.64; ⟨σ c_r⟩ over the Maxwellian relative speeds). After the cell counts
    // have mixed (Poisson counts make ⟨N(N − 1)⟩ = ⟨N⟩²), the total over 100 steps is a Poisson count:
    // it agrees within 4 √total.
    // In thin gas a cell expects far less than one candidate per step; its fractional candidates start
    // uniform in [0, 1), so the rate is right from the first step.
    void equilibriumCollisionRateIsKineticTheorys_data() {
        QTest::addColumn<double>("density");
        QTest::addColumn<double>("weight");
        QTest::addColumn<int>("mixingSteps");
        QTest::addColumn<int>("steps");
        QTest::addColumn<double>("cellsX");
        QTest::addColumn<double>("cellsY");
        QTest::newRow("1e21 m⁻³, after mixing") << 1e21 << 1e14 << 200 << 100 << 8.0 << 6.0;
        // ~13 molecules a cell: each of the 1536 cells expects one candidate in ~40 steps, so starting
        // at 0 would lose about a candidate per cell, a third of the 1800 collisions expected.
        QTest::newRow("3e18 m⁻³, from the first step") << 3e18 << 1.8e11 << 0 << 1000 << 48.0 << 32.0;
    }
    void equilibriumCollisionRateIsKineticTheorys() {
        QFETCH(double, density);
        QFETCH(double, weight);
        QFETCH(int, mixingSteps);
        QFETCH(int, steps);
        QFETCH(double, cellsX);
        QFETCH(double, cellsY);
        TunnelModel model;
        model.reset(tunnelPreset({{"initial", "rest"},
                                  {"stream_temperature", 300.0},
                                  {"left", "periodic"},
                                  {"right", "periodic"},
                                  {"bottom", "periodic"},
                                  {"top", "periodic"},
                                  {"cells_x", cellsX},
                                  {"cells_y", cellsY},
                                  {"stream_density", density},
                                  {"fn", weight}}));
        for (int k = 0; k < mixingSteps; ++k) model.step();
        double total = 0;
        for (int k = 0; k < steps; ++k) {
            model.step();
            total += double(model.lastCollisions());
        }
        const TunnelParams& p = model.parameters();
        const double n = double(model.particleCount()) * p.fn / (p.boxWidth * p.boxHeight);
        const double nu = n * model.collisionModel().meanSigmaCr(300.0, p.mass());
        const double expected = 0.5 * double(model.particleCount()) * nu * p.dt * steps;
        qInfo("%.0f collisions, kinetic theory %.1f", total, expected);
        QVERIFY2(std::abs(total - expected) < 4 * std::sqrt(expected),
                 qPrintable(QString("%1 collisions, kinetic theory %2").arg(total).arg(expected)));
    }

    // A closed specular box with a specular body at rest: nothing enters or leaves and no wall does
    // work, so the count is constant and the energy conserved to rounding.
    void closedSpecularBoxKeepsCountAndEnergy() {
        TunnelModel model;
        model.reset(tunnelPreset({{"left", "specular"},
                                  {"right", "specular"},
                                  {"bottom", "specular"},
                                  {"top", "specular"},
                                  {"surface", "specular"}},
                                 {disc(0.02, 0.015, 0.004)}));
        const std::size_t n = model.particleCount();
        QCOMPARE(n, TunnelModel::initialFillCount(model.parameters(), model.obstacles()));
        const Totals before = totalsOf(model);
        for (int k = 0; k < 60; ++k) model.step();
        QCOMPARE(model.particleCount(), n);
        QVERIFY(std::abs(totalsOf(model).energy - before.energy) < 1e-11 * before.energy);
        for (std::size_t i = 0; i < n; ++i) {
            const double dx = model.state().x[i] - 0.02, dy = model.state().y[i] - 0.015;
            QVERIFY(dx * dx + dy * dy >= 0.004 * 0.004 * (1 - 1e-12));
        }
    }

    // Gas at the wall temperature in a closed diffuse box stays at it: the walls re-emit from the
    // flux-weighted half-range Maxwellian (Bird 1994 §12.4), whose energy flux balances the incoming one
    // (a plain half-range Maxwellian would cool the gas by about a sixth). After ~3 wall transits the
    // temperature m⟨c²⟩/3k of N molecules lies within 4σ, σ = T √(2/3N), of the wall's.
    void diffuseWallsKeepTheirTemperature() {
        TunnelModel model;
        model.reset(tunnelPreset({{"initial", "rest"},
                                  {"stream_temperature", 300.0},
                                  {"wall_temperature", 300.0},
                                  {"left", "diffuse"},
                                  {"right", "diffuse"},
                                  {"bottom", "diffuse"},
                                  {"top", "diffuse"},
                                  {"box_width", 0.01},
                                  {"box_height", 0.01},
                                  {"cells_x", 5.0},
                                  {"cells_y", 5.0},
                                  {"fn", 1e13}}));
        const std::size_t n = model.particleCount();
        for (int k = 0; k < 600; ++k) model.step();
        QCOMPARE(model.particleCount(), n);
        const Totals t = totalsOf(model);
        const double temperature = model.parameters().mass() * t.energy / (3.0 * kBoltzmann * double(n));
        const double sigma = 300.0 * std::sqrt(2.0 / (3.0 * double(n)));
        QVERIFY2(std::abs(temperature - 300.0) < 4 * sigma,
                 qPrintable(QString("T = %1 K ± %2 with %3 molecules").arg(temperature).arg(sigma).arg(n)));
    }

    // One molecule crossing the right side of a periodic tunnel re-enters at the left, the flight
    // continued: x = x₀ + v h − W.
    void periodicSidesWrap() {
        Probe model;
        model.reset(tunnelPreset({{"left", "periodic"},
                                  {"right", "periodic"},
                                  {"bottom", "specular"},
                                  {"top", "specular"},
                                  {"initial", "empty"}}));
        model.state_.append(0.0399, 0.01, {1000.0, 0.0, 0.0});
        model.state_.cell.back() = 0;
        model.step();
        QCOMPARE(model.particleCount(), std::size_t(1));
        const double expected = 0.0399 + 1000.0 * 2e-7 - 0.04;
        QVERIFY(std::abs(model.state().x[0] - expected) < 1e-15);
        QCOMPARE(model.state().y[0], 0.01);
    }

    // The inflow admits ⌊k F L h / F_N⌋ molecules in k steps (the remainder carried), F the exact
    // half-range flux, Bird 1994 eq. 4.22. Only the left side is open, and nothing leaves in 3 steps
    // through sides 40 mm away at ≤ 5 km/s.
    void inflowAdmitsTheHalfRangeFlux() {
        TunnelModel model;
        model.reset(tunnelPreset({{"initial", "empty"},
                                  {"left", "inflow"},
                                  {"right", "specular"},
                                  {"bottom", "specular"},
                                  {"top", "specular"}}));
        const TunnelParams& p = model.parameters();
        const double sigma = std::sqrt(kBoltzmann * p.streamTemperature / p.mass());
        const double s = p.streamSpeed / (std::numbers::sqrt2 * sigma);
        const double perStep = tunnel::halfRangeFlux(p.streamDensity, sigma, s) * p.boxHeight * p.dt / p.fn;
        for (int k = 1; k <= 3; ++k) {
            model.step();
            QCOMPARE(double(model.particleCount()), std::floor(k * perStep + 1e-9));
        }
    }

    // The entering normal velocity has the density x e^(−(x−s)²) (Bird 1994 §12.5): its mean and mean
    // square over 40 000 draws agree with the exact moments within 4 standard errors.
    void inflowNormalVelocityIsFluxWeighted_data() {
        QTest::addColumn<double>("s");
        for (double s : {-0.7, 0.0, 0.8, 9.1}) QTest::newRow(qPrintable(QString::number(s))) << s;
    }
    void inflowNormalVelocityIsFluxWeighted() {
        QFETCH(double, s);
        const Moments exact = inflowMoments(s);
        const int n = 40000;
        double sum = 0, sum2 = 0, sum4 = 0;
        for (int k = 0; k < n; ++k) {
            tunnel::CounterRng rng(11, RngPurpose::TunnelInflow, static_cast<std::uint32_t>(k), 0);
            const double x = tunnel::inflowNormalSpeedRatio(s, rng);
            QVERIFY(x > 0);
            sum += x, sum2 += x * x, sum4 += x * x * x * x;
        }
        const double mean = sum / n, meanSquare = sum2 / n;
        const double errorMean = std::sqrt((meanSquare - mean * mean) / n);
        const double errorSquare = std::sqrt((sum4 / n - meanSquare * meanSquare) / n);
        QVERIFY2(std::abs(mean - exact.mean) < 4 * errorMean,
                 qPrintable(QString("%1 vs %2 ± %3").arg(mean).arg(exact.mean).arg(errorMean)));
        QVERIFY2(std::abs(meanSquare - exact.meanSquare) < 4 * errorSquare,
                 qPrintable(QString("%1 vs %2 ± %3").arg(meanSquare).arg(exact.meanSquare).arg(errorSquare)));
    }

    // Random numbers are keyed by molecule, cell and step, and the forces summed in fixed chunks: the
    // same run at 1 and 2 threads, bit for bit.
    void oneAndTwoThreadsAgreeBitForBit() {
        const Preset preset = tunnelPreset({{"stream_speed", 2000.0}}, {disc(0.015, 0.0, 0.004)});
        std::vector<std::unique_ptr<TunnelModel>> runs;
        for (int threads : {1, 2}) {
            omp_set_num_threads(threads);
            auto model = std::make_unique<TunnelModel>();
            model->reset(preset);
            for (int k = 0; k < 40; ++k) model->step();
            runs.push_back(std::move(model));
        }
        omp_set_num_threads(1);
        requireSameState(*runs[0], *runs[1]);
        QCOMPARE(runs[0]->sampler().lastForces()[0].drag, runs[1]->sampler().lastForces()[0].drag);
        QVERIFY(runs[0]->sampler().lastForces()[0].drag > 0);
    }

    // A snapshot taken mid-run continues exactly as the run it was taken from.
    void snapshotResumesBitForBit() {
        const Preset preset = tunnelPreset({{"stream_speed", 2000.0}}, {disc(0.015, 0.0, 0.004)});
        TunnelModel original;
        original.reset(preset);
        for (int k = 0; k < 20; ++k) original.step();
        const StateRecord saved = original.saveState();
        Preset atSave = original.toPreset();
        for (int k = 0; k < 20; ++k) original.step();
        TunnelModel resumed;
        resumed.reset(atSave);
        resumed.restoreState(saved);
        QCOMPARE(resumed.stepCount(), std::int64_t(20));
        for (int k = 0; k < 20; ++k) resumed.step();
        requireSameState(original, resumed);
    }

    // Resumed with the fields window open, every built-in scene goes on as the run that never stopped:
    // the first row (a repeat of the state the snapshot was taken in), the fields, drag_avg and the
    // rows after it. Before, the window's sums were dropped: NaN fields, drag_avg from 0, no drag in
    // the first row.
    void snapshotKeepsTheSamplingWindow_data() {
        QTest::addColumn<QString>("name");
        for (const BuiltinPreset* preset : builtinPresetsOf("tunnel"))
            QTest::newRow(preset->name.c_str()) << QString::fromStdString(preset->name);
    }
    void snapshotKeepsTheSamplingWindow() {
        QFETCH(QString, name);
        Preset preset;
        for (const BuiltinPreset* builtin : builtinPresetsOf("tunnel"))
            if (builtin->name == name.toStdString()) preset = builtin->preset;
        preset.params["sample_start"] = 4.0;
        // A moving window (the shock tube's) turns its halves over within the run and across the resume.
        const bool moving = preset.params.count("sample_window") > 0;
        if (moving) preset.params["sample_window"] = 4.0;
        const std::unique_ptr<Model> original = instantiate(preset);
        for (int k = 0; k < 10; ++k) original->step();
        const QString rowAtSave = rowText(*original);
        const std::unique_ptr<Model> resumed = throughSnapshotFile(*original);
        auto& a = dynamic_cast<TunnelModel&>(*original);
        auto& b = dynamic_cast<TunnelModel&>(*resumed);
        QCOMPARE(b.sampledSteps(), std::int64_t(moving ? 2 : 6)); // a full older half, an empty newer one
        QCOMPARE(rowText(b), rowAtSave);
        QVERIFY(fieldsCsv(b) == fieldsCsv(a));
        for (int k = 0; k < 5; ++k) a.step(), b.step();
        QCOMPARE(rowText(b), rowText(a));
        QVERIFY(fieldsCsv(b) == fieldsCsv(a));
        QCOMPARE(b.sampledSteps(), std::int64_t(moving ? 3 : 11)); // 2 older, 1 newer
    }

    // The sampler's part of a snapshot is checked like the rest: a field that does not fit is refused
    // naming it, and the model is left as it was.
    void badSamplingStateIsRefusedNamingTheField_data() {
        QTest::addColumn<QString>("key");
        QTest::addColumn<double>("value");
        QTest::newRow("negative steps") << "sampling_steps" << -1.0;
        QTest::newRow("fractional steps") << "force_interval_steps" << 2.5;
        QTest::newRow("window start") << "sample_from" << -3.0;
        QTest::newRow("lift without its drag") << "force_window_lift" << 1.0;
        QTest::newRow("negative count") << "sampling_count" << -1.0;
    }
    void badSamplingStateIsRefusedNamingTheField() {
        QFETCH(QString, key);
        QFETCH(double, value);
        TunnelModel model;
        model.reset(tunnelPreset({{"sample_start", 2.0}}, {disc(0.015, 0.015, 0.004)}));
        for (int k = 0; k < 5; ++k) model.step();
        StateRecord bad = model.saveState();
        const std::string k = key.toStdString();
        if (bad.scalars.count(k))
            bad.scalars[k] = value;
        else if (k == "force_window_lift")
            bad.arrays[k].push_back(value); // one more entry than the drag has
        else
            bad.arrays[k].front() = value;
        const std::string before = fieldsCsv(model);
        const std::int64_t steps = model.sampledSteps();
        try {
            model.restoreState(bad);
            QFAIL("a bad sampler state was accepted");
        } catch (const PresetError& e) {
            QCOMPARE(e.key(), "state." + k);
        }
        QCOMPARE(model.sampledSteps(), steps);
        QVERIFY(fieldsCsv(model) == before);
    }

    // A body dragged across the tunnel moves at most tool_speed Δt per step, and no molecule is left
    // inside it.
    void draggedBodyMovesAtBoundedSpeed() {
        TunnelModel model;
        model.reset(tunnelPreset({{"tool_speed", 200.0}}, {disc(0.01, 0.015, 0.004)}));
        model.dragObstacle(0, 0.03, 0.015);
        double x = model.obstacles()[0].x;
        for (int k = 0; k < 30; ++k) {
            model.step();
            const double moved = model.obstacles()[0].x - x;
            QVERIFY(moved > 0 && moved <= 200.0 * 2e-7 * (1 + 1e-12));
            x = model.obstacles()[0].x;
            QCOMPARE(model.sampler().sampledSteps(), std::int64_t(0)); // the window waits while it moves
        }
        const Obstacle& o = model.obstacles()[0];
        const TunnelState& s = model.state();
        for (std::size_t i = 0; i < s.size(); ++i)
            QVERIFY(std::hypot(s.x[i] - o.x, s.y[i] - o.y) >= o.radius * (1 - 1e-9));
    }

    // The piston, driven from t = 0 by piston_speed, is a specular wall moving at that speed: it
    // advances u Δt per step, no molecule is ever behind it, and the gas gains the work it does
    // (a molecule reflected from a wall moving at u gains 2 m u (u − v_x) of energy, positive as v_x < u).
    void pistonDrivesIntoTheGas() {
        TunnelModel model;
        model.reset(tunnelPreset({{"initial", "rest"},
                                  {"stream_speed", 0.0},
                                  {"piston_on", true},
                                  {"piston_speed", 400.0},
                                  {"sample_start", 10.0},
                                  {"left", "specular"},
                                  {"right", "specular"},
                                  {"bottom", "specular"},
                                  {"top", "specular"}}));
        QVERIFY(model.hasPiston());
        const double before = totalsOf(model).energy;
        for (int k = 1; k <= 50; ++k) {
            model.step();
            QVERIFY(std::abs(model.pistonX() - k * 400.0 * 2e-7) < 1e-15);
            QCOMPARE(model.pistonVelocity(), 400.0);
            const TunnelState& s = model.state();
            QVERIFY(*std::min_element(s.x.begin(), s.x.end()) >= model.pistonX());
        }
        QVERIFY(totalsOf(model).energy > before);
        QVERIFY(model.sampler().sampledSteps() > 0); // the preset's own drive does not hold the window
        model.drivePiston(0);
        model.step();
        QCOMPARE(model.pistonVelocity(), 0.0);
    }

    // Spawning fills a rectangle at the free-stream density, refuses the part inside a body, says so,
    // and restarts the fields window.
    void spawnFillsOutsideBodies() {
        TunnelModel model;
        model.reset(tunnelPreset({{"initial", "empty"}, {"sample_start", 0.0}}, {disc(0.02, 0.015, 0.003)}));
        model.step();
        QVERIFY(model.sampler().sampledSteps() > 0);
        const std::size_t before = model.particleCount();
        const std::string message = model.spawnInRectangle(0.015, 0.01, 0.025, 0.02);
        const double expected = 1e21 * (1e-4 - std::numbers::pi * 0.003 * 0.003) / 2e14;
        const double added = double(model.particleCount() - before);
        QVERIFY2(std::abs(added - expected) < 0.02 * expected, qPrintable(QString::number(added)));
        QVERIFY(message.find("Added") != std::string::npos);
        QCOMPARE(model.sampler().sampledSteps(), std::int64_t(0));
        const TunnelState& s = model.state();
        for (std::size_t i = 0; i < s.size(); ++i)
            QVERIFY(std::hypot(s.x[i] - 0.02, s.y[i] - 0.015) >= 0.003);
    }

    // The speed histogram's reference curve is the free stream's speed density: it integrates to 1, and
    // a tunnel just filled with the free stream (no body, before any step) follows it. χ² over the bins
    // expecting ≥ 5 molecules must stay below B + 5√(2B) (its mean and five standard deviations).
    void speedHistogramFollowsTheFreeStream_data() {
        QTest::addColumn<double>("streamSpeed");
        QTest::newRow("drifting (600 m/s)") << 600.0;
        QTest::newRow("at rest") << 0.0;
    }
    void speedHistogramFollowsTheFreeStream() {
        QFETCH(double, streamSpeed);
        TunnelModel model;
        model.reset(tunnelPreset({{"stream_speed", streamSpeed}, {"fn", 5e13}}));
        const std::vector<NamedHistogram> histograms = model.histograms();
        QCOMPARE(histograms.size(), std::size_t(1));
        const NamedHistogram& h = histograms[0];
        QVERIFY(h.theoryDensity);
        const double n = double(model.particleCount());
        double total = 0.0, chi2 = 0.0;
        int bins = 0;
        for (std::size_t b = 0; b < h.counts.bins(); ++b) {
            // Simpson's rule over the bin: the density varies on the scale of the thermal speed.
            const double lo = h.counts.lo() + double(b) * h.counts.binWidth(), hi = lo + h.counts.binWidth();
            const double mass =
                (hi - lo) / 6.0 *
                (h.theoryDensity(lo) + 4.0 * h.theoryDensity(0.5 * (lo + hi)) + h.theoryDensity(hi));
            total += mass;
            const double expected = n * mass;
            if (expected < 5.0) continue;
            chi2 += (h.counts.count(b) - expected) * (h.counts.count(b) - expected) / expected;
            ++bins;
        }
        QVERIFY2(std::abs(total - 1.0) < 1e-3, qPrintable(QString::number(total)));
        QVERIFY(bins >= 10);
        qInfo("χ² %.1f over %d bins, Σ f %.6f", chi2, bins, total);
        QVERIFY2(chi2 < bins + 5.0 * std::sqrt(2.0 * bins),
                 qPrintable(QString("χ² %1 over %2 bins").arg(chi2).arg(bins)));
    }

    // Refused parameters and presets name the key at fault.
    void badParametersNameTheirKey() {
        TunnelModel model;
        model.reset(tunnelPreset({}));
        const auto keyOf = [&](const ParamValues& values) -> std::string {
            try {
                model.setParams(values);
            } catch (const ParamError& e) {
                return e.key();
            }
            return "";
        };
        QCOMPARE(keyOf({{"left", "periodic"}}), std::string("right"));
        QCOMPARE(keyOf({{"top", "periodic"}}), std::string("bottom"));
        QCOMPARE(keyOf({{"dt", 1e-3}}), std::string("dt")); // ~300 collisions per molecule and step
        try {
            model.reset(tunnelPreset({}, {disc(0.05, 0.01, 0.002)}));
            QFAIL("a body outside the tunnel was accepted");
        } catch (const PresetError& e) {
            QCOMPARE(e.key(), std::string("obstacles[0]"));
        }
        try {
            model.reset(tunnelPreset({{"piston_on", true}, {"left", "periodic"}, {"right", "periodic"}}));
            QFAIL("a piston on a periodic side was accepted");
        } catch (const PresetError& e) {
            QCOMPARE(e.key(), std::string("params.piston_on"));
        }
    }

    // The shock tube's fields are the mean of its last 50–100 steps (sample_window = 100): they show the
    // compressed plateau at Rankine–Hugoniot's density and a jump that travels along the tube at the
    // shock's speed (the piston's 500 m/s into argon at 300 K). A window over the whole run drew a ramp
    // that never reached the plateau (at most 1.8e21 m⁻³ against 2.7e21).
    void theShockTubesFieldsShowTheShockWhereItIs() {
        Preset preset;
        for (const BuiltinPreset* builtin : builtinPresetsOf("tunnel"))
            if (builtin->name == "tunnel-shock-tube") preset = builtin->preset;
        QCOMPARE(std::get<double>(preset.params.at("sample_window")), 100.0);
        const double n1 = std::get<double>(preset.params.at("stream_density"));
        const double mass = std::get<double>(preset.params.at("mass_amu")) * kAtomicMass;
        const double a1 =
            tunnel_theory::soundSpeed(std::get<double>(preset.params.at("stream_temperature")), mass);
        const auto jump = tunnel_theory::pistonDrivenShock(500, a1);
        const double middle = 0.5 * (1 + jump.densityRatio) * n1, n2 = jump.densityRatio * n1;
        struct Seen {
            double speed = 0, highest = 0; // the jump's speed [m/s], the highest column mean [m⁻³]
        };
        const auto watch = [&](double window) {
            Preset run = preset;
            run.params["sample_window"] = window;
            const std::unique_ptr<Model> model = instantiate(run);
            auto& tunnel = dynamic_cast<TunnelModel&>(*model);
            Seen seen;
            // The shock: the last column, from the far wall, whose mean over the rows exceeds (n₁ + n₂)/2.
            const auto shockAt = [&] {
                const FieldGrid n = tunnel.field("n");
                double at = n.left;
                for (int i = n.nx - 1; i >= 0; --i) {
                    double mean = 0;
                    for (int j = 0; j < n.ny; ++j) mean += n.values[std::size_t(j * n.nx + i)] / n.ny;
                    if (!std::isfinite(mean)) continue; // behind the piston
                    seen.highest = std::max(seen.highest, mean);
                    if (at == n.left && mean > middle) at = n.left + (i + 0.5) * n.dx();
                }
                return at;
            };
            while (tunnel.stepCount() < 900) tunnel.step();
            const double x0 = shockAt(), t0 = tunnel.time();
            while (tunnel.stepCount() < 1500) tunnel.step();
            seen.speed = (shockAt() - x0) / (tunnel.time() - t0);
            return seen;
        };
        const Seen moving = watch(100), whole = watch(0);
        qInfo("moving window: the jump at %.0f m/s (Rankine–Hugoniot %.0f), plateau up to %.2g m⁻³ (%.2g); "
              "whole run: at most %.2g m⁻³",
              moving.speed, jump.shockSpeed, moving.highest, n2, whole.highest);
        QVERIFY2(std::abs(moving.speed / jump.shockSpeed - 1) < 0.15,
                 qPrintable(QString::number(moving.speed)));
        QVERIFY2(moving.highest > 0.9 * n2, qPrintable(QString::number(moving.highest)));
        QVERIFY2(whole.highest < 0.75 * n2, qPrintable(QString::number(whole.highest)));
    }

    // A preset that its parameters refuse is refused before its molecules are made (a tunnel of 4e7
    // molecules takes seconds and gigabytes to build), and the registry's count, which the backend choice
    // reads first, refuses a grid beyond the cell limit before it allocates the grid's open fractions.
    void aRefusedPresetBuildsNothing() {
        Counting model;
        model.resets = 0;
        try {
            model.reset(tunnelPreset({{"dt", 1e-3}})); // ~300 collisions per molecule and step
            QFAIL("the preset was accepted");
        } catch (const PresetError& e) {
            QCOMPARE(e.key(), std::string("params.dt"));
        }
        QCOMPARE(model.resets, 0);
        try {
            particleCount(tunnelPreset({{"cells_x", 4096.0}, {"cells_y", 2048.0}}));
            QFAIL("8 M cells were counted");
        } catch (const PresetError& e) {
            QCOMPARE(e.key(), std::string("params.cells_x"));
        }
    }

    // A stop request half way through a long step puts back only what the step reached, without a copy
    // of the whole state before each step: the model is then bit for bit at the step's start, and runs
    // on as the one that was never stopped. The requests come at several moments of the step (before
    // it, in the move, the sort, the collisions), so the undo of each phase is exercised.
    void aStopUndoesOnlyWhatTheStepReached() {
        const Preset preset =
            tunnelPreset({{"fn", 1e13}, {"sample_start", 0.0}}, {disc(0.015, 0.015, 0.003)});
        Counting stopped;
        stopped.reset(preset);
        const auto twin = instantiate(preset);
        const auto start = std::chrono::steady_clock::now();
        twin->step();
        const double stepSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stopped.step();
        InterruptibleStepper stepper(stopped, 1.0); // as after a long set-up: every step keeps its start
        int abandoned = 0;
        for (const double fraction : {-1.0, 0.0, 0.1, 0.3, 0.5, 0.7, 0.9}) {
            const StateRecord before = stopped.saveState();
            stopped.saves = stopped.restores = 0;
            std::thread stop([&] {
                if (fraction > 0)
                    std::this_thread::sleep_for(std::chrono::duration<double>(fraction * stepSeconds));
                requestStop();
            });
            if (fraction < 0) stop.join(); // requested before the step begins
            const bool whole = stepper.step();
            if (stop.joinable()) stop.join();
            withdrawStopRequest();
            QCOMPARE(stopped.saves, 0);
            QCOMPARE(stopped.restores, 0);
            if (whole) {
                twin->step();
                continue;
            }
            ++abandoned;
            const StateRecord after = stopped.saveState();
            QVERIFY(after.scalars == before.scalars);
            QVERIFY(after.arrays == before.arrays);
        }
        QVERIFY(abandoned > 0);
        for (int s = 0; s < 3; ++s) {
            QVERIFY(stepper.step());
            twin->step();
        }
        QCOMPARE(stopped.stepCount(), twin->stepCount());
        const StateRecord a = stopped.saveState(), b = twin->saveState();
        QVERIFY(a.scalars == b.scalars);
        QVERIFY(a.arrays == b.arrays);
    }

    // The built-in presets build what the registry says they build.
    void presetsBuildTheirCount() {
        for (const BuiltinPreset* preset : builtinPresetsOf("tunnel")) {
            const auto model = instantiate(preset->preset);
            QCOMPARE(model->particleCount(), particleCount(preset->preset));
        }
    }
};

QTEST_APPLESS_MAIN(TestTunnelModel)
#include "tst_tunnel_model.moc"
