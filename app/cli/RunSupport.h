// What a CLI run needs to lose nothing: the stop signals end its set-up at once with a sentence and stop
// its steps between two (common/StopSignals.h), and the time series (and the wind tunnel's body forces) go
// to their files row by row as they are sampled, whole rows only.
#pragma once

#include "common/AtomicFile.h"
#include "common/Model.h"
#include "common/StopSignals.h"

#include <memory>
#include <string>
#include <vector>

namespace pl::cli {

// The time series CSV: header first, then each row as it is sampled, written through to the file at
// once, whole rows only (StreamedFile). A warning, when given, comes before the header as one comment
// line, "# warning: …" (a run the user insisted on: --allow-unstable). Without a path nothing is
// formatted or kept.
class SeriesCsv {
public:
    SeriesCsv(const std::string& path, const std::vector<std::string>& columns,
              const std::string& warning = {});
    void append(const std::vector<double>& row);
    void close();
    long long rows() const { return rows_; }

private:
    std::unique_ptr<StreamedFile> file_;
    long long rows_ = 0;
};

// Why --fields (fieldsAsked) or --surface (surfaceAsked) cannot be had from this model: it samples no
// fields, or its series has no drag and lift columns. Empty when they can; the run refuses before it
// starts otherwise (bad input).
std::string sampledOutputsRefusal(const Model& model, bool fieldsAsked, bool surfaceAsked);

// The forces on the bodies, `step,time,drag,lift` [N per m of depth], one row per sample of the series:
// the model's step and time, and the drag and lift picked from the series row; streamed like it.
// Without a path nothing is written.
class SurfaceCsv {
public:
    SurfaceCsv(const std::string& path, const std::vector<std::string>& seriesColumns);
    void append(const Model& model, const std::vector<double>& seriesRow);
    void close() { csv_.close(); }

private:
    std::vector<std::size_t> picked_; // where drag and lift are in a series row (first: the columns are
                                      // checked before the file is opened)
    SeriesCsv csv_;
};

} // namespace pl::cli
