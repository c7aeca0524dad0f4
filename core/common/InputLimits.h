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
// A snapshot has no fixed bound: it may be as large as the memory this machine can give its reader
// (snapshotReadBound(), MemoryBudget.h), the rule that lets the run that writes it start.
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
// The sentence of that refusal, for readers that count the depth as they stream: "source: the JSON nests
// … (line 12); …".
std::string jsonDepthRefusal(const std::string& source, long long line);

} // namespace pl
