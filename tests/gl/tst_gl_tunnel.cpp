// The wind tunnel on the GPU against the CPU reference, statistically (the two draw different random
// numbers and the GPU steps in float): a closed specular box relaxing from counter-streaming beams to
// one temperature (energy, count and relaxation), the empty tunnel's count and uniform fields, and the
// free-molecular cylinder's drag. Scenes are small: llvmpipe runs them in CI.
#include "gl/Backends.h"
#include "gl/TunnelModelGL.h"
#include "tunnel/TunnelTheory.h"

#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace pl;
using namespace pl::gl;

namespace {

// Argon at 200 K in a 2 cm-high tunnel: σ = √(kT/m) ≈ 204 m/s, stream speed U = 1000 m/s.
Preset tunnelPreset(double width, long long cellsX, double density, double fn, double dt) {
    Preset p;
    p.model = "tunnel";
    p.seed = 20261202;
    p.params = {{"box_width", width},
                {"box_height", 0.02},
                {"cells_x", double(cellsX)},
                {"cells_y", 10.0},
                {"fn", fn},
                {"dt", dt},
                {"stream_density", density},
                {"stream_speed", 1000.0},
                {"stream_temperature", 200.0},
                {"initial", std::string("stream")},
                {"sample_start", 50.0}};
    return p;
}

// A closed box: every side a specular wall, filled with the stream drifting at 1000 m/s; the walls turn
// it into two counter-streaming beams that collisions relax to one temperature.
Preset closedBox() {
    Preset p = tunnelPreset(0.02, 10, 1e21, 5e13, 1e-6); // 8 000 molecules
    for (const char* side : {"left", "right", "bottom", "top"}) p.params[side] = std::string("specular");
    return p;
}

// The empty tunnel: inflow on the left, outflow on the right, periodic top and bottom.
Preset emptyTunnel() {
    Preset p = tunnelPreset(0.04, 20, 1e21, 2e14, 1e-6); // 4 000 molecules
    p.params["left"] = std::string("inflow");
    p.params["right"] = std::string("outflow");
    p.params["bottom"] = std::string("periodic");
    p.params["top"] = std::string("periodic");
    return p;
}

// A diffuse cylinder of radius 2 mm in the empty tunnel at n = 1e19 m⁻³: λ ≈ 0.13 m, Kn ≈ 30.
Preset freeMolecularCylinder() {
    Preset p = emptyTunnel();
    p.params["stream_density"] = 1e19;
    p.params["fn"] = 2e12;
    p.params["body_temperature"] = 300.0;
    Obstacle disc;
    disc.shape = Obstacle::Shape::Disc;
    disc.x = 0.02, disc.y = 0.01, disc.radius = 0.002;
    p.obstacles = {disc};
    p.params["sample_start"] = 30.0;
    return p;
}

struct Moments {
    double energy = 0;     // Σ ½ m v² [J]
    double tx = 0, tz = 0; // temperatures of the x and z motion about the mean [K]
};

Moments moments(const TunnelState& s, double mass) {
    Moments m;
    const double n = double(s.size());
    double mx = 0, mz = 0, ex = 0, ez = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        m.energy += 0.5 * mass * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]);
        mx += s.vx[i], mz += s.vz[i], ex += s.vx[i] * s.vx[i], ez += s.vz[i] * s.vz[i];
    }
    m.tx = mass / kBoltzmann * (ex / n - (mx / n) * (mx / n));
    m.tz = mass / kBoltzmann * (ez / n - (mz / n) * (mz / n));
    return m;
}

struct Spread {
    double mean = 0, sd = 0;
    int cells = 0;
};

// Mean and standard deviation over the sampled cells of a field that should be uniform.
Spread spreadOf(const FieldGrid& grid) {
    Spread s;
    double sum = 0, squares = 0;
    for (double v : grid.values)
        if (std::isfinite(v)) sum += v, squares += v * v, ++s.cells;
    s.mean = sum / s.cells;
    s.sd = std::sqrt(std::max(0.0, squares / s.cells - s.mean * s.mean));
    return s;
}

} // namespace

class TestGlTunnel : public QObject {
    Q_OBJECT
    std::shared_ptr<GlContext> context_;

private slots:
    void initTestCase() {
        try {
            context_ = sharedHeadlessContext();
        } catch (const GlUnavailable& e) {
            QSKIP(e.what());
        }
    }

