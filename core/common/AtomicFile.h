// Writing files so that a crash or a full disk never leaves a half-written file behind, and never
// replaces what is not a regular file; reading only regular files, of a bounded size.
#pragma once

#include "InputLimits.h"

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pl {

class FileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Where a write to path lands: path itself, or the file its symbolic link (chain) points to, since a
// write goes through a link to its target and never replaces the link. Throws FileError when that
// target exists and is not a regular file (a directory, FIFO, device or socket is never replaced).
std::string outputTarget(const std::string& path);

// Checks before a long run that path can be written: its target is absent or a regular file it may
// write, and a file can be created beside it (one is created and removed). Temporary files of earlier
// writes to it that a killed process left are removed first (as writeFileAtomically does). Throws
// FileError naming the path and why.
void checkOutputPath(const std::string& path);

// Whether two paths name one file once written: the same file through symbolic and hard links, or for a
// file that is not there yet, the same name in the same folder (after links). Paths that cannot be
// resolved (a missing folder) are compared as written, made absolute.
bool sameFile(const std::string& a, const std::string& b);

// Writes content to a temporary file beside the target (outputTarget), flushes it to disk, renames it
// over the target and flushes the folder, so that the file is the old one or the new one, whole, even
// after a crash. The target keeps its permissions (a new file gets 0666 less the umask). The temporary
// file (target.tmp-PID-XXXXXX) is removed on every failure, and temporary files of earlier writes to the
// same path whose process is gone are removed first, whatever their age. Throws FileError naming the
// path and the system's reason; the old file stays intact on failure.
void writeFileAtomically(const std::string& path, std::string_view content);
// The same for content made piece by piece, so it is never held whole: produce calls its argument once
// for each piece, in order. Whatever produce throws removes the temporary file and passes on.
using PieceSink = std::function<void(std::string_view)>;
void writePiecesAtomically(const std::string& path, const std::function<void(const PieceSink&)>& produce);

// Reads a whole regular file of at most maxBytes [bytes]. Throws FileError naming the path and why: the
// system's reason, or at once, before a byte is read, for what is not a regular file (a FIFO, a device, a
// directory: nothing blocks) and for a file larger than maxBytes ("… more than the 16 MiB that a preset
// file may hold"; what names the kind of file).
std::string readWholeFile(const std::string& path, std::size_t maxBytes = kMaxPresetFileBytes,
                          const std::string& what = "a preset file");

// A regular file read piece by piece (a snapshot, parsed as it streams in): opening refuses at once what
// readWholeFile refuses before a byte is read (what is not a regular file: nothing blocks). Throws
// FileError naming the path and why.
class FileReader {
public:
    explicit FileReader(const std::string& path);
    ~FileReader();
    FileReader(const FileReader&) = delete;
    FileReader& operator=(const FileReader&) = delete;

    const std::string& path() const { return path_; }
    std::size_t size() const { return size_; } // [bytes] when it was opened
    // Up to n bytes into buffer; 0 at the end of the file.
    std::size_t read(char* buffer, std::size_t n);

private:
    std::string path_;
    int fd_ = -1;
    std::size_t size_ = 0;
};

// A file written piece by piece where each piece reaches the operating system at once (no buffer in the
// process), so a killed or interrupted process leaves every piece it wrote: the CLI's time series,
// one row per sample. A piece is whole or absent: one that fails half way (a full disk) is cut off
// again before write() throws. It opens the target (outputTarget) truncated, keeping its permissions, and
// refuses a target that is not a regular file. Throws FileError naming the path.
class StreamedFile {
public:
    explicit StreamedFile(const std::string& path);
    ~StreamedFile();
    StreamedFile(const StreamedFile&) = delete;
    StreamedFile& operator=(const StreamedFile&) = delete;

    void write(std::string_view text);
    // Flushes to disk and closes; throws FileError when the data may not be there.
    void close();

private:
    std::string path_;
    int fd_ = -1;
    std::size_t size_ = 0; // bytes of the whole pieces written [bytes]
};

} // namespace pl
