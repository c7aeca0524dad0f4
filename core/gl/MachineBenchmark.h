// "Benchmark this machine": each kind with a benchmark scale (ModelDescriptor::benchmark) at growing N
// on each backend, timed the same way by the desktop dialog and by particlelab-bench. Time is measured over
// whole batches of steps ended by glFinish, so GPU queues are drained inside the timed region.
#pragma once

#include "Backends.h"

#include <functional>
#include <string>
#include <vector>

namespace pl::gl {

struct BenchPoint {
    std::string scene;   // the kind: "gas", "fluid", "tunnel"
    std::string backend; // "cpu" or "gl"
    std::size_t particles = 0;
    double particleStepsPerSecond = 0; // median over repeats
    double microsecondsPerStep = 0;
    int dispatchesPerStep = 0; // GPU only
    // Host time per step spent issuing the steps, before waiting for the GPU (median repeat): when it
    // nears microsecondsPerStep, the CPU side is the limit.
    double issueMicrosecondsPerStep = 0;
    std::vector<double> repeatMicrosecondsPerStep; // each repeat, in order
    double settleSeconds = 0;                      // [s] stepped before the repeats until the rate settled
};

// The benchmark experiment of a kind with about n particles (its registration's
// ModelDescriptor::benchmark). Throws std::invalid_argument for a kind without one.
Preset scaledPreset(const std::string& kind, std::size_t n);

// Steps per repeat that take about targetSeconds at a guessed rate, at least minSteps.
struct BenchSettings {
    int repeats = 5;
    double targetSeconds = 0.3;
    int minSteps = 20;
    int warmupSteps = 10;
    double maxSettleSeconds = 1.0; // [s] the longest the rate may take to settle before the repeats
};

// Times one model: warm-up, then repeats of a batch; returns the median. cancel() is polled between
// batches; a cancelled point has particleStepsPerSecond = 0.
BenchPoint timeModel(Model& model, const std::string& scene, const std::string& backend,
                     const BenchSettings& settings, const std::function<bool()>& cancel = {});

// GL copy bandwidth (read + write bytes per second) of a GLSL copy kernel over bytes, median of repeats.
double measureCopyBandwidth(std::size_t bytes, int repeats);

} // namespace pl::gl
