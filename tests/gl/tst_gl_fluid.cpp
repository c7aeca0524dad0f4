// The fluid on the GPU against the CPU reference: one step, a dam break's front and density error,
// the per-iteration error profile, obstacles, spawning and the drain between steps.
#include "catalog/ModelCatalog.h"
#include "gl/Backends.h"
#include "gl/FluidModelGL.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace pl;
using namespace pl::gl;

namespace {

// Positions ordered by their cell on a grid far finer than the spacing (0.01 against 0.4) but far
// coarser than float rounding: the GPU reorders particles, this pairs them up again.
std::vector<std::pair<double, double>> sortedPositions(const FluidState& s) {
    std::vector<std::pair<double, double>> p;
    for (std::size_t i = 0; i < s.size(); ++i) p.emplace_back(s.x[i], s.y[i]);
    auto key = [](const std::pair<double, double>& q) {
        return std::make_pair(std::lround(q.first / 0.01), std::lround(q.second / 0.01));
    };
    std::sort(p.begin(), p.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
    return p;
}

// The largest distance from a particle of one state to the nearest particle of the other, both ways: the
// GPU reorders particles, and where they do not sit on a lattice this pairs them up without an order.
double farthestFromTheOther(const FluidState& a, const FluidState& b) {
    auto oneWay = [](const FluidState& from, const FluidState& to) {
        double worst = 0;
        for (std::size_t i = 0; i < from.size(); ++i) {
            double nearest = std::numeric_limits<double>::infinity();
            for (std::size_t j = 0; j < to.size(); ++j)
                nearest = std::min(nearest, std::hypot(from.x[i] - to.x[j], from.y[i] - to.y[j]));
            worst = std::max(worst, nearest);
        }
        return worst;
    };
    return std::max(oneWay(a, b), oneWay(b, a));
}

} // namespace

class TestGlFluid : public QObject {
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

    // One step from the dam-break block. The GPU lands within float rounding of the CPU everywhere (median
    // 4e-7, worst 8e-6 with the block's corners moving by up to ~0.18 in this first, violent step, ε = 1):
    // both find the neighbours within 1.05 h of the predictions once and keep them through the iterations.
    // (When every GPU pass searched the cells around the current positions instead, the corners came out
    // up to 1.3e-3 apart.) The block sits on a lattice, so ordering positions by a fine grid pairs
    // particles up again.
    void oneStepMatchesCpu() {
        const Preset preset = loadPreset("fluid-dam-break");
        FluidModel cpu;
        cpu.reset(preset);
        const FluidState start = cpu.state(); // the CPU keeps its order: moves by index
        FluidModelGL gpu(context_);
        gpu.reset(preset);
        cpu.step();
        gpu.step();
        const auto a = sortedPositions(cpu.state()), b = sortedPositions(gpu.state());
        QCOMPARE(a.size(), b.size());
        std::vector<double> differences;
        double largestMove = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            differences.push_back(std::hypot(a[i].first - b[i].first, a[i].second - b[i].second));
            largestMove = std::max(largestMove,
                                   std::hypot(cpu.state().x[i] - start.x[i], cpu.state().y[i] - start.y[i]));
        }
        std::sort(differences.begin(), differences.end());
        const double median = differences[differences.size() / 2], worst = differences.back();
        qInfo("|Δx| after one step: median %.3g, worst %.3g; largest move %.3g", median, worst, largestMove);
        QVERIFY(median < 1e-5);
        QVERIFY(worst < 1e-4);
    }

    // Many steps: the free-surface flow is chaotic in detail, its measures are not.
    void damBreakFrontAndDensityErrorMatchCpu() {
        const Preset preset = loadPreset("fluid-dam-break");
        FluidModel cpu;
        cpu.reset(preset);
        FluidModelGL gpu(context_);
        gpu.reset(preset);
        for (int s = 0; s < 200; ++s) cpu.step(), gpu.step();
        const FluidObservables oc = cpu.observe(), og = gpu.observe();
        qInfo("front Z %.3f / %.3f, error mean %.4f / %.4f, max %.3f / %.3f", oc.frontZ, og.frontZ,
              oc.densityErrorMean, og.densityErrorMean, oc.densityErrorMax, og.densityErrorMax);
        QCOMPARE(og.particles, oc.particles);
        QVERIFY(std::abs(og.frontZ - oc.frontZ) < 0.05 * oc.frontZ);
        QVERIFY(std::abs(og.densityErrorMean - oc.densityErrorMean) < 0.3 * oc.densityErrorMean + 1e-3);
        QVERIFY(!gpu.failure());
    }

