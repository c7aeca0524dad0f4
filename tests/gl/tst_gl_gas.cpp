// The gas on the GPU against the CPU reference: counting sort, one step, ensembles, reductions and
// histograms, blow-up detection, shader sources. Runs on whatever GL 4.3 context the headless path
// finds (llvmpipe in CI), and skips only where none exists.
#include "gl/Backends.h"
#include "gl/GasModelGL.h"
#include "gl/GlProgram.h"
#include "gl/GpuCellGrid.h"
#include "gl/MachineBenchmark.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>

using namespace pl;
using namespace pl::gl;

namespace {

Preset gasPreset(ParamValues params, std::vector<Obstacle> obstacles = {}) {
    Preset p;
    p.model = "gas";
    p.seed = 7;
    p.params = std::move(params);
    p.obstacles = std::move(obstacles);
    return p;
}

// 1600 stiff disks placed at random (overlaps allowed) at speed 1: many contacts from the start. With
// more disks (smaller, at the same area fraction) the grid passes 2047 cells, and the sort takes the
// three-dispatch path instead of the one-work-group one.
Preset denseGas(const std::string& integrator, double disks = 1600) {
    return gasPreset({{"count_a", disks},
                      {"diameter_a", 0.04 * std::sqrt(1600 / disks)},
                      {"stiffness", 1e4},
                      {"init_placement", std::string("random")},
                      {"init_velocity", std::string("fixed-speed")},
                      {"integrator", integrator},
                      {"dt", 1e-4},
                      {"gravity", 1.0}},
                     {Obstacle{Obstacle::Shape::Disc, 0.3, 0.2, 0.15},
                      Obstacle{Obstacle::Shape::Box, -0.5, -0.4, 0.1, 0.2, 0.1}});
}

std::map<std::uint32_t, std::size_t> byId(const GasState& s) {
    std::map<std::uint32_t, std::size_t> index;
    for (std::size_t i = 0; i < s.size(); ++i) index[s.id[i]] = i;
    return index;
}

} // namespace

class TestGlGas : public QObject {
    Q_OBJECT
    std::shared_ptr<GlContext> context_;

private slots:
    void initTestCase() {
        try {
            context_ = sharedHeadlessContext();
        } catch (const GlUnavailable& e) {
            QSKIP(e.what());
        }
        qInfo("GL context: %s", context_->info().summary().c_str());
    }

    void contextIsFourThree() {
        QVERIFY(epoxy_gl_version() >= 43);
        QVERIFY(!context_->info().renderer.empty());
    }

    void shaderSourcesResolveIncludesOnceWithLineNumbers() {
        const ResolvedShader s = resolveShader("gas/gas_drift.comp", "#define EXTRA 1");
        QCOMPARE(s.files.front(), std::string("gas/gas_drift.comp"));
        QVERIFY(std::count(s.files.begin(), s.files.end(), "gas/gas_kernels.glsl") == 1);
        QVERIFY(std::count(s.files.begin(), s.files.end(), "common/philox.glsl") == 1);
        QVERIFY(s.text.rfind("#version 430\n#define EXTRA 1\n#line 2 0\n", 0) == 0);
        QVERIFY_THROWS_EXCEPTION(ShaderError, resolveShader("gas/no_such.comp"));
    }

    void compileErrorsNameTheFileAndLine() {
        const std::vector<std::string> files{"gas/gas_forces.comp", "gas/gas_kernels.glsl"};
        const std::string mesa = annotateLog("1:14(9): error: `x' undeclared\n", files);
        QVERIFY2(mesa.find("resources/shaders/gas/gas_kernels.glsl:14:9: error") != std::string::npos,
                 mesa.c_str());
        const std::string nvidia = annotateLog("0(31) : error C1008: undefined variable \"y\"\n", files);
        QVERIFY2(nvidia.find("resources/shaders/gas/gas_forces.comp:31 : error") != std::string::npos,
                 nvidia.c_str());
    }

    void countingSortIsAPermutationInCellOrder_data() {
        QTest::addColumn<int>("disks");
        QTest::newRow("one work group sorts (784 cells)") << 0;
        QTest::newRow("count, two-level scan, scatter (~10k cells)") << 20000;
    }

