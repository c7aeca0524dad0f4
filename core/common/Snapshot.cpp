// Snapshot files: streamed JSON both ways (SnapshotJson.h); the preset part goes through the preset
// reader's validation.
#include "Snapshot.h"

#include "AtomicFile.h"
#include "InputLimits.h"
#include "MemoryBudget.h"
#include "SnapshotJson.h"

namespace pl {

Snapshot takeSnapshot(const Model& model) {
    return {model.toPreset(), model.saveState()};
}

bool isSnapshotJson(std::string_view json) {
    try {
        checkJsonDepth(json, "");
    } catch (const PresetError&) {
        return false; // no snapshot nests that deep: read as a preset, it is refused naming the depth
    }
    return declaresSnapshot(json);
}

std::string serializeSnapshot(const Snapshot& snapshot, const std::vector<ParamSpec>& specs) {
    std::string text;
    writeSnapshotJson(snapshot, specs, [&](std::string_view piece) { text += piece; });
    return text;
}

Snapshot parseSnapshot(std::string_view json, const SpecLookup& specsFor, const std::string& sourceName) {
    return *readSnapshotJson(json, specsFor, sourceName);
}

void writeSnapshotFile(const std::string& path, const Model& model) {
    const Snapshot snapshot = takeSnapshot(model);
    writePiecesAtomically(
        path, [&](const PieceSink& write) { writeSnapshotJson(snapshot, model.paramSpecs(), write); });
}

std::string snapshotSizeRefusal(const std::string& path, std::size_t bytes) {
    return "will not read '" + path + "': it holds " + byteSize(bytes) + ", more than the " +
           byteSize(snapshotReadBound()) +
           " that this machine can read back as a snapshot now: " + snapshotBoundReason();
}

Snapshot readSnapshotFile(const std::string& path, const SpecLookup& specsFor) {
    try {
        FileReader file(path);
        if (file.size() > snapshotReadBound()) throw PresetError("", snapshotSizeRefusal(path, file.size()));
        return *readSnapshotJson(file, specsFor);
    } catch (const FileError& e) {
        throw PresetError("", e.what());
    }
}

} // namespace pl
