// Older preset schemas read with their meaning kept: per model, the keys renamed and the types changed
// since, applied before validation (the table is docs/presets.md, "Schema 2").
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace pl {

// The "params" object of a preset of schema `schema` (Preset::kOldestSchema up) for `model`, rewritten
// in the keys and types of Preset::kSchema. spelledAs receives, for each key it renamed, the key the
// file wrote, so messages name the entry as the file spells it. Throws PresetError naming the entry for a
// value whose type the migration needs and does not find, and for a key the old schema did not have.
nlohmann::json migrateParams(const std::string& model, int schema, const nlohmann::json& params,
                             const std::string& source, std::map<std::string, std::string>& spelledAs);

// The built-in preset's new name, for a name it had before (the wind tunnel's "dsmc-cylinder" is
// "tunnel-cylinder" since the presets carry their kind's name); nullptr for a name never
// renamed.
// Preset files and snapshots that name the old preset read as the new one; the CLI and the app accept
// the old name with a notice (PresetLookup).
struct RenamedPreset {
    const char* kind;
    const char* before;
    const char* now;
};
const RenamedPreset* renamedPreset(const std::string& name);

} // namespace pl
