// Signal handling and the streamed time series (and body forces) of the CLI's run.
#include "RunSupport.h"

#include "common/StopRequest.h"
#include "common/TimeSeries.h"

#include <algorithm>
#include <csignal>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace pl::cli {

namespace {

volatile std::sig_atomic_t caughtSignal = 0;
volatile std::sig_atomic_t settingUp = 0;

// What a signal during the set-up says; written with write(2), which a signal handler may call.
constexpr char kSetUpStoppedByInt[] =
    "particlelab-cli: stopped by SIGINT while setting up the experiment; nothing was written\n";
constexpr char kSetUpStoppedByTerm[] =
    "particlelab-cli: stopped by SIGTERM while setting up the experiment; nothing was written\n";

extern "C" void onStopSignal(int signal) {
    if (settingUp) {
        const bool interrupt = signal == SIGINT;
        [[maybe_unused]] const ssize_t written =
            ::write(2, interrupt ? kSetUpStoppedByInt : kSetUpStoppedByTerm,
                    interrupt ? sizeof kSetUpStoppedByInt - 1 : sizeof kSetUpStoppedByTerm - 1);
        ::_exit(128 + signal);
    }
    caughtSignal = signal;
    requestStop(); // a step of minutes polls it and is undone (common/StopRequest.h)
}

struct sigaction previous[2];
constexpr int kStopSignals[2] = {SIGINT, SIGTERM};

const std::vector<std::string> kSurfaceColumns{"step", "time", "drag", "lift"};
const std::vector<std::string> kForceColumns{"drag", "lift"}; // taken from the series

bool hasForceColumns(const std::vector<std::string>& columns) {
    return std::all_of(kForceColumns.begin(), kForceColumns.end(), [&](const std::string& name) {
        return std::find(columns.begin(), columns.end(), name) != columns.end();
    });
}

// Where drag and lift are in the series; throws std::invalid_argument when one is missing.
std::vector<std::size_t> forceColumnsIn(const std::vector<std::string>& seriesColumns) {
    if (!hasForceColumns(seriesColumns))
        throw std::invalid_argument("the series has no drag and lift columns");
    std::vector<std::size_t> picked;
    for (const std::string& name : kForceColumns)
        picked.push_back(
            std::size_t(std::find(seriesColumns.begin(), seriesColumns.end(), name) - seriesColumns.begin()));
    return picked;
}

} // namespace

StopSignals::StopSignals() {
    caughtSignal = 0;
    withdrawStopRequest();
    settingUp = 1;
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND; // a second signal finds the default action: it ends the process
    for (int i = 0; i < 2; ++i) sigaction(kStopSignals[i], &action, &previous[i]);
}

StopSignals::~StopSignals() {
    for (int i = 0; i < 2; ++i) sigaction(kStopSignals[i], &previous[i], nullptr);
    settingUp = 0;
}

void StopSignals::runStarts() {
    settingUp = 0;
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

std::string sampledOutputsRefusal(const Model& model, bool fieldsAsked, bool surfaceAsked) {
    const std::string option = fieldsAsked && surfaceAsked ? "--fields and --surface"
                               : fieldsAsked               ? "--fields"
                                                           : "--surface";
    const bool fieldsMissing = (fieldsAsked || surfaceAsked) && model.sampledFields() == nullptr;
    const bool forcesMissing = surfaceAsked && !hasForceColumns(model.seriesColumns());
    if (!fieldsMissing && !forcesMissing) return {};
    return option + " need" + (fieldsAsked && surfaceAsked ? "" : "s") +
           " a scene that samples fields and body forces (the wind tunnel, e.g. the tunnel-cylinder "
           "preset); a " +
           model.kind() + " scene has " + (fieldsMissing ? "no sampled fields" : "no drag and lift columns");
}

SurfaceCsv::SurfaceCsv(const std::string& path, const std::vector<std::string>& seriesColumns)
    : picked_(path.empty() ? std::vector<std::size_t>{} : forceColumnsIn(seriesColumns)),
      csv_(path, kSurfaceColumns) {}

void SurfaceCsv::append(const Model& model, const std::vector<double>& seriesRow) {
    if (picked_.empty()) return;
    csv_.append({static_cast<double>(model.stepCount()), model.time(), seriesRow.at(picked_[0]),
                 seriesRow.at(picked_[1])});
}

} // namespace pl::cli
