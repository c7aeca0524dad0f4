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

// Whether JSON text is a snapshot rather than a plain preset (its top-level object has "snapshot_schema");
// a text nested deeper than kMaxJsonDepth is none.
bool isSnapshotJson(std::string_view json);

// The file's text, whole (the file itself is written in pieces by writeSnapshotFile).
std::string serializeSnapshot(const Snapshot& snapshot, const std::vector<ParamSpec>& specs);
// Parses and validates the preset part fully and the state's shape (numbers and arrays of numbers).
// Throws PresetError naming the entry, or the depth of JSON nested deeper than kMaxJsonDepth; sourceName
// prefixes messages.
Snapshot parseSnapshot(std::string_view json, const SpecLookup& specsFor, const std::string& sourceName);

// Atomic write of takeSnapshot(model), streamed to the file a MiB at a time; throws FileError.
void writeSnapshotFile(const std::string& path, const Model& model);
// Reads a regular file of at most snapshotReadBound() bytes (MemoryBudget.h), parsing it as it streams in
// (the text is never held whole); throws PresetError.
Snapshot readSnapshotFile(const std::string& path, const SpecLookup& specsFor);
// The refusal of a snapshot file larger than snapshotReadBound(): its path, its size, the bound and why
// (the memory this machine can give now).
std::string snapshotSizeRefusal(const std::string& path, std::size_t bytes);

} // namespace pl
