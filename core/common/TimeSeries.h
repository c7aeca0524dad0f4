// A table of named columns sampled over time; feeds plots and CSV files.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace pl {

class TimeSeries {
public:
    explicit TimeSeries(std::vector<std::string> columns = {});

    const std::vector<std::string>& columns() const { return columns_; }
    std::size_t rows() const { return rows_.size(); }
    const std::vector<double>& row(std::size_t i) const { return rows_[i]; }

    // Appends one row; its length must match the column count.
    void append(std::vector<double> row);
    void clear() { rows_.clear(); }

    // CSV with a header line; NaN is written as "nan", numbers with 17 significant digits.
    void writeCsv(std::ostream& out) const;
    void writeCsvHeader(std::ostream& out) const;
    void writeCsvRow(std::ostream& out, std::size_t i) const;
    // One row as CSV in out's precision, for a writer that streams rows instead of keeping them.
    static void writeCsvRow(std::ostream& out, const std::vector<double>& row);

private:
    std::vector<std::string> columns_;
    std::vector<std::vector<double>> rows_;
};

} // namespace pl
