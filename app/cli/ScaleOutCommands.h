// The scale-out subcommands: export an experiment as a LAMMPS or SPARTA deck, read a LAMMPS run back,
// and run LAMMPS from here (docs/scale-out.md).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pl::cli {

struct ScaleOutOptions {
    std::string preset; // built-in name or preset file
    std::vector<std::string> sets;
    std::optional<std::uint64_t> seed;
    std::string dir;                // the deck's folder (export, import)
    std::optional<long long> steps; // default: the preset's run length, else 1000
    std::optional<long long> every; // default: every step of a preset with a run length, else 100
    std::string out, histogram;     // import and run-lammps: series and histogram CSV
    int np = 2;                     // run-lammps: MPI ranks
    std::string work;               // run-lammps: keep the deck and LAMMPS's output here
    bool quiet = false;
};

// Registers export (lammps, sparta), import (lammps, sparta) and run-lammps on app.
class ScaleOutCli {
public:
    explicit ScaleOutCli(CLI::App& app);
    // After parsing: the exit code of the chosen scale-out command, or nothing when none was chosen.
    std::optional<int> runChosen() const;

private:
    ScaleOutOptions options_;
    CLI::App* exportLammps_ = nullptr;
    CLI::App* exportSparta_ = nullptr;
    CLI::App* importLammps_ = nullptr;
    CLI::App* importSparta_ = nullptr;
    CLI::App* runLammps_ = nullptr;
};

int exportLammps(const ScaleOutOptions& options);
int exportSparta(const ScaleOutOptions& options);
int importLammps(const ScaleOutOptions& options);
int importSparta(const ScaleOutOptions& options);
int runLammps(const ScaleOutOptions& options);

} // namespace pl::cli
