// Histogram binning.
#include "Histogram.h"

#include <cmath>
#include <stdexcept>

namespace pl {

Histogram::Histogram(double lo, double hi, std::size_t bins)
    : lo_(lo), hi_(hi), width_((hi - lo) / static_cast<double>(bins)), counts_(bins, 0.0) {
    if (!(hi > lo) || bins == 0) throw std::invalid_argument("histogram needs hi > lo and at least one bin");
}

void Histogram::add(double value, double weight) {
    if (std::isnan(value)) return;
    if (value < lo_) {
        underflow_ += weight;
    } else if (value >= hi_) {
        overflow_ += weight;
    } else {
        auto bin = static_cast<std::size_t>((value - lo_) / width_);
        counts_[std::min(bin, counts_.size() - 1)] += weight; // guards round-up at the top edge
    }
}

void Histogram::clear() {
    std::fill(counts_.begin(), counts_.end(), 0.0);
    underflow_ = overflow_ = 0.0;
}

double Histogram::total() const {
    double sum = underflow_ + overflow_;
    for (double c : counts_) sum += c;
    return sum;
}

double Histogram::density(std::size_t i) const {
    const double t = total();
    return t > 0 ? counts_[i] / (t * width_) : 0.0;
}

} // namespace pl