    // Specular walls and elastic collisions conserve energy; the GPU's float collisions change a pair's
    // energy by at most about one float rounding (2⁻²³ of it) each, so the total drifts by at most
    // C · 2⁻²³ / N of itself after C collisions of N molecules: the bound. The count stays exactly. The
    // collision counts agree within 4 √(2C) (binomial acceptances: variance at most Poisson). The
    // relaxation T_z → T_x is compared at two times: T of one component from N molecules has relative
    // noise √(2/N) (1.6 % at N = 8 000), so CPU and GPU agree within 4 √2 of it.
    void closedBoxConservesAndRelaxesLikeCpu() {
        const Preset preset = closedBox();
        TunnelModel cpu;
        cpu.reset(preset);
        TunnelModelGL gpu(context_, preset);
        const double mass = cpu.parameters().mass();
        const std::size_t n = cpu.particleCount();
        QCOMPARE(gpu.particleCount(), n);
        const Moments start = moments(cpu.state(), mass);
        const double noise = 4.0 * std::sqrt(2.0) * std::sqrt(2.0 / double(n));
        long long collisions = 0, cpuCollisions = 0;
        for (int phase : {25, 125}) {
            for (int s = 0; s < phase; ++s) {
                cpu.step();
                gpu.step();
                collisions += gpu.lastCollisions();
                cpuCollisions += cpu.lastCollisions();
            }
            const Moments a = moments(cpu.state(), mass), b = moments(gpu.state(), mass);
            qInfo("after %lld steps: T_x / T_z  CPU %.1f / %.1f K, GPU %.1f / %.1f K",
                  (long long)cpu.stepCount(), a.tx, a.tz, b.tx, b.tz);
            QVERIFY(std::abs(b.tz / a.tz - 1.0) < noise);
            QVERIFY(std::abs(b.tx / a.tx - 1.0) < noise);
        }
        QCOMPARE(gpu.particleCount(), n);
        QCOMPARE(gpu.state().size(), n);
        const Moments end = moments(gpu.state(), mass);
        const double drift = std::abs(end.energy / start.energy - 1.0);
        const double bound = std::max(1.0, double(collisions)) * std::ldexp(1.0, -23) / double(n);
        qInfo("collisions: CPU %lld, GPU %lld; GPU energy drift %.3g (bound %.3g)", cpuCollisions, collisions,
              drift, bound);
        QVERIFY(collisions > 0);
        // Collisions per run: a sum of binomial acceptances, its variance at most the Poisson C.
        QVERIFY(std::abs(double(collisions - cpuCollisions)) < 4.0 * std::sqrt(2.0 * double(cpuCollisions)));
        QVERIFY(drift < bound);
        // Relaxed: one temperature, the drift's energy in it (T₀ + m U² / 3k).
        const double relaxed = 200.0 + mass * 1000.0 * 1000.0 / (3.0 * kBoltzmann);
        QVERIFY(std::abs(end.tz / relaxed - 1.0) < noise);
        QVERIFY(std::abs(end.tx / relaxed - 1.0) < noise);
    }

