// A model's dynamic state as named numbers and arrays: what a snapshot keeps beyond the preset so that a
// restored model continues bit for bit. Every value is a double; integers up to 2⁵³ (ids, counters,
// indices) are exact in one, and the snapshot file prints doubles so that they read back unchanged.
#pragma once

#include "Preset.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace pl {

struct StateRecord {
    // No array entry of any model's state comes near it (positions, velocities, sums over a window);
    // above it a kinetic energy or a variance summed over the particles can overflow to infinity and
    // run on as if it were a state.
    static constexpr double kLargestArrayValue = 1e100;

    std::map<std::string, double> scalars;
    std::map<std::string, std::vector<double>> arrays;

    template <class T> void put(const std::string& key, const std::vector<T>& values) {
        arrays[key].assign(values.begin(), values.end());
    }
    void put(const std::string& key, double value) { scalars[key] = value; }

    // The scalar named key; throws PresetError ("state.key") when it is missing or not finite (a null in
    // the file reads as NaN: no state of a running model holds one).
    double scalar(const std::string& key) const;
    // A scalar that later builds added: `absent` when an older snapshot lacks it; when present, it must
    // be finite as scalar() requires.
    double scalarOr(const std::string& key, double absent) const { return has(key) ? scalar(key) : absent; }
    // A scalar that counts (steps, events): a whole number from 0 to 2⁵³, beyond which a double no longer
    // counts one by one; throws PresetError naming the key otherwise.
    std::int64_t count(const std::string& key) const;
    bool has(const std::string& key) const { return scalars.count(key) != 0 || arrays.count(key) != 0; }
    // The array named key as T, with `size` entries (any size when size is SIZE_MAX); throws PresetError
    // when it is missing, has another length, or holds a value that is not finite, beyond
    // kLargestArrayValue, or that T cannot represent exactly.
    template <class T> std::vector<T> array(const std::string& key, std::size_t size = SIZE_MAX) const {
        const std::vector<double>& values = rawArray(key, size);
        std::vector<T> out(values.size());
        for (std::size_t i = 0; i < values.size(); ++i) {
            const auto refuse = [&](const char* why) {
                throw PresetError("state." + key, "state." + key + "[" + std::to_string(i) + "] " + why);
            };
            if (!std::isfinite(values[i])) refuse("is not a finite number");
            if (!(std::abs(values[i]) <= kLargestArrayValue))
                refuse("is beyond ±1e100, where the sums of squares the observables take overflow");
            if constexpr (std::is_integral_v<T>) // a cast from outside T's range is undefined
                if (!(values[i] >= static_cast<double>(std::numeric_limits<T>::lowest()) &&
                      values[i] < static_cast<double>(std::numeric_limits<T>::max()) + 1.0))
                    refuse("is out of range for this field");
            out[i] = static_cast<T>(values[i]);
            if (static_cast<double>(out[i]) != values[i]) refuse("is not a valid value for this field");
        }
        return out;
    }

private:
    const std::vector<double>& rawArray(const std::string& key, std::size_t size) const;
};

} // namespace pl
