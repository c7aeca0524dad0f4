// The streamed time series (and body forces) of the CLI's run.
#include "RunSupport.h"

#include "common/TimeSeries.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace pl::cli {

namespace {

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

SeriesCsv::SeriesCsv(const std::string& path, const std::vector<std::string>& columns,
                     const std::string& warning) {
    if (path.empty()) return;
    file_ = std::make_unique<StreamedFile>(path);
    std::ostringstream header;
    if (!warning.empty()) header << "# warning: " << warning << '\n';
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
