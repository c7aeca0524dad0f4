// Timing helpers shared by particlelab-bench and the desktop's benchmark dialog.
#include "MachineBenchmark.h"

#include "FluidModelGL.h"
#include "GasModelGL.h"
#include "GlProgram.h"
#include "TunnelModelGL.h"
#include "catalog/ModelCatalog.h"
#include "fluid/FluidParams.h"
#include "tunnel/TunnelModel.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace pl::gl {

namespace {
using Clock = std::chrono::steady_clock;
constexpr double kSettleBatchSeconds = 0.1; // [s] one batch of the settling loop
constexpr double kSettledTolerance = 0.03;  // two batches within 3 % of each other: settled
constexpr double kFluidRows = 64.0;         // the tallest block of the scaled fluid, in particles

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

struct BatchTime {
    double seconds = 0; // issue and completion
    double issueSeconds = 0;
};

// Steps a batch; a cancel() that turns true ends it early (its time then measures nothing).
BatchTime timeBatch(Model& model, int steps, const std::function<bool()>& cancel) {
    const auto start = Clock::now();
    for (int s = 0; s < steps && !(cancel && cancel()); ++s) model.step();
    const auto issued = Clock::now();
    model.finishPendingWork();
    return {std::chrono::duration<double>(Clock::now() - start).count(),
            std::chrono::duration<double>(issued - start).count()};
}
} // namespace

Preset scaledGasPreset(std::size_t n) {
    Preset p;
    p.model = "gas";
    p.seed = 20240501;
    const double side = 2.0 * std::sqrt(static_cast<double>(n) / 4096.0);
    p.params = {{"box_width", side},
                {"box_height", side},
                {"count_a", static_cast<double>(n)},
                {"count_b", 0.0},
                {"diameter_a", 0.01},
                {"mass_a", 1.0},
                {"stiffness", 1000.0},
                {"init_velocity", std::string("fixed-speed")},
                {"init_speed", 1.0},
                {"init_placement", std::string("random")},
                {"integrator", gasIntegrator(GasIntegrator::VelocityVerlet).name},
                {"dt", 1e-4},
                {"max_particles", static_cast<double>(std::max<std::size_t>(n, 1))}};
    return p;
}

Preset scaledFluidPreset(std::size_t n) {
    Preset p;
    p.model = "fluid";
    p.seed = 20240501;
    const double h = 0.8, spacing = 0.5 * h;
    // A block at most kFluidRows particles tall, as wide as n needs: five Jacobi iterations hold a column
    // about that tall at its rest density, while a square block of 1M particles (1024 rows) collapses into
    // a layer compressed by 30 % with cells of 300+ particles, whose cost grows 4× as it piles up
    // (BENCHMARKS.md, "GPU backends", "Against the goals").
    const double rows = std::min(std::ceil(std::sqrt(static_cast<double>(n))), kFluidRows);
    const double width = std::ceil(static_cast<double>(n) / rows) * spacing, height = rows * spacing;
    // Room beside the block for it to spread, within what the parameters allow at both ends of the range:
    // at least 4 h across (a smaller box cannot hold the kernel's support), at most the box_width bound.
    const double widest = findSpec(FluidParams::describe(), "box_width")->max;
    const double boxWidth = std::clamp(2.0 * width + 1.0, 4.0 * h + 1.0, widest);
    const double boxHeight = std::max(1.5 * height + 1.0, 4.0 * h + 1.0);
    p.params = {{"kernel", std::string("2d")},
                {"self_density", true},
                {"rest_density_source", std::string("spawn-lattice")},
                {"epsilon", 1.0},
                {"h", h},
                {"spawn_spacing", 0.5},
                {"particle_radius", 0.2},
                {"iterations", 5.0},
                {"dt", 0.01},
                {"box_width", boxWidth},
                {"box_height", boxHeight},
                {"fill_x0", 0.0},
                {"fill_y0", 0.0},
                {"fill_x1", width},
                {"fill_y1", height},
                {"max_particles", static_cast<double>(2 * n + 1024)}};
    return p;
}

