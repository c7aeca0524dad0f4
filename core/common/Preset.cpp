// Preset JSON reading (with full validation) and writing, through nlohmann::json.
#include "Preset.h"

#include "AtomicFile.h"
#include "InputLimits.h"
#include "PresetMigration.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

namespace pl {

namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& source, const std::string& key, const std::string& message) {
    throw PresetError(key, source + ": " + message);
}

void requireOnlyKeys(const Json& object, const std::vector<std::string>& allowed, const std::string& source,
                     const std::string& where) {
    for (const auto& [key, value] : object.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(source, where + key, "unknown key '" + where + key + "' (allowed: " + list + ")");
    }
}

// A first pass over the text that finds a key given twice in one object, which the parser would keep
// silently (the last one wins): its path, "params.dt" or "obstacles[1].x", or "" when there is none.
class DuplicateKeyFinder : public nlohmann::json_sax<Json> {
public:
    static std::string find(std::string_view text) {
        DuplicateKeyFinder finder;
        Json::sax_parse(text, &finder);
        return finder.duplicate_;
    }

    bool null() override { return element(); }
    bool boolean(bool) override { return element(); }
    bool number_integer(number_integer_t) override { return element(); }
    bool number_unsigned(number_unsigned_t) override { return element(); }
    bool number_float(number_float_t, const string_t&) override { return element(); }
    bool string(string_t&) override { return element(); }
    bool binary(binary_t&) override { return element(); }
    bool start_object(std::size_t) override {
        element();
        frames_.push_back({true, {}, {}, -1});
        return true;
    }
    bool key(string_t& key) override {
        Frame& frame = frames_.back();
        if (!frame.keys.insert(key).second) {
            const std::string parent = pathTo(frames_.size() - 1);
            duplicate_ = parent.empty() ? key : parent + "." + key;
            return false; // stops the pass
        }
        frame.key = key;
        return true;
    }
    bool end_object() override { return leave(); }
    bool start_array(std::size_t) override {
        element();
        frames_.push_back({false, {}, {}, -1});
        return true;
    }
    bool end_array() override { return leave(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        return false; // syntax errors are the real parser's to report
    }

private:
    struct Frame {
        bool object;
        std::set<std::string> keys;
        std::string key; // of the member being read (objects)
        long long index; // of the element being read (arrays)
    };
    bool element() {
        if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
        return true;
    }
    bool leave() {
        frames_.pop_back();
        return true;
    }
    std::string pathTo(std::size_t depth) const {
        std::string path;
        for (std::size_t i = 0; i < depth; ++i)
            path += frames_[i].object ? (path.empty() ? "" : ".") + frames_[i].key
                                      : "[" + std::to_string(frames_[i].index) + "]";
        return path;
    }
    std::vector<Frame> frames_;
    std::string duplicate_;
};

// "; note", or "" without one.
std::string noteAfter(const std::string& note) {
    return note.empty() ? note : "; " + note;
}

std::string jsonTypeName(const Json& v) {
    return v.type_name();
}

ParamValue toParamValue(const Json& v) {
    if (v.is_boolean()) return v.get<bool>();
    if (v.is_number()) return v.get<double>();
    if (v.is_string()) return v.get<std::string>();
    return std::string("<" + jsonTypeName(v) + ">"); // rejected by checkValue with the type in the message
}

double finiteNumber(const Json& object, const std::string& key, const std::string& source,
                    const std::string& path, double minimum) {
    const std::string where = path + "." + key;
    if (!object.contains(key)) fail(source, where, "missing '" + where + "'");
    const Json& v = object.at(key);
    if (!v.is_number()) fail(source, where, "'" + where + "' must be a number, got " + jsonTypeName(v));
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(source, where, "'" + where + "' must be finite");
    if (d < minimum) fail(source, where, "'" + where + "' must be at least " + std::to_string(minimum));
    return d;
}

Obstacle parseObstacle(const Json& j, const std::string& source, const std::string& path) {
    if (!j.is_object()) fail(source, path, "'" + path + "' must be an object, got " + jsonTypeName(j));
    if (!j.contains("shape") || !j.at("shape").is_string())
        fail(source, path + ".shape", "'" + path + ".shape' must be \"disc\" or \"box\"");
    Obstacle o;
    const std::string shape = j.at("shape").get<std::string>();
    const double anywhere = -std::numeric_limits<double>::max();
    if (shape == "disc") {
        requireOnlyKeys(j, {"shape", "x", "y", "radius"}, source, path + ".");
        o.shape = Obstacle::Shape::Disc;
        o.radius = finiteNumber(j, "radius", source, path, 0.0);
        if (o.radius <= 0) fail(source, path + ".radius", "'" + path + ".radius' must be positive");
    } else if (shape == "box") {
        requireOnlyKeys(j, {"shape", "x", "y", "width", "height"}, source, path + ".");
        o.shape = Obstacle::Shape::Box;
        o.halfWidth = 0.5 * finiteNumber(j, "width", source, path, 0.0);
        o.halfHeight = 0.5 * finiteNumber(j, "height", source, path, 0.0);
        if (o.halfWidth <= 0 || o.halfHeight <= 0)
            fail(source, path, "'" + path + "' must have positive width and height");
    } else {
        fail(source, path + ".shape",
             "'" + path + ".shape' must be \"disc\" or \"box\", got \"" + shape + "\"");
    }
    o.x = finiteNumber(j, "x", source, path, anywhere);
    o.y = finiteNumber(j, "y", source, path, anywhere);
    return o;
}

OrderedJson obstacleToJson(const Obstacle& o) {
    OrderedJson j;
    j["shape"] = shapeName(o.shape);
    j["x"] = o.x;
    j["y"] = o.y;
    if (o.shape == Obstacle::Shape::Disc) {
        j["radius"] = o.radius;
    } else {
        j["width"] = 2 * o.halfWidth;
        j["height"] = 2 * o.halfHeight;
    }
    return j;
}

OrderedJson valueToJson(const ParamSpec& spec, const ParamValue& value) {
    if (const auto* d = std::get_if<double>(&value)) {
        if (spec.kind == ParamKind::Integer) return static_cast<long long>(*d);
        return *d;
    }
    if (const auto* b = std::get_if<bool>(&value)) return *b;
    return std::get<std::string>(value);
}

} // namespace

