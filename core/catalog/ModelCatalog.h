// The one place that knows every scene: model kinds, their parameter specs, built-in presets and the
// factory that creates a model (and, later, chooses its backend).
#pragma once

#include "common/Model.h"
#include "common/Preset.h"
#include "common/Snapshot.h"

#include <memory>
#include <string>
#include <vector>

namespace pl {

struct ModelInfo {
    std::string kind;  // "gas"
    std::string title; // "Gas (molecular dynamics)"
    const std::vector<ParamSpec>* specs;
};

const std::vector<ModelInfo>& modelCatalog();
const std::vector<ParamSpec>* specsForModel(const std::string& kind);

// A new model of this kind, reset to its defaults; nullptr for an unknown kind.
std::unique_ptr<Model> createModel(const std::string& kind);

struct BuiltinPreset {
    std::string name; // file stem, e.g. "gas-seed"
    Preset preset;
};

// Every preset under resources/presets/, parsed (a broken built-in preset is a build defect: tests load all).
const std::vector<BuiltinPreset>& builtinPresets();

// A built-in preset by name, or a preset file by path. Throws PresetError.
Preset loadPreset(const std::string& nameOrPath);

// Validates a preset against its model's cross-field rules by resetting a scratch model. Throws PresetError.
std::unique_ptr<Model> instantiate(const Preset& preset);
// A model reset from the snapshot's preset, then given its state: it continues where the snapshot was
// taken. Throws PresetError.
std::unique_ptr<Model> instantiate(const Snapshot& snapshot);

// Whether the file at path is a snapshot (else it is read as a preset). False for a built-in name.
bool isSnapshotFile(const std::string& path);

} // namespace pl
