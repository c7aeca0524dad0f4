// Older preset schemas, one step at a time: 1 → 2 (one vocabulary across the models) and 2 → 3 (relative
// parameters say so in their key; "seed" names only the random seed). docs/presets.md has the tables.
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
    const char* from; // the key of the older schema ("" for a key the newer schema added)
    const char* to;   // its key in the newer schema
    Conversion conversion = Conversion::Same;
};

struct ValueRename {
    const char* model;
    const char* key;  // a choice parameter (its key in the newer schema)
    const char* from; // the value the older schema wrote
    const char* to;   // the same choice in the newer schema
};

// One schema to the next. Keys and values not listed keep their name, type and value.
struct Step {
    int to; // the schema this step reaches
    std::vector<Rename> keys;
    std::vector<ValueRename> values;
};

const std::vector<Step>& steps() {
    static const std::vector<Step> table{
        {2,
         {
             {"fluid", "world_width", "box_width"},
             {"fluid", "world_height", "box_height"},
             {"fluid", "gravity", "gravity_on"}, // the switch; "gravity" is the acceleration, as in the gas
             {"fluid", "gravity_y", "gravity", Conversion::Negated},
             {"gas", "", "gravity_on"}, // added: the gas has the G switch too
             {"dsmc", "count_1", "count_a"},
             {"dsmc", "count_2", "count_b"},
             {"dsmc", "drift_1", "drift_a"},
             {"dsmc", "drift_2", "drift_b"},
             {"dsmc", "hist_bins", "histogram_bins"},
             {"dsmc", "hist_speed_max", "histogram_speed_max"},
         },
         {}},
        {3,
         {
             {"gas", "tool_speed", "tool_speed_factor"},     // × the initial rms speed
             {"gas", "piston_speed", "piston_speed_factor"}, // × the initial rms speed
             {"fluid", "tool_speed", "tool_speed_factor"},   // × √(g H)
         },
         {
             {"dsmc", "cross_section", "seed", "inverse-root"}, // σ = 1e-18 c_r^-1/2 m²
             {"tunnel", "cross_section", "seed", "inverse-root"},
             {"fluid", "kernel", "seed-3d", "3d"},
         }},
    };
    return table;
}

const Step& stepFrom(int schema) {
    return steps().at(static_cast<std::size_t>(schema - Preset::kOldestSchema));
}

const Rename* renameOf(const Step& step, const std::string& model, const std::string& from) {
    for (const Rename& r : step.keys)
        if (r.model == model && *r.from && from == r.from) return &r;
    return nullptr;
}

const ValueRename* valueRenameOf(const Step& step, const std::string& model, const std::string& key,
                                 const Json& value) {
    for (const ValueRename& r : step.values)
        if (r.model == model && key == r.key && value.is_string() && value.get<std::string>() == r.from)
            return &r;
    return nullptr;
}

// The schema after `schema` that introduced `key` as a new name (renamed to or added, not renamed from),
// or 0 when the file's schema may write it.
int newerSchemaOfKey(const std::string& model, const std::string& key, int schema) {
    for (int s = schema; s < Preset::kSchema; ++s) {
        const Step& step = stepFrom(s);
        const bool target = std::any_of(step.keys.begin(), step.keys.end(),
                                        [&](const Rename& r) { return r.model == model && key == r.to; });
        if (target && !renameOf(step, model, key)) return step.to;
    }
    return 0;
}

// The schema after `schema` that renamed a choice to `value`, or 0.
int newerSchemaOfValue(const std::string& model, const std::string& key, const Json& value, int schema) {
    for (int s = schema; s < Preset::kSchema; ++s)
        for (const ValueRename& r : stepFrom(s).values)
            if (r.model == model && key == r.key && value.is_string() && value.get<std::string>() == r.to)
                return stepFrom(s).to;
    return 0;
}

[[noreturn]] void fail(const std::string& source, const std::string& key, const std::string& message) {
    throw PresetError(key, source + ": " + message);
}

