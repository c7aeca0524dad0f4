// Older preset schemas read with their meaning kept: per model, the keys renamed, the types changed and
// the choices renamed since, applied one schema at a time before validation (docs/presets.md, "Schema 2"
// and "Schema 3").
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace pl {

// The "params" object of a preset of schema `schema` (Preset::kOldestSchema up) for `model`, rewritten
// in the keys and types of Preset::kSchema. spelledAs receives, for each key it renamed, the key the
// file wrote, so messages name the entry as the file spells it. Throws PresetError naming the entry for a
// value whose type the migration needs and does not find, and for a key or choice the old schema did not
// have.
nlohmann::json migrateParams(const std::string& model, int schema, const nlohmann::json& params,
                             const std::string& source, std::map<std::string, std::string>& spelledAs);

// For a parameter key of `model` that an older schema wrote and the newest does not know, what it is
// called now: "'tool_speed' is called 'tool_speed_factor' since preset schema 3 (docs/presets.md)";
// "" for a key never renamed. The same for a choice value of parameter `key` (its newest key).
// Errors of the newest schema (a file, --set) add it.
std::string renamedKeyNote(const std::string& model, const std::string& key);
std::string renamedValueNote(const std::string& model, const std::string& key, const std::string& value);

// The built-in preset's new name, for a name it had before (the wind tunnel's "dsmc-cylinder" is
// "tunnel-cylinder" since the presets carry their kind's name, "gas-seed" is "gas-write-up" since "seed"
// means only the random seed); nullptr for a name never renamed.
// Preset files and snapshots that name the old preset read as the new one; the CLI and the app accept
// the old name with a notice (PresetLookup).
struct RenamedPreset {
    const char* kind;
    const char* before;
    const char* now;
};
const RenamedPreset* renamedPreset(const std::string& name);

} // namespace pl