    // The count settles where inflow and outflow balance, at n A / F_N: a region of an ideal gas holds
    // a Poisson number of molecules, so each count lies within 4 √N of it, and CPU and GPU within
    // 4 √(2N) of each other. The fields are uniform. Their means over the domain and the window are
    // averages over the molecules seen in it; counting each molecule once however long it stays (its
    // samples as one), N_eff = N (1 + S U Δt / W) molecules pass in S steps, so the means have standard
    // errors σ/√N_eff for u (σ = √(kT/m)), n/√N_eff for n (Poisson) and T √(2 / 3N_eff) for T: the GPU
    // lies within 4 of them of the free stream and 4 √2 of the CPU. The cells' spread (the noise
    // itself) agrees within ±35 %: 5 times the 7 % sampling error of a ratio of two spreads over 200
    // cells.
    void emptyTunnelIsUniformLikeCpu() {
        const Preset preset = emptyTunnel();
        TunnelModel cpu;
        cpu.reset(preset);
        TunnelModelGL gpu(context_, preset);
        for (int s = 0; s < 200; ++s) {
            cpu.step();
            gpu.step();
        }
        const TunnelParams& p = cpu.parameters();
        const double expected = p.streamDensity * p.boxWidth * p.boxHeight / p.fn;
        const double a = double(cpu.particleCount()), b = double(gpu.particleCount());
        qInfo("count: expected %.0f, CPU %.0f, GPU %.0f", expected, a, b);
        QVERIFY(std::abs(b - expected) < 4.0 * std::sqrt(expected));
        QVERIFY(std::abs(b - a) < 4.0 * std::sqrt(2.0 * expected));
        QCOMPARE(gpu.sampledSteps(), cpu.sampledSteps());
        const double seen = expected * (1.0 + double(gpu.sampledSteps()) * p.streamSpeed * p.dt / p.boxWidth);
        const double sigma = std::sqrt(kBoltzmann * p.streamTemperature / p.mass());
        const struct {
            const char* name;
            double freeStream, standardError;
        } fields[] = {{"n", p.streamDensity, p.streamDensity / std::sqrt(seen)},
                      {"ux", p.streamSpeed, sigma / std::sqrt(seen)},
                      {"uy", 0.0, sigma / std::sqrt(seen)},
                      {"T", p.streamTemperature, p.streamTemperature * std::sqrt(2.0 / (3.0 * seen))}};
        for (const auto& f : fields) {
            const Spread c = spreadOf(cpu.field(f.name)), g = spreadOf(gpu.field(f.name));
            QCOMPARE(g.cells, int(p.cellsX * p.cellsY));
            qInfo("%-2s: CPU %.5g, GPU %.5g ± %.2g (free stream %.5g); spread over cells CPU %.3g, GPU %.3g",
                  f.name, c.mean, g.mean, f.standardError, f.freeStream, c.sd, g.sd);
            QVERIFY(std::abs(g.mean - c.mean) < 4.0 * std::sqrt(2.0) * f.standardError);
            QVERIFY(std::abs(g.mean - f.freeStream) < 4.0 * f.standardError);
            QVERIFY(g.sd < 1.35 * c.sd && g.sd > c.sd / 1.35);
        }
    }

    // Inflow into an empty tunnel 20 cm long, closed on the right: for 100 steps nothing leaves (back at
    // the inflow side after 0.4 m, a molecule would need 4000 m/s, 15 σ above the stream), so the count
    // is the sum of the entering numbers, which come from the same half-range flux and remainders on
    // both backends: equal exactly, also after the GPU outgrew the buffers it started with (64 steps
    // of inflow).
    void closedTunnelCountsEveryEnteringMoleculeLikeCpu() {
        Preset preset = emptyTunnel();
        preset.params["box_width"] = 0.2;
        preset.params["initial"] = std::string("empty");
        preset.params["right"] = std::string("specular");
        TunnelModel cpu;
        cpu.reset(preset);
        TunnelModelGL gpu(context_, preset);
        QCOMPARE(gpu.particleCount(), std::size_t{0});
        for (int s = 0; s < 100; ++s) {
            cpu.step();
            gpu.step();
        }
        qInfo("count after 100 steps: CPU %zu, GPU %zu", cpu.particleCount(), gpu.particleCount());
        QVERIFY(cpu.particleCount() > 9000);
        QCOMPARE(gpu.particleCount(), cpu.particleCount());
        QCOMPARE(gpu.state().size(), cpu.particleCount());
    }

