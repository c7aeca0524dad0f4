// Files under resources/ compiled into the binary (core is Qt-free, so not through Qt's resource system).
#pragma once

#include <span>
#include <string_view>

namespace pl {

struct EmbeddedFile {
    std::string_view path; // relative to resources/, e.g. "presets/gas/gas-write-up.json"
    std::string_view text;
};

// Defined in a source generated at build time from resources/ (see resources/EmbedFiles.cmake).
std::span<const EmbeddedFile> embeddedFiles();

} // namespace pl
