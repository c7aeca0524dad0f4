// StateRecord look-ups that name what is missing.
#include "StateRecord.h"

#include <cmath>

namespace pl {

double StateRecord::scalar(const std::string& key) const {
    const auto it = scalars.find(key);
    if (it == scalars.end()) throw PresetError("state." + key, "the snapshot has no state." + key);
    if (!std::isfinite(it->second))
        throw PresetError("state." + key, "state." + key + " is not a finite number");
    return it->second;
}

std::int64_t StateRecord::count(const std::string& key) const {
    const double value = scalar(key);
    if (!(value >= 0 && value <= 9007199254740992.0 && value == std::floor(value)))
        throw PresetError("state." + key, "state." + key + " must be a whole number, not negative");
    return static_cast<std::int64_t>(value);
}

const std::vector<double>& StateRecord::rawArray(const std::string& key, std::size_t size) const {
    const auto it = arrays.find(key);
    if (it == arrays.end()) throw PresetError("state." + key, "the snapshot has no state." + key);
    if (size != SIZE_MAX && it->second.size() != size)
        throw PresetError("state." + key, "state." + key + " has " + std::to_string(it->second.size()) +
                                              " entries where " + std::to_string(size) + " are needed");
    return it->second;
}

} // namespace pl
