// Implementation of the CLI subcommands on top of the model catalog.
#include "Commands.h"
#include "OptionChecks.h"
#include "RunSupport.h"
#include "common/Snapshot.h"

#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "common/MemoryBudget.h"
#include "common/PresetMigration.h"
#include "common/StopRequest.h"
#include "common/ThreadGovernor.h"
#include "common/TimeSeries.h"
#include "gas/GasModel.h"
#include "gas/MethodSweep.h"
#include "gas/TimeReversal.h"
#include "gl/Backends.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <omp.h>
#include <sstream>
#include <unistd.h>

namespace pl::cli {

namespace {

using Clock = std::chrono::steady_clock;
constexpr long long kDefaultSteps = 1000;
constexpr long long kDefaultEvery = 100;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

// --threads N fixes the team; without it each model's steps run on the team its run measures fastest,
// up to every core (ThreadGovernor.h): a second thread never makes a run on a busy machine slower.
void setThreads(int threads) {
    if (threads > 0) {
        omp_set_num_threads(threads);
        setThreadPolicy({false, threads});
    } else {
        setThreadPolicy(adaptiveUnlessUserFixed());
    }
}

// The model on the asked backend; a backend that cannot be had is reported on stderr, not fatal. A
// snapshot file continues where it was taken, so it takes no --set or --seed (they would restart it).
std::unique_ptr<Model> prepare(const std::string& name, const std::vector<std::string>& sets,
                               std::optional<std::uint64_t> seed, const std::string& backend) {
    auto [snapshot, continues] = openExperiment(name);
    if (continues) {
        if (!sets.empty() || seed)
            throw std::invalid_argument("'" + name +
                                        "' is a snapshot: it continues as it was saved, without --set or "
                                        "--seed (change parameters in a preset instead)");
    } else {
        if (const std::string notice = presetRenameNotice(name); !notice.empty())
            std::cerr << "particlelab-cli: " << notice << '\n';
        applySets(snapshot.preset, sets);
        if (seed) snapshot.preset.seed = *seed;
    }
    gl::BackendChoice choice = gl::createModel(snapshot.preset, gl::backendFromName(backend));
    if (!choice.message.empty()) std::cerr << "particlelab-cli: " << choice.message << '\n';
    if (continues) choice.model->restoreState(snapshot.state);
    return std::move(choice.model);
}

namespace {

// Writes what makeText returns to path; nothing is formatted when no file was asked for.
template <class MakeText> void writeText(const std::string& path, MakeText makeText) {
    if (!path.empty()) writeFileAtomically(path, makeText());
}

// A snapshot larger than this machine can read back is kept all the same (nothing measured is lost, and
// a machine with more memory reads it); the warning says how much memory that takes. The memory this
// run holds is counted as free: a later `run FILE` starts without it.
void warnIfUnreadableHere(const std::string& path) {
    std::error_code error;
    const auto bytes = static_cast<std::size_t>(std::filesystem::file_size(path, error));
    const double held = residentMemoryBytes();
    if (error || bytes <= snapshotReadBound(held)) return;
    const double needed = static_cast<double>(bytes) * kSnapshotReadMemoryPerFileByte / kUsableMemoryShare;
    std::cerr << "particlelab-cli: warning: the snapshot '" << path << "' holds " << byteSize(bytes)
              << ", more than the " << byteSize(snapshotReadBound(held))
              << " that this machine can read back once the run has ended (" << snapshotBoundReason(held)
              << "); it is kept whole, and `run FILE` or the app continue it on a machine with "
              << byteSize(static_cast<std::size_t>(needed)) << " of memory available\n";
}

std::string particlesCsv(const Model& model) {
    std::ostringstream out;
    model.writeParticles(out);
    return out.str();
}

// The sampled fields over the model's current window (sampledOutputsRefusal() checked it has them).
std::string fieldsCsv(const Model& model) {
    std::ostringstream out;
    model.sampledFields()->writeFieldsCsv(out);
    return out.str();
}

class Progress {
public:
    Progress(long long total, bool enabled) : total_(total), enabled_(enabled), tty_(::isatty(2) != 0) {}
    void update(long long done) {
        if (!enabled_) return;
        const double elapsed = secondsSince(start_);
        if (elapsed < 1.0 || elapsed - lastPrint_ < (tty_ ? 0.25 : 2.0)) return;
        lastPrint_ = elapsed;
        const double rate = done / elapsed;
        const double eta = rate > 0 ? (total_ - done) / rate : 0.0;
        std::fprintf(stderr, "%sstep %lld/%lld (%.0f %%), %.0f steps/s, %.1f s left%s", tty_ ? "\r" : "",
                     done, total_, 100.0 * done / std::max(1LL, total_), rate, eta, tty_ ? "   " : "\n");
        printed_ = true;
    }
    void finish() {
        if (printed_ && tty_) std::fputc('\n', stderr);
    }

private:
    long long total_;
    bool enabled_, tty_, printed_ = false;
    Clock::time_point start_ = Clock::now();
    double lastPrint_ = 0.0;
};

} // namespace

// Applies "key=value" overrides on top of the preset's parameters (validated by the model's reset).
void applySets(Preset& preset, const std::vector<std::string>& sets) {
    const auto* specs = specsForModel(preset.model);
    for (const auto& assignment : sets) {
        const auto eq = assignment.find('=');
        if (eq == std::string::npos || eq == 0)
            throw PresetError("", "--set expects key=value, got \"" + assignment + "\"");
        const std::string key = assignment.substr(0, eq);
        const ParamSpec* spec = findSpec(*specs, key);
        if (!spec) {
            const std::string renamed = renamedKeyNote(preset.model, key);
            throw PresetError(key, "--set: unknown parameter '" + key + "' for model " + preset.model +
                                       (renamed.empty() ? "" : "; " + renamed));
        }
        ParamValue value = parseValue(*spec, assignment.substr(eq + 1));
        if (auto problem = checkValue(*spec, value); !problem.empty()) {
            if (const auto* s = std::get_if<std::string>(&value); s && spec->kind == ParamKind::Choice)
                if (const std::string renamed = renamedValueNote(preset.model, key, *s); !renamed.empty())
                    problem += "; " + renamed;
            throw PresetError(key, "--set: " + problem);
        }
        preset.params[key] = std::move(value);
    }
}

std::string histogramsCsv(const Model& model) {
    std::ostringstream out;
    out.precision(17);
    out << "histogram,bin_lo,bin_hi,count,density,theory_density\n";
    for (const auto& h : model.histograms()) {
        for (std::size_t b = 0; b < h.counts.bins(); ++b) {
            const double lo = h.counts.lo() + static_cast<double>(b) * h.counts.binWidth();
            out << h.name << ',' << lo << ',' << lo + h.counts.binWidth() << ',' << h.counts.count(b) << ','
                << h.counts.density(b) << ','
                << (h.theoryDensity ? h.theoryDensity(h.counts.binCentre(b)) : 0.0) << '\n';
        }
    }
    return out.str();
}

int listPresets() {
    for (const auto& p : builtinPresets()) {
        std::string summary = p.preset.description.substr(0, p.preset.description.find(". "));
        const ModelDescriptor& model = *findModel(p.preset.model); // a built-in preset's kind is registered
        std::cout << p.name << "\t" << p.preset.model << "\t" << summary << "\t" << model.units.name << "\n";
    }
    return kOk;
}

std::string sceneKinds() {
    std::string kinds;
    for (const ModelDescriptor& model : modelCatalog()) kinds += (kinds.empty() ? "" : ", ") + model.kind;
    return kinds;
}

std::string sceneUnits() {
    std::size_t width = 0;
    for (const ModelDescriptor& model : modelCatalog()) width = std::max(width, model.kind.size());
    constexpr std::size_t kGap = 2; // between the kind and its units, so the unit systems line up
    std::string text = "Units, per scene (of --set values and of the columns):\n";
    for (const ModelDescriptor& model : modelCatalog())
        text += "  " + model.kind + std::string(width - model.kind.size() + kGap, ' ') + model.units.name +
                ": " + model.units.summary + "\n";
    return text;
}

int listColumns(const std::string& sceneOrPreset) {
    const ModelDescriptor* model = findModel(sceneOrPreset);
    try {
        if (!model) model = findModel(loadPreset(sceneOrPreset).model);
    } catch (const PresetError& e) {
        std::cerr << "particlelab-cli: " << e.what() << "\n";
        return kBadInput;
    }
    std::cout << "name\tunit\tlabel\n";
    for (const SeriesColumn& column : model->series)
        std::cout << column.name << '\t' << column.unit << '\t' << column.label << '\n';
    return kOk;
}

namespace {

// The files a run writes, each with its option.
std::vector<NamedFile> runOutputs(const RunOptions& options) {
    return {{"--out", options.out},
            {"--histogram", options.histogram},
            {"--dump-initial", options.dumpInitial},
            {"--dump-final", options.dumpFinal},
            {"--snapshot", options.snapshot},
            {"--fields", options.fields},
            {"--surface", options.surface}};
}

// Every file a run writes is checked before it starts: a long run never ends in an unwritable path.
void checkRunOutputs(const RunOptions& options) {
    for (const NamedFile& output : runOutputs(options))
        if (!output.path.empty()) checkOutputPath(output.path);
}

void warnIfInaccurate(const Model& model) {
    if (const std::string warning = model.accuracyWarning(); !warning.empty())
        std::cerr << "particlelab-cli: warning: " << warning << "\n";
}

} // namespace

int prepareOrRefuse(const std::string& name, const std::vector<std::string>& sets,
                    std::optional<std::uint64_t> seed, const std::string& backend,
                    std::unique_ptr<Model>& model) {
    try {
        model = prepare(name, sets, seed, backend);
    } catch (const std::bad_alloc&) {
        std::cerr << "particlelab-cli: not enough memory to build this experiment; use fewer particles\n";
        return kBadInput;
    } catch (const std::exception& e) {
        std::cerr << "particlelab-cli: " << e.what() << "\n";
        return kBadInput;
    }
    return 0;
}

int runSimulation(const RunOptions& options) {
    StopSignals stop("particlelab-cli"); // a signal from here on ends the set-up at once, saying so
    setThreads(options.threads);
    std::unique_ptr<Model> model;
    if (const std::string refusal =
            sharedFileRefusal(runOutputs(options), {{"the input", experimentFile(options.preset)}});
        !refusal.empty()) {
        std::cerr << "particlelab-cli: " << refusal << "\n";
        return kBadInput;
    }
    try {
        checkRunOutputs(options);
    } catch (const FileError& e) {
        std::cerr << "particlelab-cli: " << e.what() << "\n";
        return kCannotWrite;
    }
    const auto setUpStart = Clock::now();
    if (const int refused =
            prepareOrRefuse(options.preset, options.sets, options.seed, options.backend, model))
        return refused;
    // --fields and --surface need a model that samples them; refused before anything runs or is written.
    if (const std::string refusal =
            sampledOutputsRefusal(*model, !options.fields.empty(), !options.surface.empty());
        !refusal.empty()) {
        std::cerr << "particlelab-cli: " << refusal << "\n";
        return kBadInput;
    }
    warnIfInaccurate(*model);
    // A step known to be unstable blows up within a few steps, and even its first rows are not physics.
    const std::string unstable = model->stabilityRefusal();
    if (!unstable.empty() && !options.allowUnstable) {
        std::cerr << "particlelab-cli: " << unstable << "; --allow-unstable runs it all the same\n";
        return kBadInput;
    }
    if (!unstable.empty())
        std::cerr << "particlelab-cli: warning: " << unstable
                  << "; running it all the same (--allow-unstable), its rows are not physics\n";
    stop.runStarts(); // a signal from here on stops the run after its step, keeping what it measured
    long long sampled = 0;
    try {
        writeText(options.dumpInitial, [&] { return particlesCsv(*model); });
        // A resumed snapshot runs what is left of the preset's run, so it ends where the run would have.
        const long long planned = model->plannedSteps();
        const long long left = std::max(0LL, planned - static_cast<long long>(model->stepCount()));
        if (planned > 0 && left == 0 && !options.steps)
            std::cerr << "particlelab-cli: the snapshot is at step " << model->stepCount()
                      << " and the preset's run is " << planned
                      << " steps long, so nothing is left to run (--steps N runs on)\n";
        const long long steps = options.steps.value_or(planned > 0 ? left : kDefaultSteps);
        const long long every = options.every.value_or(planned > 0 ? 1 : kDefaultEvery);
        SeriesCsv series(options.out, model->seriesColumns(),
                         unstable.empty() ? "" : unstable + "; run with --allow-unstable");
        SurfaceCsv surface(options.surface, model->seriesColumns());
        Progress progress(steps, !options.quiet);
        // The health is checked before each row is kept, so no row of an exploded state is written.
        auto sample = [&] {
            model->checkHealthNow();
            if (model->failure()) return;
            const std::vector<double> row = model->sampleSeries();
            series.append(row);
            surface.append(*model, row);
        };
        sample();
        InterruptibleStepper stepper(*model, secondsSince(setUpStart));
        for (long long s = 1; s <= steps && !model->failure() && !stop.caught(); ++s) {
            if (!stepper.step())
                break; // a signal undid the step half way: the run ends at the last whole one
            if (!model->failure() && (s % every == 0 || s == steps)) sample();
            progress.update(s);
        }
        model->checkHealthNow(); // the end of every run, sampled or not
        progress.finish();
        sampled = series.rows();
        series.close();
        surface.close();
        // Everything measured so far is kept even when the model failed or the run was stopped.
        writeText(options.histogram, [&] { return histogramsCsv(*model); });
        writeText(options.dumpFinal, [&] { return particlesCsv(*model); });
        writeText(options.fields, [&] { return fieldsCsv(*model); });
        if (!options.snapshot.empty()) {
            writeSnapshotFile(options.snapshot, *model);
            warnIfUnreadableHere(options.snapshot);
        }
    } catch (const FileError& e) {
        std::cerr << "particlelab-cli: " << e.what() << "\n";
        return kCannotWrite;
    } catch (const std::bad_alloc&) {
        std::cerr << "particlelab-cli: the run ran out of memory at step " << model->stepCount()
                  << "; the rows sampled until then are kept\n";
        return kModelFailed;
    }
    if (auto failure = model->failure()) {
        std::cerr << "particlelab-cli: the model stopped: " << failure->message() << "\n";
        return kModelFailed;
    }
    if (const int signal = stop.caught()) {
        std::cerr << "particlelab-cli: stopped by " << StopSignals::name(signal) << " at step "
                  << model->stepCount() << "; the " << sampled
                  << (sampled == 1 ? " row sampled until then is kept\n"
                                   : " rows sampled until then are kept\n");
        return StopSignals::exitCode(signal);
    }
    return kOk;
}

// Writes text to path atomically, or to standard output when path is empty.
int writeOrPrint(const std::string& path, const std::string& text) {
    if (path.empty()) {
        std::cout << text;
        return kOk;
    }
    try {
        writeFileAtomically(path, text);
    } catch (const std::exception& e) {
        std::cerr << "particlelab-cli: " << e.what() << "\n";
        return kCannotWrite;
    }
    return kOk;
}

// The sweep from a preset's gas: dt = horizon / steps, the reference Forest–Ruth at 1/8 of the finest.
gas::SweepResult sweepFromPreset(const SweepOptions& options) {
    Preset preset = loadPreset(options.from);
    applySets(preset, options.sets);
    GasModel gas; // the sweep compares the gas's integrators
    if (preset.model != gas.kind())
        throw std::invalid_argument("sweep --from needs a gas preset, not " + preset.model);
    gas.reset(preset);
    const double horizon = options.horizon > 0 ? options.horizon : 64 * std::abs(gas.parameters().dt);
    const int finest = *std::max_element(options.steps.begin(), options.steps.end());
    const gas::GasReference reference = gas::gasReference(gas, horizon, horizon / (8.0 * finest));
    return gas::sweepFromReference(reference, options.integrators, options.steps);
}

int integratorSweep(const SweepOptions& options) {
    if (const std::string refusal =
            sharedFileRefusal({{"--out", options.out}}, {{"--from", experimentFile(options.from)}});
        !refusal.empty()) {
        std::cerr << "particlelab-cli: " << refusal << "\n";
        return kBadInput;
    }
    gas::SweepResult result;
    try {
        result = options.from.empty()
                     ? gas::sweepHarmonicPair(options.integrators, options.steps, options.stiffness)
                     : sweepFromPreset(options);
    } catch (const std::exception& e) {
        std::cerr << "particlelab-cli: " << e.what() << "\n";
        return kBadInput;
    }
    std::ostringstream csv;
    csv.precision(17);
    csv << "integrator,dt,trajectory_error,energy_error,forces_per_time,seconds_per_time\n";
    for (const auto& p : result.points)
        csv << p.integrator << ',' << p.dt << ',' << p.trajectoryError << ',' << p.energyError << ','
            << p.forcesPerTime << ',' << p.secondsPerTime << '\n';
    for (const auto& o : result.orders)
        std::cerr << o.integrator << ": measured order " << o.measured << " (theory " << o.theory << ")\n";
    return writeOrPrint(options.out, csv.str());
}

int loschmidtEcho(const EchoOptions& options) {
    gas::EchoSetup setup;
    setup.disks = options.disks;
    std::ostringstream csv;
    csv.precision(17);
    csv << "steps,rms_double,rms_float,rms_integer\n";
    for (const auto& p : gas::loschmidtEcho(setup, options.steps))
        csv << p.steps << ',' << p.rmsDouble << ',' << p.rmsFloat << ',' << p.rmsInteger << '\n';
    return writeOrPrint(options.out, csv.str());
}

namespace {

// The bench's JSON line: the median of the timed repeats (at least one) and what ran them.
nlohmann::ordered_json benchLine(const BenchOptions& options, const Model& model,
                                 const std::vector<double>& seconds) {
    std::vector<double> sorted = seconds;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2];
    const auto particles = static_cast<double>(model.particleCount());
    nlohmann::ordered_json line;
    line["preset"] = options.preset;
    line["particles"] = model.particleCount();
    line["steps"] = options.steps;
    line["seconds"] = median;
    line["seconds_all"] = seconds;
    line["p_steps_per_s"] = particles * static_cast<double>(options.steps) / median;
    const ThreadPolicy policy = threadPolicy();
    line["threads"] = policy.adaptive ? policy.most : omp_get_max_threads();
    line["thread_policy"] = policy.adaptive ? "adaptive" : "fixed";
    // Adaptive: how many timed steps ran on each team size (index: threads).
    if (policy.adaptive) line["steps_at_threads"] = threadStepCounts();
    line["backend"] = model.backend();
    return line;
}

} // namespace

int benchmark(const BenchOptions& options) {
    StopSignals stop("particlelab-cli"); // a signal from here on ends the set-up at once, saying so
    setThreads(options.threads);
    std::unique_ptr<Model> model;
    try {
        model = prepare(options.preset, options.sets, std::nullopt, options.backend);
    } catch (const std::exception& e) {
        std::cerr << "particlelab-cli: " << e.what() << "\n";
        return kBadInput;
    }
    warnIfInaccurate(*model);
    stop.runStarts(); // a signal from here on ends the timing, keeping the repeats it finished
    // Warm-up: caches, page faults, the first cell-list allocation.
    for (long long s = 0; s < std::min<long long>(options.steps / 10 + 1, 200) && !stop.caught(); ++s)
        model->step();
    std::vector<double> seconds;
    resetThreadStepCounts();
    for (int r = 0; r < options.repeats && !stop.caught(); ++r) {
        const auto start = Clock::now();
        long long s = 0;
        for (; s < options.steps && !stop.caught(); ++s) model->step();
        model->finishPendingWork();
        if (s == options.steps) seconds.push_back(secondsSince(start)); // a repeat cut short times nothing
    }
    model->checkHealthNow();
    if (auto failure = model->failure()) {
        std::cerr << "particlelab-cli: the model stopped: " << failure->message() << "\n";
        return kModelFailed;
    }
    if (const int signal = stop.caught()) {
        if (!seconds.empty()) std::cout << benchLine(options, *model, seconds).dump() << std::endl;
        std::cerr << "particlelab-cli: stopped by " << StopSignals::name(signal) << "; the " << seconds.size()
                  << " of " << options.repeats << " timed repeats finished until then "
                  << (seconds.empty() ? "(none: nothing is printed)\n" : "are in the line printed\n");
        return StopSignals::exitCode(signal);
    }
    std::cout << benchLine(options, *model, seconds).dump() << std::endl;
    return kOk;
}

} // namespace pl::cli
