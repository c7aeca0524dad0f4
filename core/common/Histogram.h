// Fixed-width histogram over [lo, hi) with under/overflow counts and density normalisation.
#pragma once

#include <cstddef>
#include <vector>

namespace pl {

class Histogram {
public:
    Histogram() = default;
    Histogram(double lo, double hi, std::size_t bins);

    void add(double value, double weight = 1.0);
    void clear();

    std::size_t bins() const { return counts_.size(); }
    double lo() const { return lo_; }
    double hi() const { return hi_; }
    double binWidth() const { return width_; }
    double binCentre(std::size_t i) const { return lo_ + (static_cast<double>(i) + 0.5) * width_; }
    double count(std::size_t i) const { return counts_[i]; }
    double underflow() const { return underflow_; }
    double overflow() const { return overflow_; }
    // Total weight including under- and overflow.
    double total() const;
    // Probability density in bin i: count / (total · width); integrates to the in-range fraction.
    double density(std::size_t i) const;

private:
    double lo_ = 0.0, hi_ = 1.0, width_ = 1.0;
    std::vector<double> counts_;
    double underflow_ = 0.0, overflow_ = 0.0;
};

} // namespace pl
