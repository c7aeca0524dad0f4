// A gas experiment as a self-contained LAMMPS deck: input script, data file with the exact state, and
// the experiment itself, so that the run can be read back (LammpsImport.h).
#pragma once

#include "gas/GasModel.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace pl::scaleout {

// The scene holds something LAMMPS cannot reproduce and the export refuses it; the message says what
// and what to change.
class ExportError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct DeckFile {
    std::string name; // relative to the deck's folder
    std::string content;
};

struct Deck {
    std::vector<DeckFile> files;
    std::vector<std::string> notes; // how the parts of the scene were mapped; also in the deck's header
    std::string command;            // how to run it from the deck's folder
};

struct LammpsExportOptions {
    long long steps = 1000;
    long long every = 100; // thermo output and particle dumps
};

// File names inside a deck, shared by export and import.
inline constexpr const char* kLammpsInput = "in.lammps";
inline constexpr const char* kLammpsData = "data.lammps";
inline constexpr const char* kLammpsLog = "log.lammps";
inline constexpr const char* kLammpsDump = "dump.lammpstrj";
inline constexpr const char* kExperimentFile = "particlelab.json";

// The run a deck holds when nothing else is asked: a preset's planned run with every step written (the
// series then match ours row for row), else 1000 steps written every 100.
LammpsExportOptions defaultLammpsOptions(const GasModel& gas);

// A CPU copy of an experiment in its current state, whatever backend it computes on, to export from.
// Throws ExportError when the scene is not the gas.
std::unique_ptr<GasModel> gasToExport(const Model& model);

// The deck for the gas in its current state. Throws ExportError for an integrator other than velocity
// Verlet, a negative dt, thermal walls or obstacles.
Deck lammpsDeck(const GasModel& gas, const LammpsExportOptions& options);

// Writes every file of the deck into dir (created if missing). Throws FileError.
void writeDeck(const Deck& deck, const std::string& dir);

} // namespace pl::scaleout
