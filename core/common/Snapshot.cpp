// Snapshot files through nlohmann::json; the preset part goes through the preset reader's validation.
#include "Snapshot.h"

#include "AtomicFile.h"
#include "InputLimits.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace pl {

namespace {

using Json = nlohmann::json;

// JSON has no NaN (an empty sample window, an absent species): written as null, read back as NaN.
Json number(double v) {
    return std::isfinite(v) ? Json(v) : Json(nullptr);
}

double numberOf(const Json& v, const std::string& where, const std::string& source) {
    if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (!v.is_number()) throw PresetError(where, source + ": '" + where + "' must be a number");
    return v.get<double>();
}

} // namespace

Snapshot takeSnapshot(const Model& model) {
    return {model.toPreset(), model.saveState()};
}

bool isSnapshotJson(std::string_view json) {
    try {
        checkJsonDepth(json, "");
    } catch (const PresetError&) {
        return false; // no snapshot nests that deep: read as a preset, it is refused naming the depth
    }
    const Json root = Json::parse(json.begin(), json.end(), nullptr, false);
    return root.is_object() && root.contains("snapshot_schema");
}

std::string serializeSnapshot(const Snapshot& snapshot, const std::vector<ParamSpec>& specs) {
    Json state = {{"scalars", Json::object()}, {"arrays", Json::object()}};
    for (const auto& [key, value] : snapshot.state.scalars) state["scalars"][key] = number(value);
    for (const auto& [key, values] : snapshot.state.arrays) {
        Json list = Json::array();
        for (const double v : values) list.push_back(number(v));
        state["arrays"][key] = std::move(list);
    }
    Json root;
    root["snapshot_schema"] = Snapshot::kSchema;
    root["preset"] = Json::parse(serializePreset(snapshot.preset, specs));
    root["state"] = std::move(state);
    return root.dump() + "\n"; // doubles print with enough digits to read back exactly
}

Snapshot parseSnapshot(std::string_view json, const SpecLookup& specsFor, const std::string& sourceName) {
    checkJsonDepth(json, sourceName); // before the preset part is printed and parsed again, recursively
    const Json root = Json::parse(json.begin(), json.end(), nullptr, false);
    if (root.is_discarded()) throw PresetError("", sourceName + ": not valid JSON");
    if (!root.is_object() || !root.contains("snapshot_schema"))
        throw PresetError("snapshot_schema", sourceName + ": not a snapshot (no snapshot_schema)");
    if (root["snapshot_schema"] != Snapshot::kSchema)
        throw PresetError("snapshot_schema", sourceName + ": snapshot_schema " +
                                                 root["snapshot_schema"].dump() +
                                                 " is not supported (this version reads " +
                                                 std::to_string(Snapshot::kSchema) + ")");
    if (!root.contains("preset") || !root["preset"].is_object())
        throw PresetError("preset", sourceName + ": 'preset' must be an object");
    Snapshot s;
    s.preset = parsePreset(root["preset"].dump(), specsFor, sourceName + " (preset)");
    const Json& state = root.value("state", Json());
    if (!state.is_object() || !state.contains("scalars") || !state.contains("arrays") ||
        !state["scalars"].is_object() || !state["arrays"].is_object())
        throw PresetError("state", sourceName + ": 'state' must hold the objects 'scalars' and 'arrays'");
    for (const auto& [key, value] : state["scalars"].items())
        s.state.scalars[key] = numberOf(value, "state." + key, sourceName);
    for (const auto& [key, values] : state["arrays"].items()) {
        if (!values.is_array())
            throw PresetError("state." + key, sourceName + ": 'state." + key + "' must be a list");
        std::vector<double>& out = s.state.arrays[key];
        out.reserve(values.size());
        for (const Json& v : values) out.push_back(numberOf(v, "state." + key, sourceName));
    }
    return s;
}

void writeSnapshotFile(const std::string& path, const Model& model) {
    writeFileAtomically(path, serializeSnapshot(takeSnapshot(model), model.paramSpecs()));
}

Snapshot readSnapshotFile(const std::string& path, const SpecLookup& specsFor) {
    const std::string text = readExperimentText(path, kMaxSnapshotFileBytes, "a snapshot");
    return parseSnapshot(text, specsFor, path);
}

} // namespace pl
