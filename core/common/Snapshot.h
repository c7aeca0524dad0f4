// Snapshots: an experiment's preset and its model's full dynamic state in one versioned JSON file, so
// a run stopped today continues exactly where it was: bit for bit on the CPU.
//   {"snapshot_schema": 1, "preset": {… a preset …}, "state": {"scalars": {…}, "arrays": {…}}}
#pragma once

#include "Model.h"
#include "Preset.h"
#include "StateRecord.h"

#include <string>
#include <string_view>

namespace pl {

struct Snapshot {
    static constexpr int kSchema = 1;
    Preset preset; // the parameters, seed and obstacles as they are now
    StateRecord state;
};

Snapshot takeSnapshot(const Model& model);

// Whether JSON text is a snapshot rather than a plain preset (it has "snapshot_schema").
bool isSnapshotJson(std::string_view json);

std::string serializeSnapshot(const Snapshot& snapshot, const std::vector<ParamSpec>& specs);
// Parses and validates the preset part fully and the state's shape (numbers and arrays of numbers).
// Throws PresetError naming the entry, or the depth of JSON nested deeper than kMaxJsonDepth; sourceName
// prefixes messages.
Snapshot parseSnapshot(std::string_view json, const SpecLookup& specsFor, const std::string& sourceName);

// Atomic write of takeSnapshot(model); throws FileError.
void writeSnapshotFile(const std::string& path, const Model& model);
// Reads a regular file of at most kMaxSnapshotFileBytes (InputLimits.h) and parses it; throws PresetError.
Snapshot readSnapshotFile(const std::string& path, const SpecLookup& specsFor);

} // namespace pl
