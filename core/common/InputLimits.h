// Bounds on what the programs read: an experiment file is a regular file of bounded size, and its JSON
// nests no deeper than a fixed depth, so a FIFO, a device, a huge file or a deeply nested text is refused
// at once with a sentence instead of blocking, exhausting memory or overflowing the stack.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace pl {

// [bytes] the largest preset file read: the biggest built-in preset is under 4 KiB.
constexpr std::size_t kMaxPresetFileBytes = std::size_t{16} << 20; // 16 MiB
// [bytes] the largest snapshot file read: about 1.7 M disks of the gas (160 bytes each) or 2.6 M molecules
// of the tunnel (100 bytes each). `run --snapshot` writes a larger one all the same, with a warning.
constexpr std::size_t kMaxSnapshotFileBytes = std::size_t{256} << 20; // 256 MiB
// The deepest nesting of arrays and objects in a preset or snapshot: theirs is 4 at most.
constexpr int kMaxJsonDepth = 64;

// The text of an experiment file (preset or snapshot) of at most maxBytes, read by readWholeFile; its
// refusals (not a regular file, too large, unreadable) come as PresetError (key ""), as a file's other
// errors do. what names the file in the message ("a preset file").
std::string readExperimentText(const std::string& path, std::size_t maxBytes, const std::string& what);

// A size in bytes as people read it: "512 bytes", "16 MiB", "1.0 GiB".
std::string byteSize(std::size_t bytes);

// Throws PresetError (key "") naming source and the depth when text nests arrays and objects deeper than
// kMaxJsonDepth. A single pass over the characters, outside strings, without recursion: it runs before
// the text is parsed, so no parser, copy or printer of the JSON ever recurses deeper.
void checkJsonDepth(std::string_view text, const std::string& source);

} // namespace pl