// Keys and values of a newer schema inside an older file are mistaken: the file means its own schema.
void refuseNewerNames(const std::string& model, int schema, const Json& params, const std::string& source) {
    const std::string declare = " (docs/presets.md), or declare \"schema\": ";
    const std::string mine = "this schema-" + std::to_string(schema) + " file must use its schema-" +
                             std::to_string(schema) + " name";
    for (const auto& [key, value] : params.items()) {
        const std::string where = "params." + key;
        if (const int newer = newerSchemaOfKey(model, key, schema))
            fail(source, where,
                 "'" + where + "' is a schema-" + std::to_string(newer) + " key; " + mine + declare +
                     std::to_string(newer));
        if (const int newer = newerSchemaOfValue(model, key, value, schema))
            fail(source, where,
                 "'" + where + "': " + value.dump() + " is a schema-" + std::to_string(newer) + " choice; " +
                     mine + declare + std::to_string(newer));
    }
}

// One step: params of schema step.to − 1 in the keys and values of step.to. spelledAs maps each renamed
// key to the key the file wrote, through every earlier step.
Json migrateStep(const std::string& model, const Step& step, const Json& params, const std::string& source,
                 std::map<std::string, std::string>& spelledAs) {
    Json migrated = Json::object();
    std::map<std::string, std::string> spelled;
    for (const auto& [key, value] : params.items()) {
        const auto written = spelledAs.find(key);
        const std::string asWritten = written != spelledAs.end() ? written->second : key;
        const Rename* rename = renameOf(step, model, key);
        const std::string to = rename ? rename->to : key;
        Json converted = value;
        if (rename && rename->conversion == Conversion::Negated) {
            const std::string where = "params." + asWritten;
            if (!value.is_number())
                fail(source, where, "'" + where + "' must be a number, got " + value.type_name());
            const double v = value.get<double>();
            converted = v == 0.0 ? 0.0 : -v; // no −0 in files written from it
        }
        if (const ValueRename* r = valueRenameOf(step, model, to, converted)) converted = r->to;
        migrated[to] = std::move(converted);
        if (rename || written != spelledAs.end()) spelled[to] = asWritten;
    }
    spelledAs = std::move(spelled);
    return migrated;
}

} // namespace

Json migrateParams(const std::string& model, int schema, const Json& params, const std::string& source,
                   std::map<std::string, std::string>& spelledAs) {
    if (schema >= Preset::kSchema || !params.is_object()) return params;
    refuseNewerNames(model, schema, params, source);
    Json migrated = params;
    for (int s = schema; s < Preset::kSchema; ++s)
        migrated = migrateStep(model, stepFrom(s), migrated, source, spelledAs);
    return migrated;
}

std::string renamedKeyNote(const std::string& model, const std::string& key) {
    std::string now = key;
    int since = 0;
    bool negated = false;
    for (int s = Preset::kOldestSchema; s < Preset::kSchema; ++s)
        if (const Rename* r = renameOf(stepFrom(s), model, now)) {
            now = r->to;
            since = stepFrom(s).to;
            negated = negated != (r->conversion == Conversion::Negated);
        }
    if (!since) return {};
    return "'" + key + "' is called '" + now + "' since preset schema " + std::to_string(since) +
           (negated ? ", with the sign flipped" : "") + " (docs/presets.md)";
}

std::string renamedValueNote(const std::string& model, const std::string& key, const std::string& value) {
    std::string now = value;
    int since = 0;
    for (int s = Preset::kOldestSchema; s < Preset::kSchema; ++s)
        if (const ValueRename* r = valueRenameOf(stepFrom(s), model, key, Json(now))) {
            now = r->to;
            since = stepFrom(s).to;
        }
    if (!since) return {};
    return "\"" + value + "\" is called \"" + now + "\" since preset schema " + std::to_string(since) +
           " (docs/presets.md)";
}

const RenamedPreset* renamedPreset(const std::string& name) {
    static constexpr RenamedPreset renamed[] = {
        // The wind tunnel's presets were named after the method (dsmc-*) before they took the kind's name.
        {"tunnel", "dsmc-cylinder", "tunnel-cylinder"},
        {"tunnel", "dsmc-free-molecular-cylinder", "tunnel-free-molecular-cylinder"},
        {"tunnel", "dsmc-shock-tube", "tunnel-shock-tube"},
        {"tunnel", "dsmc-couette", "tunnel-couette"},
        // The scenes of the original write-up were named "-seed", a word kept for the random seed.
        {"gas", "gas-seed", "gas-write-up"},
        {"dsmc", "dsmc-seed", "dsmc-write-up"},
        {"fluid", "fluid-seed", "fluid-write-up"},
    };
    for (const RenamedPreset& r : renamed)
        if (name == r.before) return &r;
    return nullptr;
}

} // namespace pl
