// Experiment presets: versioned JSON files holding a model's parameters, seed and obstacles.
#pragma once

#include "Obstacle.h"
#include "ParamSpec.h"

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pl {

struct Preset {
    static constexpr int kSchema = 3;       // written; see docs/presets.md for what changed
    static constexpr int kOldestSchema = 1; // read and migrated to kSchema with the same meaning
    std::string model;                      // "gas", later "dsmc", "fluid"
    std::string name;
    std::string description;
    std::uint64_t seed = 1;
    ParamValues params; // only keys of the model's ParamSpec list; absent keys take their defaults
    std::vector<Obstacle> obstacles;
};

// A preset that cannot be used. key() names the offending entry ("params.dt", "obstacles[1].radius").
class PresetError : public std::runtime_error {
public:
    PresetError(std::string key, const std::string& message)
        : std::runtime_error(message), key_(std::move(key)) {}
    const std::string& key() const { return key_; }

private:
    std::string key_;
};

// Returns the parameter specs of a model name, or nullptr for an unknown model.
using SpecLookup = std::function<const std::vector<ParamSpec>*(const std::string& model)>;

// Parses and validates preset JSON: syntax, schema version, model, every key, type, range and finiteness.
// A file of an older schema (kOldestSchema up) is migrated to kSchema first: renamed keys and changed
// types keep their meaning (PresetMigration.h), and errors name the entry as the file spells it.
// Throws PresetError with a message naming the entry and what is allowed, or the depth of JSON nested
// deeper than kMaxJsonDepth (InputLimits.h). sourceName prefixes messages.
Preset parsePreset(std::string_view json, const SpecLookup& specsFor,
                   const std::string& sourceName = "preset");

// Serialises as schema kSchema with parameters in spec order (every parameter written, defaults included).
std::string serializePreset(const Preset& preset, const std::vector<ParamSpec>& specs);

// Reads a regular file of at most kMaxPresetFileBytes (InputLimits.h) and parses it; throws PresetError.
Preset readPresetFile(const std::string& path, const SpecLookup& specsFor);
void writePresetFile(const std::string& path, const Preset& preset, const std::vector<ParamSpec>& specs);

} // namespace pl