    // After a step the GPU holds every disk once, in the order of its cell.
    void countingSortIsAPermutationInCellOrder() {
        QFETCH(int, disks);
        GasModelGL model(context_);
        model.reset(disks == 0 ? denseGas("velocity-verlet") : scaledPreset("gas", std::size_t(disks)));
        model.step();
        QCOMPARE(model.dispatchesLastStep(), disks == 0 ? 2 : 6);
        const GasState& s = model.state();
        QCOMPARE(s.size(), std::size_t(disks == 0 ? 1600 : disks));
        std::vector<std::uint32_t> ids(s.id.begin(), s.id.end());
        std::sort(ids.begin(), ids.end());
        for (std::uint32_t i = 0; i < ids.size(); ++i) QCOMPARE(ids[i], i);
        const GpuCellGrid& grid = model.cellGrid();
        QVERIFY(grid.side() >= model.parameters().maxDiameter());
        const double left = model.parameters().left(), bottom = model.parameters().bottom();
        long long previous = -1;
        for (std::size_t i = 0; i < s.size(); ++i) {
            const int cx = std::clamp(int((s.x[i] - left) / grid.side()), 0, grid.nx() - 1);
            const int cy = std::clamp(int((s.y[i] - bottom) / grid.side()), 0, grid.ny() - 1);
            const long long cell = static_cast<long long>(cy) * grid.nx() + cx;
            QVERIFY2(cell >= previous, "disks are in cell order");
            previous = cell;
        }
    }

