// A model's time-series columns written once: name, unit, label and how to read each from one sample of
// the model's observables. sampleSeries(), the CSV header, the CLI and the plot specs all read it.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

namespace pl {

// What a series column is, without how to read it: the registry's view of a model's table.
struct SeriesColumn {
    std::string name;  // the CSV header and the series store's key, e.g. "kinetic"
    std::string unit;  // e.g. "M·L²/T²"; empty when dimensionless or a count
    std::string label; // a short human name, e.g. "kinetic energy"
};

// The columns of a model whose sample is a Row (its observables struct, or a struct around it).
template <class Row> class SeriesTable {
public:
    struct Entry {
        SeriesColumn column;
        double (*get)(const Row& row);
    };

    SeriesTable(std::initializer_list<Entry> entries) : entries_(entries) {}

    std::vector<std::string> names() const {
        std::vector<std::string> list;
        list.reserve(entries_.size());
        for (const Entry& e : entries_) list.push_back(e.column.name);
        return list;
    }

    std::vector<SeriesColumn> columns() const {
        std::vector<SeriesColumn> list;
        list.reserve(entries_.size());
        for (const Entry& e : entries_) list.push_back(e.column);
        return list;
    }

    // One row of values in column order.
    std::vector<double> sample(const Row& row) const {
        std::vector<double> values;
        values.reserve(entries_.size());
        for (const Entry& e : entries_) values.push_back(e.get(row));
        return values;
    }

private:
    std::vector<Entry> entries_;
};

} // namespace pl
