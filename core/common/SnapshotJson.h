// The snapshot file's JSON text, streamed both ways: written piece by piece from the state's numbers
// and read by a SAX pass that fills the state's arrays directly, so neither side holds a JSON tree of
// the particles (16 bytes a number and more) nor, when reading a file, its whole text.
#pragma once

#include "AtomicFile.h"
#include "Snapshot.h"

#include <optional>
#include <string>
#include <string_view>

namespace pl {

// Calls write with the snapshot's text in pieces of about a MiB: {"preset":…,"snapshot_schema":1,
// "state":{"arrays":{…},"scalars":{…}}} and a newline, keys in that order (as the builds before wrote
// them). Numbers are the shortest text that reads back as the same double; NaN and infinities are null.
void writeSnapshotJson(const Snapshot& snapshot, const std::vector<ParamSpec>& specs, const PieceSink& write);

// Whether JSON text or a file's text declares a snapshot: its top-level object has "snapshot_schema".
// Reads only as far as that key (the first line or so of the files this program writes); a text that
// breaks off or nests deeper than kMaxJsonDepth before it declares none.
bool declaresSnapshot(std::string_view text);
bool declaresSnapshot(FileReader& file);

// The snapshot a text or a file holds, read in one pass that keeps no JSON tree of the state. When the
// text declares none (as declaresSnapshot says, read to its end), nullopt with orNothing, so it can be
// read as a preset; else a PresetError (invalid JSON, too deep, no snapshot_schema). For a snapshot,
// every refusal of parseSnapshot (Snapshot.h) comes as PresetError naming the entry, a key given twice
// in one object by its path ("state.arrays.vx"). The arrays are bounded by the memory this process can
// give as they grow (MemoryBudget.h). Messages start with source, or with the file's path.
std::optional<Snapshot> readSnapshotJson(std::string_view text, const SpecLookup& specsFor,
                                         const std::string& source, bool orNothing = false);
std::optional<Snapshot> readSnapshotJson(FileReader& file, const SpecLookup& specsFor,
                                         bool orNothing = false);

} // namespace pl
