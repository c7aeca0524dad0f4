#include "TheoryRows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pl {

double SeriesColumns::first(const std::string& name) const {
    const int c = index(name);
    return c < 0 || series_.rows() == 0 ? NAN : series_.row(0)[static_cast<std::size_t>(c)];
}

double SeriesColumns::last(const std::string& name) const {
    const int c = index(name);
    return c < 0 || series_.rows() == 0 ? NAN : series_.row(series_.rows() - 1)[static_cast<std::size_t>(c)];
}

std::vector<double> SeriesColumns::run(const std::string& name) const {
    std::vector<double> values;
    const int c = index(name);
    for (std::size_t r = 1; c >= 0 && r < series_.rows(); ++r)
        if (const double v = series_.row(r)[static_cast<std::size_t>(c)]; std::isfinite(v))
            values.push_back(v);
    return values;
}

int SeriesColumns::index(const std::string& name) const {
    const auto& columns = series_.columns();
    const auto it = std::find(columns.begin(), columns.end(), name);
    return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
}

std::string theoryNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

std::string theoryPercent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g %%", 100.0 * share);
    return text;
}

} // namespace pl
