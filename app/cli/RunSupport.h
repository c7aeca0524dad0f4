// What a CLI run needs to lose nothing: SIGINT and SIGTERM stop it between steps, and the time series
// goes to its file row by row as it is sampled.
#pragma once

#include "common/AtomicFile.h"

#include <memory>
#include <string>
#include <vector>

namespace pl::cli {

// Catches SIGINT and SIGTERM for the life of the object: the first one asks the run to stop after its
// current step; a second one of the same kind ends the process at once, as without this.
class StopSignals {
public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    int caught() const;                                      // the signal's number, 0 while none came
    static std::string name(int signal);                     // "SIGINT"
    static int exitCode(int signal) { return 128 + signal; } // the shell's convention: 130, 143
};

// The time series CSV: header first, then each row as it is sampled, written through to the file at
// once. Without a path nothing is formatted or kept.
class SeriesCsv {
public:
    SeriesCsv(const std::string& path, const std::vector<std::string>& columns);
    void append(const std::vector<double>& row);
    void close();
    long long rows() const { return rows_; }

private:
    std::unique_ptr<StreamedFile> file_;
    long long rows_ = 0;
};

} // namespace pl::cli
