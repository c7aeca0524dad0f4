// Reading a SPARTA run of an exported DSMC deck back: the stats table of log.sparta and the velocity
// dumps become the series and histograms `run` writes for the cell.
#pragma once

#include "LogAndDump.h"
#include "common/TimeSeries.h"
#include "dsmc/DsmcModel.h"

#include <memory>
#include <string>

namespace pl::scaleout {

inline constexpr const char* kSpartaLog = "log.sparta";

struct ImportedCell {
    TimeSeries series;                // one row per dumped step, the columns of `run` for DSMC
    std::unique_ptr<DsmcModel> final; // the cell in the last dumped state, for histograms
    long long frames = 0;
};

// Reads dir/particlelab.json, dir/log.sparta and dir/dump.sparta (SpartaDeck.h).
ImportedCell importSpartaRun(const std::string& dir);

} // namespace pl::scaleout
