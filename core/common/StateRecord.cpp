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

const std::vector<double>& StateRecord::rawArray(const std::string& key, std::size_t size) const {
    const auto it = arrays.find(key);
    if (it == arrays.end()) throw PresetError("state." + key, "the snapshot has no state." + key);
    if (size != SIZE_MAX && it->second.size() != size)
        throw PresetError("state." + key, "state." + key + " has " + std::to_string(it->second.size()) +
                                              " entries, the snapshot's particles need " +
                                              std::to_string(size));
    return it->second;
}

} // namespace pl
