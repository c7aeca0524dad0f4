// The two text formats LAMMPS and SPARTA share: the thermo/stats table of a log ("Step …" header,
// rows, "Loop time …") and the dump snapshot ("ITEM: TIMESTEP", count, box, "ITEM: ATOMS" columns).
#pragma once

#include "common/Preset.h"

#include <fstream>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace pl::scaleout {

// A log, dump or deck that cannot be read; the message names the file and the line.
class ImportError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Every thermo block of a log (several runs follow each other), under the names the code prints
// ("Step", "KinEng", "c_kT_a", "Ncoll", …). A following run's repeated first step is dropped.
struct ThermoTable {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
    int column(const std::string& name) const; // −1 when absent
};
ThermoTable readThermo(std::istream& log);

struct DumpFrame {
    long long step = 0;
    std::vector<std::string> columns;        // of "ITEM: ATOMS"
    std::vector<std::vector<double>> values; // one row per particle, in the file's order
    // The column's index; throws ImportError naming what the reader needs when it is absent.
    std::size_t column(const std::string& name, const std::string& needed) const;
};

// One snapshot after the other.
class DumpReader {
public:
    explicit DumpReader(std::istream& in) : in_(in) {}
    bool next(DumpFrame& frame); // false at the end; throws ImportError on a malformed snapshot

private:
    std::istream& in_;
    long long line_ = 0;
};

// A deck's folder after the run: the experiment export wrote (particlelab.json) for model, and an output
// file of the run. Both throw ImportError saying what is missing.
Preset readExportedExperiment(const std::string& dir, const std::string& model);
std::ifstream openRunFile(const std::string& dir, const std::string& name);

} // namespace pl::scaleout
