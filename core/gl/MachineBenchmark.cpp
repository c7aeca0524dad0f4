// Timing helpers shared by particlelab-bench and the desktop's benchmark dialog.
#include "MachineBenchmark.h"

#include "FluidModelGL.h"
#include "GasModelGL.h"
#include "GlProgram.h"
#include "TunnelModelGL.h"
#include "catalog/ModelCatalog.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace pl::gl {

namespace {
using Clock = std::chrono::steady_clock;
constexpr double kSettleBatchSeconds = 0.1; // [s] one batch of the settling loop
constexpr double kSettledTolerance = 0.03;  // two batches within 3 % of each other: settled

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

Preset scaledPreset(const std::string& kind, std::size_t n) {
    const ModelDescriptor* descriptor = findModel(kind);
    if (!descriptor || !descriptor->benchmark.scaledPreset)
        throw std::invalid_argument("the scene '" + kind + "' has no benchmark scale");
    return descriptor->benchmark.scaledPreset(n);
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
