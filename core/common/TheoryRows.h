// A kind's key readouts at the end of a run beside the theory they are checked against, each with its
// verdict: what the lab report prints under "Readouts against theory" and what a lesson's check reads.
// Each kind computes its own (ModelDescriptor::theoryRows, in its folder); every formula is the kind's
// core code, this file only reads series and words numbers.
#pragma once

#include "TimeSeries.h"

#include <optional>
#include <string>
#include <vector>

namespace pl {

struct TheoryRow {
    std::string name;  // what is measured: "KS distance of the speeds to Maxwell–Boltzmann"
    std::string value; // the measured value, four significant digits
    std::string unit;  // the value's unit; empty: none
    std::string note;  // the theory's value and the verdict, in words
    // The verdict as data: whether the measurement agrees with the theory (the KS distance below its
    // critical value, the front below Ritter's bound); empty where the row only compares (a ratio).
    std::optional<bool> agrees{};
};

// Reads columns of a run's series by name: NaN for a column the kind does not have or an empty series.
class SeriesColumns {
public:
    explicit SeriesColumns(const TimeSeries& series) : series_(series) {}
    double first(const std::string& name) const;
    double last(const std::string& name) const;
    // Every finite value of the column after the first sample (the state the run started from).
    std::vector<double> run(const std::string& name) const;

private:
    int index(const std::string& name) const;
    const TimeSeries& series_;
};

// Numbers as the report writes them: four significant digits ("0.4742"); a share as per cent with three
// ("1.35 %").
std::string theoryNumber(double value);
std::string theoryPercent(double share);

} // namespace pl
