// particlelab-bench: the GPU benchmark runner. Links core + gl only (no Qt), so it runs headless on a
// machine with nothing but a GL driver. Prints one JSON line per measurement and a table at the end.
#include "../cli/OptionChecks.h"
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "common/StopSignals.h"
#include "gl/Backends.h"
#include "gl/GasModelGL.h"
#include "gl/MachineBenchmark.h"

#include <CLI/CLI.hpp>
#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>

namespace {

// The longest a repeat or the settling may be asked to take [s], and the most repeats: an hour per point
// at most.
constexpr double kMaxTargetSeconds = 60.0;
constexpr long long kMaxRepeats = 60;

// The kinds with a benchmark scale (ModelDescriptor::benchmark), in the catalog's order.
std::vector<const pl::ModelDescriptor*> benchmarkedKinds() {
    std::vector<const pl::ModelDescriptor*> kinds;
    for (const pl::ModelDescriptor& kind : pl::modelCatalog())
        if (kind.benchmark.scaledPreset) kinds.push_back(&kind);
    return kinds;
}

// Why kind cannot be timed at n, as a model of the kind would refuse the scaled parameters (the gas: more
// disks than half the physical memory holds; the tunnel: more cells than it allows), or empty: checked for
// every point before the first one runs.
std::string pointRefusal(const pl::ModelDescriptor& kind, std::size_t n) {
    try {
        kind.create()->setParams(kind.benchmark.scaledPreset(n).params); // validates, builds nothing
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
    const std::vector<const pl::ModelDescriptor*> kinds = benchmarkedKinds();
    std::map<std::string, std::vector<std::size_t>> sizes; // each kind's --KIND option
    std::vector<std::string> scenes;
    std::size_t largestOfAll = 0;
    for (const pl::ModelDescriptor* kind : kinds) {
        sizes[kind->kind] = kind->benchmark.benchSizes;
        scenes.push_back(kind->kind);
        largestOfAll = std::max(largestOfAll, kind->benchmark.largest());
    }
    std::string sceneList;
    for (const std::string& scene : scenes) sceneList += (sceneList.empty() ? "" : ", ") + scene;
    std::size_t cpuMax = 65536;
    std::string out;
    pl::gl::BenchSettings settings;
    for (const pl::ModelDescriptor* kind : kinds)
        app.add_option("--" + kind->kind, sizes[kind->kind], kind->benchmark.sizesHelp)
            ->transform(
                wholeNumber(1, static_cast<long long>(kind->benchmark.largest()), kind->benchmark.limit));
    app.add_option(
           "--scenes", scenes,
           "Scenes to time, of " + sceneList +
               " (default all). Only the tunnel points: --scenes tunnel; e.g. --scenes tunnel --tunnel "
               "100000 1000000 10000000, or --tunnel 20000 on llvmpipe")
        ->check(CLI::IsMember(std::vector<std::string>(scenes))); // the choices, not the option being parsed
    app.add_option("--cpu-max", cpuMax, "Largest N also timed on the CPU model (0: none)")
        ->transform(wholeNumber(0, static_cast<long long>(largestOfAll), "the largest size of any scene"));
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
    for (const pl::ModelDescriptor* kind : kinds)
        if (std::find(scenes.begin(), scenes.end(), kind->kind) != scenes.end())
            for (const std::size_t n : sizes[kind->kind])
                if (const std::string refusal = pointRefusal(*kind, n); !refusal.empty()) {
                    std::cerr << "particlelab-bench: --" << kind->kind << " " << n << ": " << refusal << "\n";
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
            emit({{"scene", model.kind()},
                  {"particles", n},
                  {"pass", pass},
                  {"us_per_step", ns / kProfiledSteps / 1e3}});
        model.setProfiling(false);
    };
    auto selected = [&](const std::string& scene) {
        return std::find(scenes.begin(), scenes.end(), scene) != scenes.end();
    };
    // The kinds whose GPU model times its passes (the gas's), profiled at their largest size at the end.
    std::vector<const pl::ModelDescriptor*> profiled;
    // Times one point; a GPU gas point once for each --force-lanes value. False once a stop came.
    auto timePoint = [&](const pl::ModelDescriptor& kind, const pl::Preset& preset,
                         const std::string& backend, double goal) {
        const double bytes = kind.benchmark.gpuBytesPerParticleStep;
        for (std::size_t variant = 0;; ++variant) {
            auto choice = pl::gl::createModel(kind.kind, pl::gl::backendFromName(backend), &preset, context);
            if (!choice.message.empty()) std::cerr << choice.message << '\n';
            auto* gas = dynamic_cast<pl::gl::GasModelGL*>(choice.model.get());
            const std::vector<unsigned> lanes = gas ? forceLanes : std::vector<unsigned>{0};
            if (gas) gas->setForceLanesPerDisk(lanes[variant]);
            const auto p = pl::gl::timeModel(*choice.model, kind.kind, backend, settings, stopped);
            if (stopped()) return false; // the point was not timed to its end: not a measurement
            const bool gpu = backend == "gl";
            emit({{"scene", kind.kind},
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
            if (gas && profileEach) profilePasses(*gas, p.particles);
            if (gas && std::find(profiled.begin(), profiled.end(), &kind) == profiled.end())
                profiled.push_back(&kind);
            if (variant + 1 >= lanes.size()) return true;
        }
    };
    for (const pl::ModelDescriptor* kind : kinds) {
        if (!selected(kind->kind)) continue;
        const double goal = kind->benchmark.goalParticleStepsPerSecond > 0
                                ? kind->benchmark.goalParticleStepsPerSecond
                                : copy / kind->benchmark.goalBytesPerParticleStep;
        for (std::size_t n : sizes[kind->kind]) {
            if (stopped()) break;
            const pl::Preset preset = kind->benchmark.scaledPreset(n);
            for (const std::string backend : {"gl", "cpu"})
                if ((backend != "cpu" || n <= cpuMax) && !timePoint(*kind, preset, backend, goal)) break;
        }
    }
    // Where the time goes at the largest size, on a fresh model.
    for (const pl::ModelDescriptor* kind : profiled) {
        if (profileEach || stopped() || sizes[kind->kind].empty()) break;
        const std::size_t n = sizes[kind->kind].back();
        const pl::Preset preset = kind->benchmark.scaledPreset(n);
        auto choice = pl::gl::createModel(kind->kind, pl::gl::Backend::Gl, &preset, context);
        if (auto* gas = dynamic_cast<pl::gl::GasModelGL*>(choice.model.get())) {
            for (int s = 0; s < 5; ++s) gas->step();
            profilePasses(*gas, n);
        }
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
