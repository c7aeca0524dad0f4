// Signal handling and the streamed time series of the CLI's run.
#include "RunSupport.h"

#include "common/TimeSeries.h"

#include <csignal>
#include <sstream>

namespace pl::cli {

namespace {

volatile std::sig_atomic_t caughtSignal = 0;

extern "C" void onStopSignal(int signal) {
    caughtSignal = signal;
}

struct sigaction previous[2];
constexpr int kStopSignals[2] = {SIGINT, SIGTERM};

} // namespace

StopSignals::StopSignals() {
    caughtSignal = 0;
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND; // a second signal finds the default action: it ends the process
    for (int i = 0; i < 2; ++i) sigaction(kStopSignals[i], &action, &previous[i]);
}

StopSignals::~StopSignals() {
    for (int i = 0; i < 2; ++i) sigaction(kStopSignals[i], &previous[i], nullptr);
}

int StopSignals::caught() const {
    return caughtSignal;
}

std::string StopSignals::name(int signal) {
    switch (signal) {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
    }
    return "signal " + std::to_string(signal);
}

SeriesCsv::SeriesCsv(const std::string& path, const std::vector<std::string>& columns) {
    if (path.empty()) return;
    file_ = std::make_unique<StreamedFile>(path);
    std::ostringstream header;
    for (std::size_t c = 0; c < columns.size(); ++c) header << (c ? "," : "") << columns[c];
    header << '\n';
    file_->write(header.str());
}

void SeriesCsv::append(const std::vector<double>& row) {
    ++rows_;
    if (!file_) return;
    std::ostringstream line;
    line.precision(17);
    TimeSeries::writeCsvRow(line, row);
    file_->write(line.str());
}

void SeriesCsv::close() {
    if (file_) file_->close();
}

} // namespace pl::cli
