// The registry: the registrations of every model kind (collected from the kinds' folders by the build),
// lookups and built-in presets.
#include "ModelCatalog.h"

#include "common/AtomicFile.h"
#include "common/EmbeddedFiles.h"
#include "common/InputLimits.h"
#include "common/MemoryBudget.h"
#include "common/PresetMigration.h"
#include "common/SnapshotJson.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace pl {

namespace {
// What every registration must declare; throws std::invalid_argument naming the kind otherwise.
void requireComplete(const ModelDescriptor& descriptor) {
    if (descriptor.kind.empty() || descriptor.units.name.empty() || descriptor.units.time.empty() ||
        !(descriptor.watchableRate > 0) || !descriptor.specs || !descriptor.create ||
        !descriptor.particleCount)
        throw std::invalid_argument(
            "the model kind '" + descriptor.kind +
            "' needs a name, its units and unit of time, a watchable rate, parameter specs, a creator and a "
            "particle count");
    if (descriptor.stateArrays.x.empty() != descriptor.stateArrays.y.empty() ||
        (!descriptor.stateArrays.id.empty() && descriptor.stateArrays.x.empty()))
        throw std::invalid_argument("the model kind '" + descriptor.kind +
                                    "' names both position arrays or none, and an identity only beside them");
}

// The built-in kinds (each folder of core/ with a kind.cmake; RegisteredKinds.cpp is generated from
// them), then those registered from outside.
std::vector<std::reference_wrapper<const ModelDescriptor>>& registeredKinds() {
    static std::vector<std::reference_wrapper<const ModelDescriptor>> list = [] {
        std::vector<std::reference_wrapper<const ModelDescriptor>> kinds = builtInKinds();
        for (const ModelDescriptor& d : kinds) requireComplete(d);
        return kinds;
    }();
    return list;
}
} // namespace

const std::vector<std::reference_wrapper<const ModelDescriptor>>& modelCatalog() {
    return registeredKinds();
}

void registerModel(const ModelDescriptor& descriptor) {
    requireComplete(descriptor);
    if (findModel(descriptor.kind))
        throw std::invalid_argument("the model kind '" + descriptor.kind + "' is registered already");
    registeredKinds().push_back(descriptor);
}

namespace {
constexpr std::string_view kPresetPrefix = "presets/";
constexpr std::string_view kPresetSuffix = ".json";
} // namespace

const ModelDescriptor* findModel(const std::string& kind) {
    for (const ModelDescriptor& m : modelCatalog())
        if (m.kind == kind) return &m;
    return nullptr;
}

std::string unknownScene(const std::string& kind) {
    std::string scenes;
    for (const ModelDescriptor& m : modelCatalog()) scenes += (scenes.empty() ? "" : ", ") + m.kind;
    return "unknown scene \"" + kind + "\" (the scenes are " + scenes + ")";
}

const std::vector<ParamSpec>* specsForModel(const std::string& kind) {
    const ModelDescriptor* m = findModel(kind);
    return m ? m->specs : nullptr;
}

std::unique_ptr<Model> createModel(const std::string& kind) {
    const ModelDescriptor* m = findModel(kind);
    return m ? m->create() : nullptr;
}

std::size_t particleCount(const Preset& preset) {
    const ModelDescriptor* m = findModel(preset.model);
    if (!m) throw PresetError("model", unknownScene(preset.model));
    try {
        return m->particleCount(preset);
    } catch (const ParamError& e) {
        throw PresetError("params." + e.key(), e.what());
    }
}

Preset defaultPreset(const ModelDescriptor& descriptor) {
    Preset preset;
    preset.model = descriptor.kind;
    for (const ParamSpec& spec : *descriptor.specs) preset.params[spec.key] = spec.defaultValue;
    return preset;
}

NumberFormat readoutFormat(const PresentReadout& readout, double value) {
    constexpr double kPlainBelow = 1e6, kPlainFrom = 1e-4;
    const double size = std::abs(value);
    if (readout.format == 'f' || !std::isfinite(value) || size == 0)
        return {readout.format, readout.precision};
    if (size >= kPlainBelow || size < kPlainFrom) return {'g', readout.precision};
    // 'g' writes an exponent from 10^precision on: there the whole number says as much, without one.
    if (size >= std::pow(10.0, readout.precision)) return {'f', 0};
    return {'g', readout.precision};
}

