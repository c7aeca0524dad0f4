// Schema 1 → 2 of preset files: one vocabulary across the models (docs/presets.md, "Schema 2").
#include "PresetMigration.h"

#include "Preset.h"

#include <algorithm>
#include <vector>

namespace pl {

namespace {

using Json = nlohmann::json;

enum class Conversion {
    Same,   // the value as it is, under a new key
    Negated // a number whose sign flips: the fluid's gravity_y (up positive) → gravity (down positive)
};

struct Rename {
    const char* model;
    const char* from; // the schema-1 key
    const char* to;   // the schema-2 key
    Conversion conversion = Conversion::Same;
};

// Schema 1 → 2. Keys not listed keep their name, type and value.
const std::vector<Rename>& schema1Renames() {
    static const std::vector<Rename> renames{
        {"fluid", "world_width", "box_width"},
        {"fluid", "world_height", "box_height"},
        {"fluid", "gravity", "gravity_on"}, // the switch; "gravity" is now the acceleration, as in the gas
        {"fluid", "gravity_y", "gravity", Conversion::Negated},
        {"dsmc", "count_1", "count_a"},
        {"dsmc", "count_2", "count_b"},
        {"dsmc", "drift_1", "drift_a"},
        {"dsmc", "drift_2", "drift_b"},
        {"dsmc", "hist_bins", "histogram_bins"},
        {"dsmc", "hist_speed_max", "histogram_speed_max"},
    };
    return renames;
}

// Keys schema 2 added without a schema-1 spelling: a schema-1 file giving them is mistaken.
const std::vector<Rename>& schema2Additions() {
    static const std::vector<Rename> added{{"gas", "", "gravity_on"}};
    return added;
}

// Whether `key` is new in schema 2 for `model` (it appears there but did not exist in schema 1).
bool onlyInSchema2(const std::string& model, const std::string& key) {
    bool renamedTo = false, existedBefore = false;
    for (const auto& r : schema1Renames()) {
        if (r.model != model) continue;
        renamedTo = renamedTo || key == r.to;
        existedBefore = existedBefore || key == r.from;
    }
    for (const auto& a : schema2Additions()) renamedTo = renamedTo || (a.model == model && key == a.to);
    return renamedTo && !existedBefore;
}

[[noreturn]] void fail(const std::string& source, const std::string& key, const std::string& message) {
    throw PresetError(key, source + ": " + message);
}

} // namespace

Json migrateParams(const std::string& model, int schema, const Json& params, const std::string& source,
                   std::map<std::string, std::string>& spelledAs) {
    if (schema >= Preset::kSchema || !params.is_object()) return params;
    Json migrated = Json::object();
    for (const auto& [key, value] : params.items()) {
        const std::string where = "params." + key;
        if (onlyInSchema2(model, key))
            fail(source, where,
                 "'" + where + "' is a schema-2 key; this schema-1 file must use its schema-1 name " +
                     "(docs/presets.md), or declare \"schema\": 2");
        const auto rename = std::find_if(schema1Renames().begin(), schema1Renames().end(),
                                         [&](const Rename& r) { return r.model == model && key == r.from; });
        if (rename == schema1Renames().end()) {
            migrated[key] = value;
            continue;
        }
        Json converted = value;
        if (rename->conversion == Conversion::Negated) {
            if (!value.is_number())
                fail(source, where, "'" + where + "' must be a number, got " + value.type_name());
            const double v = value.get<double>();
            converted = v == 0.0 ? 0.0 : -v; // no −0 in files written from it
        }
        migrated[rename->to] = std::move(converted);
        spelledAs[rename->to] = key;
    }
    return migrated;
}

const RenamedPreset* renamedPreset(const std::string& name) {
    // The wind tunnel's presets were named after the method (dsmc-*) before they took the kind's name.
    static constexpr RenamedPreset renamed[] = {
        {"tunnel", "dsmc-cylinder", "tunnel-cylinder"},
        {"tunnel", "dsmc-free-molecular-cylinder", "tunnel-free-molecular-cylinder"},
        {"tunnel", "dsmc-shock-tube", "tunnel-shock-tube"},
        {"tunnel", "dsmc-couette", "tunnel-couette"},
    };
    for (const RenamedPreset& r : renamed)
        if (name == r.before) return &r;
    return nullptr;
}

} // namespace pl
