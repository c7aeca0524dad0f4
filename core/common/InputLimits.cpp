// The JSON depth check and the sizes in the messages of the input bounds.
#include "InputLimits.h"

#include "AtomicFile.h"
#include "Preset.h"

#include <cstdio>

namespace pl {

std::string byteSize(std::size_t bytes) {
    constexpr std::size_t kKiB = 1024, kMiB = kKiB << 10, kGiB = kMiB << 10;
    char text[32];
    if (bytes < kKiB) return std::to_string(bytes) + " bytes";
    const auto in = [&](std::size_t unit, const char* name) {
        if (bytes % unit == 0)
            std::snprintf(text, sizeof text, "%zu %s", bytes / unit, name);
        else
            std::snprintf(text, sizeof text, "%.1f %s", static_cast<double>(bytes) / unit, name);
        return std::string(text);
    };
    if (bytes < kMiB) return in(kKiB, "KiB");
    if (bytes < kGiB) return in(kMiB, "MiB");
    return in(kGiB, "GiB");
}

void checkJsonDepth(std::string_view text, const std::string& source) {
    int depth = 0;
    bool inString = false, escaped = false;
    long long line = 1;
    for (const char c : text) {
        if (c == '\n') ++line;
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) throw PresetError("", jsonDepthRefusal(source, line));
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth; // unbalanced brackets are the parser's to report
        }
    }
}

std::string jsonDepthRefusal(const std::string& source, long long line) {
    return source + ": the JSON nests arrays and objects more than " + std::to_string(kMaxJsonDepth) +
           " levels deep (line " + std::to_string(line) + "); a preset or snapshot needs at most 4";
}

std::string readExperimentText(const std::string& path, std::size_t maxBytes, const std::string& what) {
    try {
        return readWholeFile(path, maxBytes, what);
    } catch (const FileError& e) {
        throw PresetError("", e.what());
    }
}

} // namespace pl
