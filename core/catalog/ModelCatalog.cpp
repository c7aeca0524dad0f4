// Model registry and built-in presets.
#include "ModelCatalog.h"

#include "common/AtomicFile.h"

#include "common/EmbeddedFiles.h"
#include "dsmc/DsmcModel.h"
#include "md/MdModel.h"
#include "pbf/PbfModel.h"

#include <filesystem>

namespace pl {

namespace {
constexpr std::string_view kPresetPrefix = "presets/";
constexpr std::string_view kPresetSuffix = ".json";
} // namespace

const std::vector<ModelInfo>& modelCatalog() {
    static const std::vector<ModelInfo> list{{"gas", "Gas (molecular dynamics)", &MdParams::describe()},
                                             {"dsmc", "Rarefied gas (DSMC)", &DsmcParams::describe()},
                                             {"fluid", "Fluid (position-based)", &PbfParams::describe()}};
    return list;
}

const std::vector<ParamSpec>* specsForModel(const std::string& kind) {
    for (const auto& m : modelCatalog())
        if (m.kind == kind) return m.specs;
    return nullptr;
}

std::unique_ptr<Model> createModel(const std::string& kind) {
    if (kind == "gas") return std::make_unique<MdModel>();
    if (kind == "dsmc") return std::make_unique<DsmcModel>();
    if (kind == "fluid") return std::make_unique<PbfModel>();
    return nullptr;
}

const std::vector<BuiltinPreset>& builtinPresets() {
    static const std::vector<BuiltinPreset> list = [] {
        std::vector<BuiltinPreset> presets;
        for (const auto& file : embeddedFiles()) {
            if (!file.path.starts_with(kPresetPrefix) || !file.path.ends_with(kPresetSuffix)) continue;
            const std::string stem = std::filesystem::path(std::string(file.path)).stem().string();
            presets.push_back({stem, parsePreset(file.text, specsForModel, std::string(file.path))});
        }
        return presets;
    }();
    return list;
}

Preset loadPreset(const std::string& nameOrPath) {
    for (const auto& p : builtinPresets())
        if (p.name == nameOrPath) return p.preset;
    if (!std::filesystem::exists(nameOrPath)) {
        std::string names;
        for (const auto& p : builtinPresets()) names += (names.empty() ? "" : ", ") + p.name;
        throw PresetError("", "'" + nameOrPath + "' is neither a built-in preset (" + names + ") nor a file");
    }
    return readPresetFile(nameOrPath, specsForModel);
}

std::unique_ptr<Model> instantiate(const Preset& preset) {
    auto model = createModel(preset.model);
    if (!model) throw PresetError("model", "unknown model \"" + preset.model + "\"");
    model->reset(preset);
    return model;
}

std::unique_ptr<Model> instantiate(const Snapshot& snapshot) {
    auto model = instantiate(snapshot.preset);
    model->restoreState(snapshot.state);
    return model;
}

bool isSnapshotFile(const std::string& path) {
    for (const auto& p : builtinPresets())
        if (p.name == path) return false;
    if (!std::filesystem::is_regular_file(path)) return false;
    try {
        return isSnapshotJson(readWholeFile(path));
    } catch (const FileError&) {
        return false; // reading it as a preset then reports why
    }
}

} // namespace pl
