// "Benchmark this machine": the gas (and later scenes) at growing N on each backend, timed the same way
// by the desktop dialog and by particlelab-bench. Time is measured over whole batches of steps ended by
// glFinish, so GPU queues are drained inside the timed region.
#pragma once

#include "Backends.h"

#include <functional>
#include <string>
#include <vector>

namespace pl::gl {

struct BenchPoint {
    std::string scene;   // "gas", "fluid" or "tunnel"
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

// The write-up's gas (velocity Verlet, d = 0.01, k = 1000, speed 1) with n disks at the write-up's area
// fraction: the box grows as √(n / 4096).
Preset scaledGasPreset(std::size_t n);

// The dam break's fluid (2D kernels, ε = 1, h = 0.8, spacing 0.4) with about n particles in one block at
// most 64 rows tall (square below 4096 particles) in a tank twice as wide and 1.5 times as high,
// 5 iterations: a column five iterations hold at its rest density at every n.
Preset scaledFluidPreset(std::size_t n);

// The `tunnel-cylinder` preset (hypersonic argon past a cylinder, collisions on) scaled to about n
// simulated molecules: F_N shrinks and the cell grid refines by √ of the ratio along each side, so the
// flow (density, Kn, Δt) and the molecules per cell stay the preset's and only the resolution grows.
Preset scaledTunnelPreset(std::size_t n);

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