    // A fluid packed so tightly that each particle has ~38 neighbours within the search radius, more
    // than the first list holds: those particles walk their cells, and after a health check (every 64
    // steps) the list has grown to hold them. From one saved state, a model with the grown list and a
    // fresh one walking cells take the same step as the CPU: the walk and the list give the same pairs.
    void aCrowdedFluidWalksItsCellsUntilItsListGrows() {
        Preset preset = loadPreset("fluid-dam-break");
        preset.params["spawn_spacing"] = 0.3;
        preset.params["fill_x1"] = 6.0;
        preset.params["fill_y1"] = 8.0;
        FluidModelGL grown(context_);
        grown.reset(preset);
        const unsigned first = grown.neighbourListLength();
        for (int s = 0; s < 64; ++s) grown.step();
        QVERIFY(!grown.failure());
        QVERIFY2(grown.neighbourListLength() > first, "the list grows after particles overflowed it");
        const StateRecord saved = grown.saveState();
        FluidModelGL walking(context_);
        walking.reset(preset);
        walking.restoreState(saved);
        QCOMPARE(walking.neighbourListLength(), first);
        FluidModel cpu;
        cpu.reset(preset);
        cpu.restoreState(saved);
        const FluidState before = cpu.state();
        grown.step(), walking.step(), cpu.step();
        double largestMove = 0;
        for (std::size_t i = 0; i < before.size(); ++i)
            largestMove = std::max(
                largestMove, std::hypot(cpu.state().x[i] - before.x[i], cpu.state().y[i] - before.y[i]));
        const double listed = farthestFromTheOther(cpu.state(), grown.state()),
                     walked = farthestFromTheOther(cpu.state(), walking.state());
        qInfo("list %u → %u; the farthest particle from the CPU's: list %.3g, cells %.3g; largest move %.3g",
              first, grown.neighbourListLength(), listed, walked, largestMove);
        // The saved state is 64 chaotic steps in: float rounding that those steps left differs from run to
        // run (the sort's atomics order each cell), and one step amplifies it as in oneStepMatchesCpu.
        QVERIFY(listed < 0.015 * largestMove);
        QVERIFY(walked < 0.015 * largestMove);
    }

    // The λ pass's group reductions give the same per-iteration profile as the CPU's serial sums.
    void iterationErrorsComeFromTheGpu() {
        const Preset preset = loadPreset("fluid-dam-break");
        FluidModelGL gpu(context_);
        gpu.reset(preset);
        for (int s = 0; s < 30; ++s) gpu.step();
        const std::vector<double> mean = gpu.iterationErrorMean();
        QCOMPARE(mean.size(), std::size_t(gpu.parameters().iterations + 1));
        QVERIFY(mean.front() > 0);
        QVERIFY2(mean.back() < mean.front(), "the corrections reduce the compression within the step");
        // The last λ pass measured the state before the last correction: close to what the CPU
        // measures on the pulled state after it, and never below zero.
        for (double e : mean) QVERIFY(e >= 0 && std::isfinite(e));
    }

    void obstaclesSpawningAndTheDrainWork() {
        Preset preset = loadPreset("fluid-obstacle");
        constexpr std::size_t kCap = 3900; // the pool holds 3840
        preset.params["max_particles"] = double(kCap);
        FluidModelGL gpu(context_);
        gpu.reset(preset);
        const std::size_t before = gpu.particleCount();
        for (int s = 0; s < 10; ++s) gpu.step();
        const std::string message = gpu.spawnInRectangle(2, 30, 20, 34);
        QVERIFY2(message.find("the drain will remove") != std::string::npos, message.c_str());
        gpu.step();
        QCOMPARE(gpu.particleCount(), kCap);
        QVERIFY(before < kCap);
        const Obstacle& o = gpu.obstacles().front();
        for (int s = 0; s < 20; ++s) gpu.step();
        const FluidState& st = gpu.state();
        for (std::size_t i = 0; i < st.size(); ++i)
            QVERIFY2(!o.contains(st.x[i], st.y[i], 0.5 * gpu.parameters().particleRadius),
                     "no particle inside the disc");
        QVERIFY(!gpu.failure());
    }

    void divergenceIsCaught() {
        Preset preset = loadPreset("fluid-dam-break");
        preset.params["epsilon"] = 1e-30;
        preset.params["dt"] = 0.5;
        FluidModelGL gpu(context_);
        gpu.reset(preset);
        for (int s = 0; s < 200 && !gpu.failure(); ++s) gpu.step();
        const FluidState& st = gpu.state();
        const bool finite =
            std::all_of(st.vx.begin(), st.vx.end(), [](double v) { return std::isfinite(v); });
        QVERIFY2(gpu.failure().has_value() || finite, "a diverged solve is reported, never silently NaN");
    }

    void factoryMakesTheFluidOnTheGpu() {
        const Preset preset = loadPreset("fluid-dam-break");
        auto choice = createModel("fluid", Backend::Gl, &preset, context_);
        QCOMPARE(choice.backend, Backend::Gl);
        QVERIFY(dynamic_cast<FluidModelGL*>(choice.model.get()));
        QCOMPARE(choice.model->particleCount(), std::size_t(1250));
    }
};

QTEST_GUILESS_MAIN(TestGlFluid)
#include "tst_gl_fluid.moc"
