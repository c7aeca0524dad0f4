// The CLI's subcommands: list, run, bench. Each returns the process exit code.
#pragma once

#include "common/Model.h"
#include "common/Preset.h"
#include "gas/GasIntegratorTable.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pl::cli {

enum ExitCode : int {
    kOk = 0,
    kBadInput = 2,    // unknown preset, bad file, invalid --set
    kModelFailed = 3, // the model blew up; its message is printed
    kCannotWrite = 4, // an output file could not be written
};

struct RunOptions {
    std::string preset;            // built-in name or file path
    std::vector<std::string> sets; // "key=value"
    std::optional<std::uint64_t> seed;
    int threads = 0;                // 0: OpenMP's default
    std::optional<long long> steps; // default: the preset's run length (DSMC), else 1000
    std::optional<long long> every; // sample observables every this many steps; default: 1 for a run with
                                    // a planned length (as the DSMC write-up prints every step), else 100
    std::string out, histogram, dumpInitial, dumpFinal;
    std::string fields;           // sampled fields at the end (a scene with SampledFields: the wind tunnel)
    std::string surface;          // step,time,drag,lift per sample (the wind tunnel's body forces)
    std::string snapshot;         // the full state at the end (also when stopped), to continue from
    std::string backend = "auto"; // cpu, gl or auto
    bool quiet = false;
    bool allowUnstable = false; // run a step known to be unstable (Model::stabilityRefusal) all the same
};

struct BenchOptions {
    std::string preset;
    std::vector<std::string> sets;
    int threads = 0;
    long long steps = 2000;
    int repeats = 3;
    std::string backend = "auto";
};

struct EchoOptions {
    int disks = 64;
    std::vector<long long> steps{10, 30, 100, 300, 1000, 3000, 10000};
    std::string out; // CSV; standard output when empty
};

struct SweepOptions {
    std::vector<std::string> integrators = gasIntegratorNamesByOrder();
    std::vector<int> steps{16, 32, 64, 128, 256}; // steps over the horizon
    double stiffness = 1000.0;
    std::string from;              // a gas preset: sweep from its state against a Forest–Ruth reference
    std::vector<std::string> sets; // overrides of that preset
    double horizon = 0;            // simulated time of each run from a preset; 0: 64 of its steps
    std::string out;               // CSV; standard output when empty
};

// Fixes the OpenMP team at threads, or (0) lets each run measure the fastest team.
void setThreads(int threads);
// The experiment a command runs: a built-in preset, a preset file with "key=value" overrides and a seed, or
// a snapshot that continues as saved (it takes neither). backend: cpu, gl or auto; a backend that cannot be
// had is said on stderr. Throws what reading or building throws (bad input).
std::unique_ptr<Model> prepare(const std::string& name, const std::vector<std::string>& sets,
                               std::optional<std::uint64_t> seed, const std::string& backend);
// prepare(), its refusal said on stderr: 0 with `model` built, or the exit code (kBadInput).
int prepareOrRefuse(const std::string& name, const std::vector<std::string>& sets,
                    std::optional<std::uint64_t> seed, const std::string& backend,
                    std::unique_ptr<Model>& model);

// Writes text to path atomically (kCannotWrite and a message when it cannot), or to standard output.
int writeOrPrint(const std::string& path, const std::string& text);

// Applies "key=value" overrides on top of the preset's parameters. Throws PresetError.
void applySets(Preset& preset, const std::vector<std::string>& sets);
// The model's histograms as CSV: histogram,bin_lo,bin_hi,count,density,theory_density.
std::string histogramsCsv(const Model& model);

// One line per built-in preset: name<TAB>kind<TAB>first sentence of its description<TAB>its kind's units.
int listPresets();
// The registered scene kinds, comma-separated ("gas, dsmc, fluid").
std::string sceneKinds();
// The unit system each kind declares, a line per kind ("  gas     reduced (L, T, M): length L, …"), under
// a heading: the footer of the help of the commands that take parameters or print columns.
std::string sceneUnits();
// The series columns of a scene kind, or of a preset's kind, one "name<TAB>unit<TAB>label" line each.
int listColumns(const std::string& sceneOrPreset);
int runSimulation(const RunOptions& options);
int benchmark(const BenchOptions& options);
// The Loschmidt echo of a periodic gas in double, float and bit-reversible integer arithmetic.
int loschmidtEcho(const EchoOptions& options);
// Accuracy against cost of the gas's integrators on the harmonic pair, with measured orders.
int integratorSweep(const SweepOptions& options);

} // namespace pl::cli
