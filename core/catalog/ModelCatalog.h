// The one place that knows every scene: the registered model kinds (one ModelDescriptor each), their
// built-in presets, and the creation of a CPU model. The GPU models are core/gl/GpuModels.cpp's table.
#pragma once

#include "ModelDescriptor.h"
#include "common/Model.h"
#include "common/Preset.h"
#include "common/Snapshot.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pl {

// The built-in kinds' registrations in menu order: RegisteredKinds.cpp, which core/CMakeLists.txt generates
// from the kind.cmake of each kind's folder (docs/architecture.md, "Adding a model kind").
std::vector<std::reference_wrapper<const ModelDescriptor>> builtInKinds();
// Every registered kind, in menu order.
const std::vector<std::reference_wrapper<const ModelDescriptor>>& modelCatalog();
// Adds a kind from outside this library after the built-in ones (the test tree's ballistic kind, which
// shows that a kind made by docs/architecture.md's checklist passes the catalog's contract), before
// anything reads the catalog on another thread. Throws std::invalid_argument for an incomplete
// descriptor or a kind already registered. The descriptor must outlive the catalog.
void registerModel(const ModelDescriptor& descriptor);
// The kind's descriptor, or nullptr for an unknown kind.
const ModelDescriptor* findModel(const std::string& kind);
// "unknown scene \"plasma\" (the scenes are gas, dsmc, fluid, tunnel)": the user's word for a kind.
std::string unknownScene(const std::string& kind);
const std::vector<ParamSpec>* specsForModel(const std::string& kind);

// A new model of this kind, reset to its defaults; nullptr for an unknown kind.
std::unique_ptr<Model> createModel(const std::string& kind);

// The particles instantiate(preset) makes, from the preset alone. Throws PresetError for an unknown
// model or a parameter its specs refuse.
std::size_t particleCount(const Preset& preset);

struct BuiltinPreset {
    std::string name;   // file stem, e.g. "gas-write-up"
    std::string folder; // the folder under resources/presets/ it was read from: its model kind
    Preset preset;
};

// Every preset under resources/presets/<kind>/, parsed (a broken built-in preset is a build defect:
// tests load all).
const std::vector<BuiltinPreset>& builtinPresets();
// The built-in presets of one kind, in file order.
std::vector<const BuiltinPreset*> builtinPresetsOf(const std::string& kind);

// A built-in preset by name (or by a name it had before: renamedPreset()), or a preset file by path.
// Throws PresetError.
Preset loadPreset(const std::string& nameOrPath);
// One sentence for a built-in preset asked for by its old name ("the preset 'dsmc-cylinder' is now called
// 'tunnel-cylinder'"); empty otherwise.
std::string presetRenameNotice(const std::string& nameOrPath);

// Validates a preset against its model's cross-field rules by resetting a scratch model. Throws PresetError.
std::unique_ptr<Model> instantiate(const Preset& preset);
// A model reset from the snapshot's preset, then given its state: it continues where the snapshot was
// taken. Throws PresetError.
std::unique_ptr<Model> instantiate(const Snapshot& snapshot);

// Whether the file at path is a snapshot (else it is read as a preset): read only as far as its top-level
// "snapshot_schema". False for a built-in name, and for what is not a regular file (reading it as a
// preset then says why).
bool isSnapshotFile(const std::string& path);

// The file that `run NAME` and the app's Open read for nameOrPath; empty for a built-in preset's name
// (or old name) and for a name that is no file.
std::string experimentFile(const std::string& nameOrPath);

// An experiment as the CLI and the app open it: a built-in preset, a preset file or a snapshot file, each
// bounded (InputLimits.h: a regular file, at most kMaxPresetFileBytes for a preset and snapshotReadBound()
// for a snapshot, the memory this machine can give its reader; JSON at most kMaxJsonDepth deep). A
// snapshot is parsed as it streams in, in one pass that also tells it from a preset; a preset is then
// read again whole. isSnapshot says the state is the snapshot's, to continue from. Throws PresetError
// with a sentence naming the file.
struct OpenedExperiment {
    Snapshot snapshot; // the preset and, when isSnapshot, its saved state
    bool isSnapshot = false;
};
OpenedExperiment openExperiment(const std::string& nameOrPath);

} // namespace pl
