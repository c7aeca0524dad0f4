// particlelab-bench: the GPU benchmark runner. Links core + gl only (no Qt), so it runs headless on a
// machine with nothing but a GL driver. Prints one JSON line per measurement and a table at the end.
#include "../cli/OptionChecks.h"
#include "common/AtomicFile.h"
#include "common/StopSignals.h"
#include "gl/Backends.h"
#include "gl/FluidModelGL.h"
#include "gl/GasModelGL.h"
#include "gl/MachineBenchmark.h"
#include "tunnel/TunnelParams.h"

#include <CLI/CLI.hpp>
#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>

namespace {

// Bytes the gas's GPU step must move per disk (velocity Verlet), from the kernels' loads and stores:
// count pass reads pos, vel, acc, tag (28) and writes (cell, slot) (8) plus a 4-byte atomic; the
// scatter pass reads the same 28 + 8 + a 4-byte cell start and writes pos, vel, tag (20); the scan
// reads, writes and clears about half a count per disk (6); the force pass reads pos, vel, tag (20)
// and writes acc (8). Neighbour reads hit the cache in cell order and are not counted.
constexpr double kGasBytesPerParticleStep = 40 + 60 + 6 + 28;

// The fluid's (5 iterations): predict count 16 + 12, scatter 28 + 24 (x, v, x*), scan 3, per iteration
// λ 8 + 4 and Δx 12 + 8, velocity 16 + 8. Neighbour reads hit the cache and are not counted.
constexpr int kFluidIterations = 5;
constexpr double kFluidBytesPerParticleStep = 28 + 52 + 3 + kFluidIterations * (12 + 20) + 24;

// The tunnel's (tunnel-cylinder, collisions on): the move reads a molecule (position 8, velocity 8 + 4)
// and writes it moved with its (cell, slot) (28) plus a 4-byte atomic; the scatter reads that and a
// cell start (32) and writes the sorted molecule (20); the collide-and-sample pass reads each velocity
// once for the sums (12; pair reads hit the cache within a cell, about one accepted pair per molecule
// writes 12 more). The scan and the per-cell arrays are ~1/40 of a word per molecule.
constexpr double kTunnelBytesPerParticleStep = 52 + 52 + 24;
// The issue's goal for the tunnel on an H200: particle-steps per second at 10 M molecules.
constexpr double kTunnelGoal = 2e9;

// The longest a repeat or the settling may be asked to take [s], and the most repeats: an hour per point
// at most.
constexpr double kMaxTargetSeconds = 60.0;
constexpr long long kMaxRepeats = 60;

// The most particles each scene's scaled preset may have: the gas's count_a range, the fluid's particle cap
// (which the scaled preset sets to 2 n + 1024), the tunnel's molecule limit.
long long maxGasSize() {
    return static_cast<long long>(pl::findSpec(pl::GasParams::describe(), "count_a")->max);
}
long long maxFluidSize() {
    return (static_cast<long long>(pl::findSpec(pl::FluidParams::describe(), "max_particles")->max) - 1024) /
           2;
}
long long maxTunnelSize() {
    return static_cast<long long>(pl::TunnelParams::maxParticles());
}

pl::Preset scaledPreset(const std::string& scene, std::size_t n) {
    return scene == "gas"     ? pl::gl::scaledGasPreset(n)
           : scene == "fluid" ? pl::gl::scaledFluidPreset(n)
                              : pl::gl::scaledTunnelPreset(n);
}

// Why scene cannot be timed at n, as the scene's reset would refuse it (the gas: more disks than half the
// physical memory holds; the tunnel: more cells than it allows), or empty: checked for every point
// before the first one runs.
std::string pointRefusal(const std::string& scene, std::size_t n) {
    try {
        const pl::Preset preset = scaledPreset(scene, n);
        if (scene == "gas")
            pl::validateParams(pl::withValues(pl::GasParams{}, pl::GasParams::fields(), preset.params));
        else if (scene == "fluid")
            pl::validateParams(pl::withValues(pl::FluidParams{}, pl::FluidParams::fields(), preset.params));
        else
            pl::validateParams(pl::withValues(pl::TunnelParams{}, pl::TunnelParams::fields(), preset.params));
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

} // namespace

int main(int argc, char** argv) {
    using pl::cli::positiveReal;
    using pl::cli::wholeNumber;
    CLI::App app{"ParticleLab GPU benchmark: particle-steps per second against N, headless"};
    app.set_version_flag("--version", std::string("particlelab-bench ") + PARTICLELAB_VERSION,
                         "Print the program's version and exit");
    std::vector<std::size_t> gasSizes{4096, 16384, 65536, 262144, 1048576, 4194304};
    std::vector<std::size_t> fluidSizes{10000, 40000, 160000, 640000, 1048576};
    std::vector<std::size_t> tunnelSizes{100000, 1000000, 10000000};
    std::vector<std::string> scenes{"gas", "fluid", "tunnel"};
    std::size_t cpuMax = 65536;
    std::string out;
    pl::gl::BenchSettings settings;
    app.add_option("--gas", gasSizes,
                   "Gas sizes (disks), each at most what half the physical memory holds (240 bytes a disk)")
        ->transform(wholeNumber(1, maxGasSize(), "the gas's count_a range"));
    app.add_option("--fluid", fluidSizes, "Fluid sizes (particles, 5 iterations)")
        ->transform(wholeNumber(1, maxFluidSize(), "the fluid's particle cap, which is 2 N + 1024 here"));
    app.add_option(
           "--tunnel", tunnelSizes,
           "Wind-tunnel sizes (molecules): tunnel-cylinder with collisions, F_N and the cell grid scaled")
        ->transform(wholeNumber(1, maxTunnelSize(), "the tunnel's molecule limit"));
    app.add_option(
           "--scenes", scenes,
           "Scenes to time, of gas, fluid, tunnel (default all). Only the tunnel points: --scenes tunnel; "
           "e.g. --scenes tunnel --tunnel 100000 1000000 10000000, or --tunnel 20000 on llvmpipe")
        ->check(CLI::IsMember({"gas", "fluid", "tunnel"}));
    app.add_option("--cpu-max", cpuMax, "Largest N also timed on the CPU model (0: none)")
        ->transform(wholeNumber(0, std::max({maxGasSize(), maxFluidSize(), maxTunnelSize()}),
                                "the largest size of any scene"));
    app.add_option("--repeats", settings.repeats, "Timed repeats per point; the median is reported")
        ->transform(wholeNumber(1, kMaxRepeats));
    app.add_option("--seconds", settings.targetSeconds, "Target seconds per repeat")
        ->check(positiveReal(false, kMaxTargetSeconds));
    settings.maxSettleSeconds = 8.0;
    app.add_option("--settle", settings.maxSettleSeconds,
                   "Longest seconds a point steps before its repeats, until two batches agree within 3 %")
        ->check(positiveReal(true, kMaxTargetSeconds));
    app.add_option("--out", out,
                   "Also write the JSON lines to this file, each as it is measured (checked before the "
                   "sweep: a directory, a FIFO or a path that cannot be created is refused with exit 4)")
        ->check(pl::cli::fileName());
    std::vector<unsigned> forceLanes{0};
    app.add_option(
           "--force-lanes", forceLanes,
           "Invocations per disk in the gas's force pass, each timed: 0 (automatic) or a power of two "
           "up to 32")
        ->check(CLI::IsMember({0u, 1u, 2u, 4u, 8u, 16u, 32u}));
    bool glDebug = false, profileEach = false;
    app.add_flag("--profile-each", profileEach,
                 "After timing each GPU gas point, profile its passes on the same model (timestamps)");
    app.add_flag("--gl-debug", glDebug, "Print the driver's debug messages (performance remarks)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e); // --help, --version: the text, exit 0
        std::cerr << "particlelab-bench: " << e.what() << "; see 'particlelab-bench --help'\n";
        return 2; // a bad option, as particlelab-cli answers it
    }
    // A stop signal ends the checks and the GL set-up at once, saying so; once the sweep runs, it ends the
    // sweep at the point being timed, keeping every line measured before it.
    pl::StopSignals stop("particlelab-bench");
    // Every point is checked before the first one runs, and so is the file: a sweep never ends in either.
    struct SizeOption {
        const char* option;
        std::string scene;
        const std::vector<std::size_t>* sizes;
    };
    for (const SizeOption& o :
         {SizeOption{"--gas", "gas", &gasSizes}, SizeOption{"--fluid", "fluid", &fluidSizes},
          SizeOption{"--tunnel", "tunnel", &tunnelSizes}})
        if (std::find(scenes.begin(), scenes.end(), o.scene) != scenes.end())
            for (const std::size_t n : *o.sizes)
                if (const std::string refusal = pointRefusal(o.scene, n); !refusal.empty()) {
                    std::cerr << "particlelab-bench: " << o.option << " " << n << ": " << refusal << "\n";
                    return 2;
                }
    std::unique_ptr<pl::StreamedFile> file; // each line reaches the file as it is measured
    try {
        if (!out.empty()) {
            pl::checkOutputPath(out);
            file = std::make_unique<pl::StreamedFile>(out);
        }
    } catch (const pl::FileError& e) {
        std::cerr << "particlelab-bench: " << e.what() << "\n";
        return 4; // an output that cannot be written, as particlelab-cli answers it
    }
    int exitCode = 0;
    // A file that fails while the sweep runs (a full disk) is reported once; the lines go on to stdout.
    const auto fileFailed = [&](const pl::FileError& e) {
        std::cerr << "particlelab-bench: " << e.what() << "; the lines go on to standard output only\n";
        file.reset();
        exitCode = 4;
    };
    auto emit = [&](const nlohmann::json& j) {
        std::cout << j.dump() << std::endl;
        try {
            if (file) file->write(j.dump() + '\n');
        } catch (const pl::FileError& e) {
            fileFailed(e);
        }
    };
    std::shared_ptr<pl::gl::GlContext> context;
    try {
        context = pl::gl::sharedHeadlessContext();
    } catch (const pl::gl::GlUnavailable& e) {
        std::cerr << "particlelab-bench: " << e.what() << '\n';
        return 2;
    }
    if (glDebug) {
        // Driver remarks (e.g. buffers moved between video and host memory) go to stderr, once each.
        glEnable(GL_DEBUG_OUTPUT);
        glDebugMessageCallback(
            [](GLenum, GLenum type, GLuint id, GLenum, GLsizei, const GLchar* message, const void*) {
                static std::vector<GLuint> seen;
                if (std::find(seen.begin(), seen.end(), id) != seen.end() || seen.size() > 50) return;
                seen.push_back(id);
                std::fprintf(stderr, "GL debug (type 0x%x, id %u): %s\n", type, id, message);
            },
            nullptr);
    }
    stop.runStarts();
    const auto stopped = [&] { return stop.caught() != 0; };
    const auto& info = context->info();
    const double copy = pl::gl::measureCopyBandwidth(std::size_t{256} << 20, 5);
    emit({{"context", info.summary()}, {"copy_bandwidth_bytes_per_s", copy}});

    std::vector<pl::gl::BenchPoint> points;
    // Where the time goes: GPU timestamps around each pass (a sync every step, so the passes add up to
    // more than a pipelined step).
    auto profilePasses = [&](pl::gl::GasModelGL& model, std::size_t n) {
        model.setProfiling(true);
        constexpr int kProfiledSteps = 50;
        for (int s = 0; s < kProfiledSteps; ++s) model.step();
        for (const auto& [pass, ns] : model.profile())
            emit({{"scene", "gas"},
                  {"particles", n},
                  {"pass", pass},
                  {"us_per_step", ns / kProfiledSteps / 1e3}});
        model.setProfiling(false);
    };
    auto selected = [&](const std::string& scene) {
        return std::find(scenes.begin(), scenes.end(), scene) != scenes.end();
    };
    auto sweep = [&](const std::string& scene, const std::vector<std::size_t>& sizes, double bytes,
                     double goal) {
        if (!selected(scene)) return;
        for (std::size_t n : sizes) {
            if (stopped()) return;
            const pl::Preset preset = scene == "gas"     ? pl::gl::scaledGasPreset(n)
                                      : scene == "fluid" ? pl::gl::scaledFluidPreset(n)
                                                         : pl::gl::scaledTunnelPreset(n);
            for (const std::string backend : {"gl", "cpu"}) {
                if (backend == "cpu" && n > cpuMax) continue;
                const bool gpuGas = backend == "gl" && scene == "gas";
                for (unsigned lanes : gpuGas ? forceLanes : std::vector<unsigned>{0}) {
                    auto choice =
                        pl::gl::createModel(scene, pl::gl::backendFromName(backend), &preset, context);
                    if (!choice.message.empty()) std::cerr << choice.message << '\n';
                    auto* gas = dynamic_cast<pl::gl::GasModelGL*>(choice.model.get());
                    if (gas) gas->setForceLanesPerDisk(lanes);
                    const auto p = pl::gl::timeModel(*choice.model, scene, backend, settings, stopped);
                    if (stopped()) return; // the point was not timed to its end: not a measurement
                    const bool gpu = backend == "gl";
                    emit(
                        {{"scene", scene},
                         {"force_lanes_per_disk", gas ? gas->forceLanesPerDisk() : 0u},
                         {"backend", backend},
                         {"particles", p.particles},
                         {"particle_steps_per_s", p.particleStepsPerSecond},
                         {"us_per_step", p.microsecondsPerStep},
                         {"dispatches_per_step", p.dispatchesPerStep},
                         {"issue_us_per_step", p.issueMicrosecondsPerStep},
                         {"repeat_us_per_step", p.repeatMicrosecondsPerStep},
                         {"settle_s", p.settleSeconds},
                         {"model_bytes_per_particle_step", gpu ? bytes : 0.0},
                         {"achieved_bandwidth_fraction", gpu ? p.particleStepsPerSecond * bytes / copy : 0.0},
                         {"goal_particle_steps_per_s", goal}});
                    points.push_back(p);
                    if (gas && profileEach) profilePasses(*gas, n);
                }
            }
        }
    };
    sweep("gas", gasSizes, kGasBytesPerParticleStep, copy / 150.0);
    sweep("fluid", fluidSizes, kFluidBytesPerParticleStep, copy / 700.0);
    sweep("tunnel", tunnelSizes, kTunnelBytesPerParticleStep, kTunnelGoal);
    // Where the time goes at the largest size, on a fresh model.
    if (selected("gas") && !gasSizes.empty() && !profileEach && !stopped()) {
        const pl::Preset preset = pl::gl::scaledGasPreset(gasSizes.back());
        pl::gl::GasModelGL model(context);
        model.reset(preset);
        for (int s = 0; s < 5; ++s) model.step();
        profilePasses(model, gasSizes.back());
    }
    std::printf("\n%s\nGL copy bandwidth %.3g B/s\n%-6s %-4s %10s %14s %10s %10s %6s\n",
                info.summary().c_str(), copy, "scene", "bk", "N", "p-steps/s", "us/step", "issue us", "disp");
    for (const auto& p : points)
        std::printf("%-6s %-4s %10zu %14.4g %10.2f %10.2f %6d\n", p.scene.c_str(), p.backend.c_str(),
                    p.particles, p.particleStepsPerSecond, p.microsecondsPerStep, p.issueMicrosecondsPerStep,
                    p.dispatchesPerStep);
    try {
        if (file) file->close();
    } catch (const pl::FileError& e) {
        fileFailed(e);
    }
    if (const int signal = stop.caught()) {
        std::cerr << "particlelab-bench: stopped by " << pl::StopSignals::name(signal) << "; the "
                  << points.size()
                  << (points.size() == 1 ? " point measured until then is kept\n"
                                         : " points measured until then are kept\n");
        return pl::StopSignals::exitCode(signal);
    }
    return exitCode;
}