ParamValues fewerParticles(const ParamValues& values, double share, const std::vector<std::string>& counts) {
    ParamValues lighter;
    for (const std::string& key : counts)
        if (const auto it = values.find(key); it != values.end())
            if (const double* count = std::get_if<double>(&it->second); count && *count > 0)
                lighter[key] = std::max(1.0, std::floor(*count * share));
    return lighter;
}

const std::vector<BuiltinPreset>& builtinPresets() {
    static const std::vector<BuiltinPreset> list = [] {
        std::vector<BuiltinPreset> presets;
        for (const auto& file : embeddedFiles()) {
            if (!file.path.starts_with(kPresetPrefix) || !file.path.ends_with(kPresetSuffix)) continue;
            const std::filesystem::path path(std::string(file.path));
            presets.push_back({path.stem().string(), path.parent_path().filename().string(),
                               parsePreset(file.text, specsForModel, std::string(file.path))});
        }
        return presets;
    }();
    return list;
}

std::vector<const BuiltinPreset*> builtinPresetsOf(const std::string& kind) {
    std::vector<const BuiltinPreset*> list;
    for (const BuiltinPreset& p : builtinPresets())
        if (p.folder == kind) list.push_back(&p);
    return list;
}

namespace {
// The built-in preset a name means: its own, or the one an old name now has (a file of that name wins).
const BuiltinPreset* builtinNamed(const std::string& nameOrPath) {
    for (const auto& p : builtinPresets())
        if (p.name == nameOrPath) return &p;
    const RenamedPreset* renamed = renamedPreset(nameOrPath);
    if (!renamed || std::filesystem::exists(nameOrPath)) return nullptr;
    for (const auto& p : builtinPresets())
        if (p.name == renamed->now) return &p;
    return nullptr;
}
} // namespace

std::string presetRenameNotice(const std::string& nameOrPath) {
    const RenamedPreset* renamed = renamedPreset(nameOrPath);
    if (!renamed || builtinNamed(nameOrPath) == nullptr || builtinNamed(nameOrPath)->name == nameOrPath)
        return {};
    return "the preset '" + nameOrPath + "' is now called '" + renamed->now + "'";
}

Preset loadPreset(const std::string& nameOrPath) {
    if (const BuiltinPreset* builtin = builtinNamed(nameOrPath)) return builtin->preset;
    if (!std::filesystem::exists(nameOrPath)) {
        std::string names;
        for (const auto& p : builtinPresets()) names += (names.empty() ? "" : ", ") + p.name;
        throw PresetError("", "'" + nameOrPath + "' is neither a built-in preset (" + names + ") nor a file");
    }
    return readPresetFile(nameOrPath, specsForModel);
}

std::unique_ptr<Model> instantiate(const Preset& preset) {
    auto model = createModel(preset.model);
    if (!model) throw PresetError("model", unknownScene(preset.model));
    model->reset(preset);
    return model;
}

std::unique_ptr<Model> instantiate(const Snapshot& snapshot) {
    auto model = instantiate(snapshot.preset);
    model->restoreState(snapshot.state);
    return model;
}

bool isSnapshotFile(const std::string& path) {
    if (experimentFile(path).empty()) return false;
    try {
        FileReader file(path);
        return declaresSnapshot(file);
    } catch (const FileError&) {
        return false; // reading it as a preset then reports why
    }
}

std::string experimentFile(const std::string& nameOrPath) {
    std::error_code error;
    if (builtinNamed(nameOrPath) || !std::filesystem::exists(nameOrPath, error)) return {};
    return nameOrPath;
}

OpenedExperiment openExperiment(const std::string& nameOrPath) {
    const std::string path = experimentFile(nameOrPath);
    if (path.empty()) return {{loadPreset(nameOrPath), {}}, false}; // a built-in one, or why there is none
    std::size_t size = 0;
    try {
        FileReader file(path);
        size = file.size();
        if (size > std::max(snapshotReadBound(), kMaxPresetFileBytes))
            throw PresetError("", snapshotSizeRefusal(path, size)); // at once, from its size
        if (std::optional<Snapshot> snapshot = readSnapshotJson(file, specsForModel, true))
            return {std::move(*snapshot), true};
    } catch (const FileError& e) {
        throw PresetError("", e.what());
    }
    if (size > kMaxPresetFileBytes) // no snapshot, and too large for a preset
        throw PresetError("", "will not read '" + path + "': it holds " + byteSize(size) +
                                  ", more than the " + byteSize(kMaxPresetFileBytes) +
                                  " that a preset file may hold");
    return {{readPresetFile(path, specsForModel), {}}, false};
}

} // namespace pl