Preset scaledTunnelPreset(std::size_t n) {
    Preset p = loadPreset("tunnel-cylinder");
    TunnelParams params;
    params = withValues(params, TunnelParams::fields(), p.params);
    const double preset = static_cast<double>(TunnelModel::initialFillCount(params, p.obstacles));
    const double ratio = static_cast<double>(std::max<std::size_t>(n, 1)) / std::max(preset, 1.0);
    // The grid refines with √ratio (the molecules per cell stay), up to the tunnel's cell limit.
    const double cells = static_cast<double>(params.cellsX) * static_cast<double>(params.cellsY);
    const double refine = std::min(std::sqrt(ratio), std::sqrt(TunnelParams::maxCells() / cells));
    // The free stream over the whole domain must fit the molecule limit (TunnelParams::validate), which the
    // body's share of the domain leaves room for below the top of the range only.
    const double fullStream = params.streamDensity * params.boxWidth * params.boxHeight;
    p.params["fn"] = std::max(params.fn / ratio, fullStream / TunnelParams::maxParticles() * (1.0 + 1e-12));
    const double cellsX = std::max(1.0, std::round(static_cast<double>(params.cellsX) * refine));
    const double cellsY = std::max(1.0, std::round(static_cast<double>(params.cellsY) * refine));
    p.params["cells_x"] = cellsX;
    p.params["cells_y"] = std::min(cellsY, std::floor(TunnelParams::maxCells() / cellsX)); // rounding up
    p.params["run_steps"] = 0.0;
    return p;
}

BenchPoint timeModel(Model& model, const std::string& scene, const std::string& backend,
                     const BenchSettings& settings, const std::function<bool()>& cancel) {
    BenchPoint point;
    point.scene = scene;
    point.backend = backend;
    point.particles = model.particleCount();
    const double warm = timeBatch(model, settings.warmupSteps, cancel).seconds;
    double perStep = std::max(warm / std::max(settings.warmupSteps, 1), 1e-7);
    // A GPU that idled (while the host built the initial state, or ran CPU models) runs its passes up to
    // 3x slower for seconds after it is loaded again (BENCHMARKS.md, "The slow start of a GPU point"):
    // keep stepping in short batches until two in a row agree, so the repeats time the steady state.
    const auto settleStart = Clock::now();
    for (double previous = 0.0;;) {
        if (cancel && cancel()) return point;
        const int batch = std::max(settings.minSteps, static_cast<int>(kSettleBatchSeconds / perStep));
        perStep = std::max(timeBatch(model, batch, cancel).seconds / batch, 1e-7);
        const double elapsed = std::chrono::duration<double>(Clock::now() - settleStart).count();
        if (std::abs(perStep - previous) < kSettledTolerance * perStep || elapsed > settings.maxSettleSeconds)
            break;
        previous = perStep;
    }
    point.settleSeconds = std::chrono::duration<double>(Clock::now() - settleStart).count();
    const int steps = std::max(settings.minSteps, static_cast<int>(settings.targetSeconds / perStep));
    // The count may change while stepping (the tunnel fills its shock layer): the mean over the repeats.
    const std::size_t countBefore = model.particleCount();
    std::vector<double> rates, issue;
    for (int r = 0; r < settings.repeats; ++r) {
        if (cancel && cancel()) return point;
        const BatchTime t = timeBatch(model, steps, cancel);
        if (cancel && cancel()) return point;
        rates.push_back(steps / t.seconds);
        point.repeatMicrosecondsPerStep.push_back(1e6 * t.seconds / steps);
        issue.push_back(1e6 * t.issueSeconds / steps);
    }
    point.particles = (countBefore + model.particleCount()) / 2;
    const double stepsPerSecond = median(rates);
    point.issueMicrosecondsPerStep = median(issue);
    point.particleStepsPerSecond = stepsPerSecond * static_cast<double>(point.particles);
    point.microsecondsPerStep = 1e6 / stepsPerSecond;
    if (auto* gas = dynamic_cast<GasModelGL*>(&model)) point.dispatchesPerStep = gas->dispatchesLastStep();
    if (auto* fluid = dynamic_cast<FluidModelGL*>(&model))
        point.dispatchesPerStep = fluid->dispatchesLastStep();
    if (auto* tunnel = dynamic_cast<TunnelModelGL*>(&model))
        point.dispatchesPerStep = tunnel->dispatchesLastStep();
    return point;
}

double measureCopyBandwidth(std::size_t bytes, int repeats) {
    ComputeProgram copy("common/copy.comp");
    Buffer from, to;
    from.reserve(bytes);
    to.reserve(bytes);
    from.fillZero(bytes);
    const std::size_t items = bytes / 16; // one vec4 per invocation
    copy.use();
    copy.set("count", static_cast<unsigned>(items));
    from.bind(0);
    to.bind(1);
    std::vector<double> rates;
    for (int r = 0; r < repeats + 1; ++r) {
        glFinish();
        const auto start = Clock::now();
        constexpr int kCopies = 10;
        for (int c = 0; c < kCopies; ++c) {
            copy.dispatch(items, 256);
            storageBarrier();
        }
        glFinish();
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        if (r > 0)
            rates.push_back(2.0 * static_cast<double>(items * 16) * kCopies / seconds); // first: warm-up
    }
    return median(rates);
}

} // namespace pl::gl