Preset parsePreset(std::string_view text, const SpecLookup& specsFor, const std::string& source) {
    checkJsonDepth(text, source); // before anything parses, copies or prints the JSON, all recursively
    Json root;
    if (const std::string duplicate = DuplicateKeyFinder::find(text); !duplicate.empty())
        fail(source, duplicate, "duplicate key '" + duplicate + "': each key may be given only once");
    try {
        root = Json::parse(text);
    } catch (const Json::exception& e) { // syntax errors, and numbers beyond double range ("1e999")
        fail(source, "", std::string("not valid JSON: ") + e.what());
    }
    if (!root.is_object()) fail(source, "", "a preset must be a JSON object, got " + jsonTypeName(root));
    requireOnlyKeys(root, {"schema", "model", "name", "description", "seed", "params", "obstacles"}, source,
                    "");

    const std::string readable = "this version reads schemas " + std::to_string(Preset::kOldestSchema) +
                                 " to " + std::to_string(Preset::kSchema);
    if (!root.contains("schema")) fail(source, "schema", "missing 'schema' (" + readable + ")");
    const Json& schema = root.at("schema");
    if (!schema.is_number_integer()) fail(source, "schema", "'schema' must be an integer");
    const long long version = schema.get<long long>();
    if (version < Preset::kOldestSchema || version > Preset::kSchema)
        fail(source, "schema", "schema " + std::to_string(version) + " is not supported (" + readable + ")");

    Preset preset;
    if (!root.contains("model") || !root.at("model").is_string())
        fail(source, "model", "'model' must name the scene, e.g. \"gas\"");
    preset.model = root.at("model").get<std::string>();
    const std::vector<ParamSpec>* specs = specsFor(preset.model);
    if (!specs) fail(source, "model", "unknown scene \"" + preset.model + "\"");

    for (const char* key : {"name", "description"}) {
        if (!root.contains(key)) continue;
        if (!root.at(key).is_string()) fail(source, key, std::string("'") + key + "' must be a string");
        (std::string(key) == "name" ? preset.name : preset.description) = root.at(key).get<std::string>();
    }
    if (const RenamedPreset* r = renamedPreset(preset.name); r && preset.model == r->kind)
        preset.name = r->now;
    if (root.contains("seed")) {
        const Json& seed = root.at("seed");
        if (!seed.is_number_unsigned() && !(seed.is_number_integer() && seed.get<long long>() >= 0))
            fail(source, "seed", "'seed' must be a non-negative integer");
        preset.seed = seed.get<std::uint64_t>();
    }

    if (root.contains("params")) {
        const Json& params = root.at("params");
        if (!params.is_object()) fail(source, "params", "'params' must be an object of key: value");
        std::map<std::string, std::string> spelledAs; // newest key → the older key the file wrote
        const Json current =
            migrateParams(preset.model, static_cast<int>(version), params, source, spelledAs);
        for (const auto& [key, value] : current.items()) {
            const auto old = spelledAs.find(key);
            const std::string where = "params." + (old != spelledAs.end() ? old->second : key);
            const ParamSpec* spec = findSpec(*specs, key);
            if (!spec)
                fail(source, where,
                     "unknown parameter '" + where + "' for model " + preset.model + " (schema " +
                         std::to_string(version) + ")" + noteAfter(renamedKeyNote(preset.model, key)));
            ParamValue v = toParamValue(value);
            if (auto problem = checkValue(*spec, v); !problem.empty()) {
                if (const auto* s = std::get_if<std::string>(&v); s && spec->kind == ParamKind::Choice)
                    problem += noteAfter(renamedValueNote(preset.model, key, *s));
                fail(source, where,
                     old == spelledAs.end() ? problem
                                            : "'" + where + "' (schema " + std::to_string(version) +
                                                  ", now '" + key + "'): " + problem);
            }
            preset.params[key] = std::move(v);
        }
    }

    if (root.contains("obstacles")) {
        const Json& list = root.at("obstacles");
        if (!list.is_array()) fail(source, "obstacles", "'obstacles' must be an array");
        for (std::size_t i = 0; i < list.size(); ++i)
            preset.obstacles.push_back(
                parseObstacle(list[i], source, "obstacles[" + std::to_string(i) + "]"));
    }
    return preset;
}

std::string serializePreset(const Preset& preset, const std::vector<ParamSpec>& specs) {
    OrderedJson root;
    root["schema"] = Preset::kSchema;
    root["model"] = preset.model;
    root["name"] = preset.name;
    root["description"] = preset.description;
    root["seed"] = preset.seed;
    OrderedJson params = OrderedJson::object();
    for (const auto& spec : specs) {
        auto it = preset.params.find(spec.key);
        params[spec.key] = valueToJson(spec, it != preset.params.end() ? it->second : spec.defaultValue);
    }
    root["params"] = params;
    OrderedJson obstacles = OrderedJson::array();
    for (const auto& o : preset.obstacles) obstacles.push_back(obstacleToJson(o));
    root["obstacles"] = obstacles;
    return root.dump(2) + "\n";
}

Preset readPresetFile(const std::string& path, const SpecLookup& specsFor) {
    const std::string text = readExperimentText(path, kMaxPresetFileBytes, "a preset file");
    return parsePreset(text, specsFor, path);
}

void writePresetFile(const std::string& path, const Preset& preset, const std::vector<ParamSpec>& specs) {
    writeFileAtomically(path, serializePreset(preset, specs));
}

} // namespace pl
