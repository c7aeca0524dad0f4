// Reading a LAMMPS run of an exported gas deck back into ParticleLab's series and histograms: the
// thermo table of log.lammps and the text dumps (id type x y vx vy), through LogAndDump.h.
#pragma once

#include "LogAndDump.h"
#include "common/TimeSeries.h"
#include "gas/GasModel.h"

#include <memory>
#include <string>

namespace pl::scaleout {

struct ImportedRun {
    TimeSeries series;               // the columns of `run` for the gas; NaN where LAMMPS gives nothing
    std::unique_ptr<GasModel> final; // the gas in the last dumped state, for histograms and dumps
    long long frames = 0;            // dump frames read
};

// Reads dir/particlelab.json, dir/log.lammps and dir/dump.lammpstrj (LammpsDeck.h).
ImportedRun importLammpsRun(const std::string& dir);

} // namespace pl::scaleout