    void oneStepMatchesCpu_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("disks");
        QTest::addColumn<unsigned>("forceLanes"); // invocations per disk in the force pass (0: automatic)
        for (const char* name : {"velocity-verlet", "symplectic-euler", "explicit-euler", "forest-ruth"})
            QTest::newRow(name) << QString(name) << 1600.0 << 0u;
        QTest::newRow("velocity-verlet, 3-dispatch sort") << QString("velocity-verlet") << 9000.0 << 0u;
        for (unsigned lanes : {2u, 8u, 32u})
            QTest::newRow(qPrintable(QString("forest-ruth, %1 invocations per disk").arg(lanes)))
                << QString("forest-ruth") << 1600.0 << lanes;
    }

    // float32 tolerances: positions of magnitude ≤ 1 carry ≤ 6e-8 rounding each, so a pair distance is
    // off by up to 4 ulp(1) ≈ 4.8e-7 and a contact force k(d − r) by k·4.8e-7 = 4.8e-3; with up to ten
    // overlapping partners accelerations agree to 0.05 (|a| reaches ~1000 here: 5e-5 relative).
    // Positions after three steps of 1e-4 agree to a few ulps, velocities to 3 dt·|Δa| plus rounding.
    void oneStepMatchesCpu() {
        QFETCH(QString, integrator);
        QFETCH(double, disks);
        QFETCH(unsigned, forceLanes);
        const Preset preset = denseGas(integrator.toStdString(), disks);
        GasModel cpu;
        cpu.reset(preset);
        GasModelGL gpu(context_);
        gpu.reset(preset);
        gpu.setForceLanesPerDisk(forceLanes);
        for (int s = 0; s < 3; ++s) {
            cpu.step();
            gpu.step();
        }
        const GasState& a = cpu.state();
        const GasState& b = gpu.state();
        const auto index = byId(b);
        double worstX = 0, worstA = 0, worstV = 0, maxA = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            const std::size_t j = index.at(a.id[i]);
            worstX = std::max({worstX, std::abs(a.x[i] - b.x[j]), std::abs(a.y[i] - b.y[j])});
            worstV = std::max({worstV, std::abs(a.vx[i] - b.vx[j]), std::abs(a.vy[i] - b.vy[j])});
            worstA = std::max({worstA, std::abs(a.ax[i] - b.ax[j]), std::abs(a.ay[i] - b.ay[j])});
            maxA = std::max(maxA, std::hypot(a.ax[i], a.ay[i]));
        }
        qInfo("worst |Δx| %.3g, |Δv| %.3g, |Δa| %.3g of max |a| %.3g", worstX, worstV, worstA, maxA);
        QVERIFY(worstX < 1e-6);
        QVERIFY(worstV < 1e-5);
        QVERIFY(worstA < 0.05);
        QVERIFY(maxA > 50); // contacts were resolved, not just gravity
    }

    // Many steps: chaos separates the trajectories, the ensemble averages stay the same.
    void ensembleAveragesMatchCpu() {
        const Preset preset = gasPreset({{"count_a", 1500.0},
                                         {"diameter_a", 0.03},
                                         {"stiffness", 1e5},
                                         {"init_placement", std::string("lattice")},
                                         {"dt", 2e-4},
                                         {"pressure_window", 0.2}});
        GasModel cpu;
        cpu.reset(preset);
        GasModelGL gpu(context_);
        gpu.reset(preset);
        double kT[2] = {}, pressure[2] = {}, wall[2] = {}, rate[2] = {};
        int samples = 0;
        for (int s = 1; s <= 3000; ++s) {
            cpu.step();
            gpu.step();
            if (s % 100 || s < 1000) {
                if (s % 100 == 0) (void)cpu.observe(), (void)gpu.observe();
                continue;
            }
            const GasObservables oc = cpu.observe(), og = gpu.observe();
            kT[0] += oc.kT, kT[1] += og.kT;
            pressure[0] += oc.pressureVirial, pressure[1] += og.pressureVirial;
            wall[0] += oc.pressureWall, wall[1] += og.pressureWall;
            rate[0] += oc.collisionRate, rate[1] += og.collisionRate;
            ++samples;
        }
        qInfo("kT %.5f / %.5f, virial P %.4f / %.4f, wall P %.4f / %.4f, contact rate %.1f / %.1f",
              kT[0] / samples, kT[1] / samples, pressure[0] / samples, pressure[1] / samples,
              wall[0] / samples, wall[1] / samples, rate[0] / samples, rate[1] / samples);
        QVERIFY(std::abs(kT[1] / kT[0] - 1) < 0.01);             // energy is conserved on both
        QVERIFY(std::abs(pressure[1] / pressure[0] - 1) < 0.05); // fluctuating: a few per cent
        QVERIFY(std::abs(wall[1] / wall[0] - 1) < 0.1);
        QVERIFY(std::abs(rate[1] / rate[0] - 1) < 0.1);
        QVERIFY(!gpu.failure());
    }

    // The GPU's sums and histograms of one state against the CPU's of the same state; the energies
    // through the force pass's lane sums (8 invocations per disk).
    void reductionsAndHistogramsMatchCpu() {
        GasModelGL gpu(context_);
        gpu.reset(denseGas("velocity-verlet"));
        gpu.setForceLanesPerDisk(8);
        for (int s = 0; s < 20; ++s) gpu.step();
        std::vector<GasParticle> particles;
        const GasState& s = gpu.state();
        for (std::size_t i = 0; i < s.size(); ++i)
            particles.push_back({s.x[i], s.y[i], s.vx[i], s.vy[i], s.species[i]});
        GasModel cpu;
        cpu.reset(denseGas("velocity-verlet"));
        cpu.placeParticles(particles);
        const GasObservables og = gpu.observe(), oc = cpu.observe();
        QVERIFY(std::abs(og.kinetic / oc.kinetic - 1) < 1e-5);
        QVERIFY(std::abs(og.potential / oc.potential - 1) < 1e-3);
        QVERIFY(std::abs(og.pressureVirial / oc.pressureVirial - 1) < 1e-3);
        QVERIFY(std::abs(og.px - oc.px) < 1e-3 && std::abs(og.py - oc.py) < 1e-3);
        QCOMPARE(og.particles, oc.particles);
        // Binned KS: at most one fine bin's mass (≈ 0.0015) below the exact statistic.
        QVERIFY2(og.ksDistance[0] <= oc.ksDistance[0] + 1e-6 && og.ksDistance[0] > oc.ksDistance[0] - 0.003,
                 qPrintable(QString("KS %1 vs %2").arg(og.ksDistance[0]).arg(oc.ksDistance[0])));
        const auto hg = gpu.histograms(), hc = cpu.histograms();
        QCOMPARE(hg.size(), hc.size());
        double differ = 0;
        for (std::size_t b = 0; b < hc[0].counts.bins(); ++b)
            differ += std::abs(hg[0].counts.count(b) - hc[0].counts.count(b));
        QVERIFY2(differ <= 4, "only speeds within float rounding of a bin edge may land differently");
        QCOMPARE(hg[0].counts.total(), hc[0].counts.total());
        QCOMPARE(hg[0].name, hc[0].name);
    }

    void forceLanesAreChosenOrRefused() {
        GasModelGL gpu(context_);
        gpu.reset(denseGas("velocity-verlet"));
        QCOMPARE(gpu.forceLanesPerDisk(), context_->info().software ? 1u : 8u); // 1600 disks: spread them
        gpu.setForceLanesPerDisk(4);
        QCOMPARE(gpu.forceLanesPerDisk(), 4u);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, gpu.setForceLanesPerDisk(3));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, gpu.setForceLanesPerDisk(64));
        QCOMPARE(gpu.forceLanesPerDisk(), 4u); // a refused count changes nothing
    }

    void blowUpIsCaughtOnTheGpu() {
        Preset preset = denseGas("velocity-verlet");
        preset.params["dt"] = 2e-3; // ω dt = √(2k/m) dt ≈ 0.28 per contact, but overlapping lattice … then 8×
        preset.params["stiffness"] = 1e6;
        GasModelGL gpu(context_);
        gpu.reset(preset);
        for (int s = 0; s < 2000 && !gpu.failure(); ++s) gpu.step();
        QVERIFY(gpu.failure().has_value());
        QVERIFY2(gpu.failure()->hint.find("dt·ω") != std::string::npos, gpu.failure()->hint.c_str());
        for (double x : gpu.state().x) QVERIFY(std::isfinite(x));
        const auto stepsAtFailure = gpu.stepCount();
        gpu.step();
        QCOMPARE(gpu.stepCount(), stepsAtFailure);
    }

    void cpuOnlySettingsStillRunOnTheGlModel() {
        Preset preset = denseGas("rk4");
        GasModelGL gpu(context_);
        gpu.reset(preset);
        QVERIFY(!gpu.stepsOnGpu());
        GasModel cpu;
        cpu.reset(preset);
        for (int s = 0; s < 5; ++s) gpu.step(), cpu.step();
        QCOMPARE(gpu.state().x, cpu.state().x); // the same CPU code on the same state
    }

    void editsBetweenStepsReachTheGpu() {
        GasModelGL gpu(context_);
        gpu.reset(denseGas("velocity-verlet"));
        gpu.step();
        const auto before = gpu.particleCount();
        const SpawnResult r = gpu.spawnRectangle(-0.95, 0.85, -0.6, 0.95, 0, 0.5);
        QVERIFY(r.added > 0);
        gpu.step();
        QCOMPARE(gpu.particleCount(), before + std::size_t(r.added));
        QCOMPARE(gpu.observe().particles, before + std::size_t(r.added));
        gpu.scaleKineticEnergy(4.0);
        const double k0 = gpu.observe().kinetic;
        gpu.step();
        QVERIFY(std::abs(gpu.observe().kinetic / k0 - 1) < 0.05);
    }

    void factoryPicksTheBackend() {
        const Preset preset = denseGas("velocity-verlet");
        auto gl = createModel("gas", Backend::Gl, &preset, context_);
        QCOMPARE(gl.backend, Backend::Gl);
        QVERIFY(dynamic_cast<GasModelGL*>(gl.model.get()));
        auto cpu = createModel("gas", Backend::Cpu, &preset, context_);
        QVERIFY(!dynamic_cast<GasModelGL*>(cpu.model.get()));
        auto dsmc = createModel("dsmc", Backend::Gl, nullptr, context_);
        QCOMPARE(dsmc.backend, Backend::Cpu);
        QVERIFY(dsmc.message.find("no GPU model") != std::string::npos);
        // A software rasteriser shares the CPU's cores: auto keeps the CPU there.
        auto automatic = createModel("gas", Backend::Auto, &preset, context_);
        QCOMPARE(automatic.backend, context_->info().software ? Backend::Cpu : Backend::Gl);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, backendFromName("cuda"));
    }
};

QTEST_GUILESS_MAIN(TestGlGas)
#include "tst_gl_gas.moc"
