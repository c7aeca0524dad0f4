// export lammps / sparta, import lammps / sparta and run-lammps: the deck comes from core/scaleout, LAMMPS
// runs as a child process (core/scaleout/LammpsRun.h) whose thermo lines become a progress line.
#include "ScaleOutCommands.h"

#include "Commands.h"
#include "OptionChecks.h"
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "common/Snapshot.h"
#include "scaleout/LammpsDeck.h"
#include "scaleout/LammpsImport.h"
#include "scaleout/LammpsRun.h"
#include "scaleout/SpartaDeck.h"
#include "scaleout/SpartaImport.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <unistd.h>

namespace pl::cli {

namespace {

constexpr long long kDefaultSteps = 1000;
constexpr long long kDefaultEvery = 100;

int fail(int code, const std::string& message) {
    std::cerr << "particlelab-cli: " << message << "\n";
    return code;
}

// The experiment of a built-in name, a preset file or a snapshot file (then with its saved state), with
// --set and --seed applied. Throws PresetError.
Preset loadExperiment(const ScaleOutOptions& options, std::optional<StateRecord>& state) {
    auto [snapshot, isSnapshot] = openExperiment(options.preset);
    Preset preset = std::move(snapshot.preset);
    if (isSnapshot) state = std::move(snapshot.state);
    applySets(preset, options.sets);
    if (options.seed) preset.seed = *options.seed;
    return preset;
}

// The kinds handed to peer ("lammps", "sparta"), from their registrations, as a sentence names them.
std::string kindsFor(const std::string& peer) {
    std::vector<std::string> kinds;
    for (const ModelDescriptor& kind : modelCatalog())
        if (kind.peer == peer) kinds.push_back(kind.kind);
    std::string out;
    for (std::size_t i = 0; i < kinds.size(); ++i)
        out += (i == 0 ? "" : i + 1 == kinds.size() ? " or " : ", ") + kinds[i];
    return out;
}

// The model of the experiment, at step 0 or in a snapshot's state, ready to export to peer; throws
// std::invalid_argument for a kind the peer does not take, naming the export that does.
std::unique_ptr<Model> modelFor(const ScaleOutOptions& options, const std::string& peer) {
    std::optional<StateRecord> state;
    const Preset preset = loadExperiment(options, state);
    const ModelDescriptor* kind = findModel(preset.model);
    if (!kind || kind->peer != peer)
        throw std::invalid_argument("export " + peer + " needs a " + kindsFor(peer) + " experiment, not " +
                                    preset.model +
                                    (kind && !kind->peer.empty() ? " (use export " + kind->peer + ")" : ""));
    std::unique_ptr<Model> model = kind->create();
    model->reset(preset);
    if (state) model->restoreState(*state);
    return model;
}

// Writes the deck and says what it holds; the exit code. steps receives the steps the deck runs.
int exportDeck(const ScaleOutOptions& options, const std::string& dir, bool quiet, long long& steps) {
    scaleout::Deck deck;
    try {
        const auto model = modelFor(options, "lammps");
        const auto* gas = dynamic_cast<const GasModel*>(model.get());
        if (!gas) throw std::invalid_argument("export lammps writes a deck of a GasModel only");
        scaleout::LammpsExportOptions deckOptions = scaleout::defaultLammpsOptions(*gas);
        if (options.steps) deckOptions.steps = *options.steps;
        if (options.every) deckOptions.every = *options.every;
        deck = scaleout::lammpsDeck(*gas, deckOptions);
        steps = deckOptions.steps;
    } catch (const std::exception& e) {
        return fail(kBadInput, e.what());
    }
    try {
        scaleout::writeDeck(deck, dir);
    } catch (const FileError& e) {
        return fail(kCannotWrite, e.what());
    }
    if (!quiet) {
        std::cerr << "particlelab-cli: wrote the LAMMPS deck " << dir << "/" << scaleout::kLammpsInput
                  << "\n";
        for (const auto& note : deck.notes) std::cerr << "  " << note << "\n";
        std::cerr << "  run it: cd " << dir << " && " << deck.command << "\n";
    }
    return kOk;
}

// import and run-lammps write a series and a histogram: refused (bad input) before anything is read or
// written when the two are one file or one of them is a file the command reads.
std::optional<int> refuseSharedFiles(const ScaleOutOptions& options, const std::vector<NamedFile>& inputs) {
    const std::string refusal =
        sharedFileRefusal({{"--out", options.out}, {"--histogram", options.histogram}}, inputs);
    if (refusal.empty()) return std::nullopt;
    return fail(kBadInput, refusal);
}

// The files an import reads from the deck's folder dir, with what they are.
std::vector<NamedFile> importedFiles(const std::string& dir, const char* log, const char* dump) {
    const auto in = [&dir](const char* name) { return (std::filesystem::path(dir) / name).string(); };
    return {{"the run's log", in(log)},
            {"the run's dump", in(dump)},
            {"the exported experiment", in(scaleout::kExperimentFile)}};
}

// The histogram of an imported run's last state and its series, in the files `run` would write.
template <class Imported>
int writeImportedFiles(const Imported& run, const ScaleOutOptions& options, const std::string& summary) {
    try {
        if (!options.histogram.empty()) writeFileAtomically(options.histogram, histogramsCsv(*run.final));
    } catch (const FileError& e) {
        return fail(kCannotWrite, e.what());
    }
    std::ostringstream csv;
    run.series.writeCsv(csv);
    if (!options.quiet) std::cerr << "particlelab-cli: " << summary << "\n";
    return writeOrPrint(options.out, csv.str());
}

int writeImported(const std::string& dir, const ScaleOutOptions& options) {
    scaleout::ImportedRun run;
    try {
        run = scaleout::importLammpsRun(dir);
    } catch (const std::exception& e) {
        return fail(kBadInput, e.what());
    }
    return writeImportedFiles(run, options,
                              "read " + std::to_string(run.series.rows()) + " thermo rows and " +
                                  std::to_string(run.frames) + " dump frames from " + dir);
}

} // namespace

int exportLammps(const ScaleOutOptions& options) {
    long long steps = 0;
    return exportDeck(options, options.dir, options.quiet, steps);
}

int exportSparta(const ScaleOutOptions& options) {
    scaleout::Deck deck;
    try {
        // The run's length and output: the preset's planned run written every step, else the defaults;
        // a tunnel without a planned run gets at least twice its sample_start, so the fields window
        // holds as many steps as the settling before it.
        auto deckOptions = [&options](long long planned, long long leastSteps) {
            scaleout::SpartaExportOptions chosen;
            chosen.every = options.every.value_or(planned > 0 ? 1 : kDefaultEvery);
            const long long unplanned = std::max(kDefaultSteps, leastSteps);
            chosen.steps = options.steps.value_or(
                planned > 0 ? planned : (unplanned + chosen.every - 1) / chosen.every * chosen.every);
            return chosen;
        };
        const auto model = modelFor(options, "sparta");
        if (const auto* tunnel = dynamic_cast<const TunnelModel*>(model.get()))
            deck = scaleout::spartaDeck(
                *tunnel, deckOptions(tunnel->plannedSteps(), 2 * tunnel->parameters().sampleStart));
        else if (const auto* cell = dynamic_cast<const DsmcModel*>(model.get()))
            deck = scaleout::spartaDeck(*cell, deckOptions(cell->plannedSteps(), 0));
        else
            throw std::invalid_argument("export sparta writes decks of a TunnelModel or a DsmcModel only");
    } catch (const std::exception& e) {
        return fail(kBadInput, e.what());
    }
    try {
        scaleout::writeDeck(deck, options.dir);
    } catch (const FileError& e) {
        return fail(kCannotWrite, e.what());
    }
    if (!options.quiet) {
        std::cerr << "particlelab-cli: wrote the SPARTA deck " << options.dir << "/" << scaleout::kSpartaInput
                  << "\n";
        for (const auto& note : deck.notes) std::cerr << "  " << note << "\n";
        std::cerr << "  run it: cd " << options.dir << " && " << deck.command << "\n";
    }
    return kOk;
}

int importLammps(const ScaleOutOptions& options) {
    if (const auto refused = refuseSharedFiles(
            options, importedFiles(options.dir, scaleout::kLammpsLog, scaleout::kLammpsDump)))
        return *refused;
    return writeImported(options.dir, options);
}

int importSparta(const ScaleOutOptions& options) {
    if (const auto refused = refuseSharedFiles(
            options, importedFiles(options.dir, scaleout::kSpartaLog, scaleout::kSpartaDump)))
        return *refused;
    scaleout::ImportedCell run;
    try {
        run = scaleout::importSpartaRun(options.dir);
    } catch (const std::exception& e) {
        return fail(kBadInput, e.what());
    }
    return writeImportedFiles(run, options,
                              "read " + std::to_string(run.frames) + " dumped steps from " + options.dir);
}

int runLammps(const ScaleOutOptions& options) {
    if (const auto refused = refuseSharedFiles(options, {{"the input", experimentFile(options.preset)}}))
        return *refused;
    if (const std::string missing = scaleout::missingLammpsProgram(); !missing.empty())
        return fail(kBadInput, missing + " not found on PATH: run-lammps needs LAMMPS and MPI (Debian: apt "
                                         "install lammps openmpi-bin)");
    std::string dir = options.work;
    if (dir.empty()) {
        std::string pattern = (std::filesystem::temp_directory_path() / "particlelab-lammps-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) return fail(kCannotWrite, "cannot create a temporary folder");
        dir = pattern;
    }
    long long steps = 0;
    if (const int code = exportDeck(options, dir, true, steps); code != kOk) {
        if (options.work.empty()) std::filesystem::remove_all(dir);
        return code;
    }
    const auto progress = [&options, steps](long long step) {
        if (!options.quiet) std::fprintf(stderr, "LAMMPS step %lld/%lld\n", step, steps);
    };
    const scaleout::LammpsRunResult result = scaleout::runLammps(dir, options.np, progress, {});
    if (result.status != 0) {
        std::cerr << "particlelab-cli: LAMMPS failed (exit status " << result.status << ") in " << dir
                  << "; its last output:\n"
                  << result.lastOutput;
        return kModelFailed;
    }
    const int code = writeImported(dir, options);
    if (options.work.empty()) std::filesystem::remove_all(dir);
    return code;
}

ScaleOutCli::ScaleOutCli(CLI::App& app) {
    ScaleOutOptions& o = options_;
    auto addPresetOptions = [&o](CLI::App* cmd) {
        cmd->add_option("preset", o.preset, "Built-in preset name, preset file or snapshot file")->required();
        cmd->add_option("--set", o.sets, "Override a parameter: key=value (repeatable)");
        cmd->add_option("--seed", o.seed, "Random seed (default: the preset's)")
            ->transform(wholeNumber(0, std::numeric_limits<long long>::max()));
        cmd->add_option("--steps", o.steps, "Steps to run (default: the preset's run length, else 1000)")
            ->transform(wholeNumber(0, kMaxSteps));
        cmd->add_option("--every", o.every,
                        "Output and particle dumps every K steps (default: every step of a preset with a run "
                        "length, else 100)")
            ->transform(wholeNumber(1, kMaxSteps));
    };
    auto* exportCmd =
        app.add_subcommand("export", "Write an experiment as a LAMMPS or SPARTA deck (docs/scale-out.md)");
    exportCmd->require_subcommand(1);
    exportLammps_ = exportCmd->add_subcommand(
        "lammps", "The gas as a LAMMPS deck: in.lammps, data.lammps with the exact state, particlelab.json");
    addPresetOptions(exportLammps_);
    exportLammps_->add_option("--out", o.dir, "Folder of the deck (created if missing)")
        ->required()
        ->check(fileName());
    exportLammps_->add_flag("--quiet", o.quiet, "No summary on stderr");

    exportSparta_ = exportCmd->add_subcommand(
        "sparta",
        "The DSMC cell or the wind tunnel as a SPARTA deck: in.sparta, species and VSS files, the cell's "
        "exact initial velocities or the tunnel's bodies, grid fields and body forces");
    addPresetOptions(exportSparta_);
    exportSparta_->add_option("--out", o.dir, "Folder of the deck (created if missing)")
        ->required()
        ->check(fileName());
    exportSparta_->add_flag("--quiet", o.quiet, "No summary on stderr");

    auto* importCmd = app.add_subcommand("import", "Read a LAMMPS or SPARTA run of an exported deck back");
    importCmd->require_subcommand(1);
    importLammps_ = importCmd->add_subcommand(
        "lammps",
        "log.lammps and dump.lammpstrj of an exported deck as the series and histogram CSVs of run");
    importLammps_->add_option("dir", o.dir, "The deck's folder after LAMMPS ran in it")->required();
    importLammps_->add_option("--out", o.out, "Time series CSV (default: standard output)")
        ->check(fileName());
    importLammps_->add_option("--histogram", o.histogram, "Speed histograms of the last dump")
        ->check(fileName());
    importLammps_->add_flag("--quiet", o.quiet, "No summary on stderr");

    importSparta_ = importCmd->add_subcommand(
        "sparta",
        "log.sparta and dump.sparta of an exported DSMC deck as the series and histogram CSVs of run");
    importSparta_->add_option("dir", o.dir, "The deck's folder after SPARTA ran in it")->required();
    importSparta_->add_option("--out", o.out, "Time series CSV (default: standard output)")
        ->check(fileName());
    importSparta_->add_option("--histogram", o.histogram, "Histograms of the last dump")->check(fileName());
    importSparta_->add_flag("--quiet", o.quiet, "No summary on stderr");

    runLammps_ =
        app.add_subcommand("run-lammps", "Export a gas, run it with mpirun -np N lmp, and import the result");
    addPresetOptions(runLammps_);
    runLammps_->add_option("--np", o.np, "MPI ranks (default 2)")->transform(wholeNumber(1, 4096));
    runLammps_->add_option("--out", o.out, "Time series CSV (default: standard output)")->check(fileName());
    runLammps_->add_option("--histogram", o.histogram, "Speed histograms of the last dump")
        ->check(fileName());
    runLammps_->add_option("--work", o.work, "Keep the deck and LAMMPS's output in this folder");
    runLammps_->add_flag("--quiet", o.quiet, "No progress lines");
}

std::optional<int> ScaleOutCli::runChosen() const {
    if (exportLammps_->parsed()) return exportLammps(options_);
    if (exportSparta_->parsed()) return exportSparta(options_);
    if (importLammps_->parsed()) return importLammps(options_);
    if (importSparta_->parsed()) return importSparta(options_);
    if (runLammps_->parsed()) return runLammps(options_);
    return std::nullopt;
}

} // namespace pl::cli
