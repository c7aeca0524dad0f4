// Writing files so that a crash or a full disk never leaves a half-written file behind.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace pl {

class FileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Writes content to a temporary file beside path, flushes it to disk, then renames it over path.
// Throws FileError naming the path and the system's reason; the old file stays intact on failure.
void writeFileAtomically(const std::string& path, std::string_view content);

// Reads a whole file; throws FileError naming the path and the system's reason.
std::string readWholeFile(const std::string& path);

} // namespace pl
