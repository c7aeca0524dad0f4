// ClipFormat: suffixes and sizes, without FFmpeg, so the command line refuses before it opens anything.
#include "ClipFormat.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace pl {

std::optional<ClipFormat> clipFormatOf(const std::string& path) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::nullopt;
    std::string suffix = path.substr(dot + 1);
    std::transform(suffix.begin(), suffix.end(), suffix.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (suffix == "mp4") return ClipFormat::Mp4;
    if (suffix == "webm") return ClipFormat::WebM;
    if (suffix == "gif") return ClipFormat::Gif;
    return std::nullopt;
}

std::string clipFormatName(ClipFormat format) {
    switch (format) {
    case ClipFormat::Mp4:
        return "MP4 (H.264)";
    case ClipFormat::WebM:
        return "WebM (VP9)";
    case ClipFormat::Gif:
        return "GIF";
    }
    return {};
}

bool parseClipSize(const std::string& text, int& width, int& height) {
    const auto x = text.find('x');
    if (x == std::string::npos || x == 0 || x + 1 >= text.size()) return false;
    const char* begin = text.data();
    const char* end = begin + text.size();
    for (const char* p = begin; p != end; ++p)
        if (p != begin + x && !std::isdigit(static_cast<unsigned char>(*p))) return false;
    if (x > 6 || text.size() - x - 1 > 6) return false; // no overflow: at most 999999
    std::from_chars(begin, begin + x, width);
    std::from_chars(begin + x + 1, end, height);
    return true;
}

std::string clipSizeRefusal(ClipFormat format, int width, int height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width < kMinClipSide || height < kMinClipSide)
        return "the clip size " + size + " is too small: each side needs at least " +
               std::to_string(kMinClipSide) + " pixels";
    if (width > kMaxClipWidth || height > kMaxClipHeight)
        return "the clip size " + size + " is larger than " + std::to_string(kMaxClipWidth) + "x" +
               std::to_string(kMaxClipHeight) + " (8K), the largest recorded";
    if (format != ClipFormat::Gif && (width % 2 != 0 || height % 2 != 0))
        return "the clip size " + size + " has an odd side, which " + clipFormatName(format) +
               " cannot store (its colours are kept at half resolution); use an even width and height";
    return {};
}

} // namespace pl