    // Free-molecular drag: each step's force is a sum over different molecules (a molecule re-emitted
    // by the body leaves), so steps are independent and the window mean has the standard error
    // sd / √steps of the CPU's per-step series; the GPU's mean (summed on the GPU, handed over lazily
    // across ring hand-overs) lies within 4 √2 standard errors of the CPU's.
    void freeMolecularDragMatchesCpu_data() {
        QTest::addColumn<bool>("specularBox");
        QTest::newRow("diffuse disc") << false;
        QTest::newRow("specular box") << true;
    }
    void freeMolecularDragMatchesCpu() {
        QFETCH(bool, specularBox);
        Preset preset = freeMolecularCylinder();
        if (specularBox) { // a 4 mm × 6 mm box, mirror-reflecting
            Obstacle& box = preset.obstacles.front();
            box.shape = Obstacle::Shape::Box;
            box.halfWidth = 0.002, box.halfHeight = 0.003;
            preset.params["surface"] = std::string("specular");
        }
        TunnelModel cpu;
        cpu.reset(preset);
        TunnelModelGL gpu(context_, preset);
        const auto columns = cpu.seriesColumns();
        const auto dragColumn =
            std::size_t(std::find(columns.begin(), columns.end(), "drag") - columns.begin());
        QVERIFY(dragColumn < columns.size());
        std::vector<double> perStep;
        for (int s = 0; s < 180; ++s) {
            cpu.step();
            gpu.step();
            const auto row = cpu.sampleSeries();
            if (cpu.stepCount() > 30) perStep.push_back(row[dragColumn]);
        }
        double mean = 0, squares = 0;
        for (double d : perStep) mean += d, squares += d * d;
        mean /= double(perStep.size());
        const double sd = std::sqrt(squares / double(perStep.size()) - mean * mean);
        const double error = sd / std::sqrt(double(perStep.size()));
        const TunnelObservables a = cpu.observe(), b = gpu.observe();
        const TunnelParams& p = cpu.parameters();
        const double theory = tunnel_theory::freeMolecularCylinderDrag(
            p.streamDensity, p.streamTemperature, p.mass(), p.streamSpeed, 0.002, p.bodyTemperature);
        qInfo(
            "drag [N/m]: CPU %.5g, GPU %.5g (± %.2g per run); the diffuse disc's free-molecular theory %.5g",
            a.dragAverage, b.dragAverage, error, theory);
        QCOMPARE(b.sampledSteps, a.sampledSteps);
        QVERIFY(a.dragAverage > 0);
        QVERIFY(std::abs(b.dragAverage - a.dragAverage) < 4.0 * std::sqrt(2.0) * error);
        QVERIFY(std::abs(b.lift) < std::abs(b.drag));
    }

    // The piston driven at 500 m/s into argon at rest (the shock tube, shortened to 4 cm and 8 000
    // molecules): after 30 µs the molecules' positions, binned by 1 mm, are two draws of the same
    // profile (gas at rest, the shock, the compressed layer). An ideal gas holds a Poisson number of
    // molecules in a region, so Σ (a − b)² / (a + b) over B occupied bins is χ² with B degrees of
    // freedom (mean B, variance 2B): it stays below B + 5 √(2B). The box is closed: the count stays.
    void pistonDrivenShockMatchesCpu() {
        Preset preset = tunnelPreset(0.04, 100, 1e21, 8e12, 2e-7);
        preset.params["box_height"] = 0.0016;
        preset.params["cells_y"] = 4.0;
        preset.params["stream_speed"] = 0.0;
        preset.params["stream_temperature"] = 300.0;
        preset.params["initial"] = std::string("rest");
        for (const char* side : {"left", "right", "bottom", "top"})
            preset.params[side] = std::string("specular");
        preset.params["piston_on"] = true;
        preset.params["piston_speed"] = 500.0;
        TunnelModel cpu;
        cpu.reset(preset);
        TunnelModelGL gpu(context_, preset);
        const std::size_t n = cpu.particleCount();
        for (int s = 0; s < 150; ++s) {
            cpu.step();
            gpu.step();
        }
        QCOMPARE(gpu.pistonX(), cpu.pistonX());
        QCOMPARE(gpu.particleCount(), n);
        constexpr int kBins = 40;
        std::vector<double> a(kBins), b(kBins);
        for (double x : cpu.state().x) a[std::min(kBins - 1, int(x / 0.04 * kBins))] += 1;
        for (double x : gpu.state().x) b[std::min(kBins - 1, int(x / 0.04 * kBins))] += 1;
        double chi2 = 0;
        int occupied = 0;
        for (int k = 0; k < kBins; ++k)
            if (a[k] + b[k] > 0) chi2 += (a[k] - b[k]) * (a[k] - b[k]) / (a[k] + b[k]), ++occupied;
        const int peak = int(std::max_element(a.begin(), a.end()) - a.begin());
        qInfo("piston at %.4g m; densest bin %d: CPU %.0f, GPU %.0f; χ² %.1f over %d bins", cpu.pistonX(),
              peak, a[peak], b[peak], chi2, occupied);
        QVERIFY(a[peak] > 2.0 * double(n) / kBins); // compressed
        QVERIFY(chi2 < occupied + 5.0 * std::sqrt(2.0 * occupied));
    }
};

QTEST_GUILESS_MAIN(TestGlTunnel)
#include "tst_gl_tunnel.moc"
