// TimeSeries storage and CSV output.
#include "TimeSeries.h"

#include <cmath>
#include <stdexcept>

namespace pl {

TimeSeries::TimeSeries(std::vector<std::string> columns) : columns_(std::move(columns)) {}

void TimeSeries::append(std::vector<double> row) {
    if (row.size() != columns_.size())
        throw std::invalid_argument("row has " + std::to_string(row.size()) + " values for " +
                                    std::to_string(columns_.size()) + " columns");
    rows_.push_back(std::move(row));
}

void TimeSeries::writeCsvHeader(std::ostream& out) const {
    for (std::size_t c = 0; c < columns_.size(); ++c) out << (c ? "," : "") << columns_[c];
    out << '\n';
}

void TimeSeries::writeCsvRow(std::ostream& out, std::size_t i) const {
    writeCsvRow(out, rows_[i]);
}

void TimeSeries::writeCsvRow(std::ostream& out, const std::vector<double>& r) {
    for (std::size_t c = 0; c < r.size(); ++c) {
        if (c) out << ',';
        if (std::isnan(r[c]))
            out << "nan";
        else
            out << r[c];
    }
    out << '\n';
}

void TimeSeries::writeCsv(std::ostream& out) const {
    const auto precision = out.precision(17);
    writeCsvHeader(out);
    for (std::size_t i = 0; i < rows_.size(); ++i) writeCsvRow(out, i);
    out.precision(precision);
}

} // namespace pl
