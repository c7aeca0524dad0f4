// What a clip's file name and size mean before anything is encoded: the format follows the suffix, and a
// size the format cannot take is refused in one sentence. Shared by the CLI's record, which checks its
// options before it starts the media program, and the app's Record; no Qt, no FFmpeg.
#pragma once

#include <optional>
#include <string>

namespace pl {

enum class ClipFormat {
    Mp4,  // H.264 (libx264) in MP4, yuv420p: plays in browsers and presentation programs
    WebM, // VP9 (libvpx-vp9) in WebM, yuv420p
    Gif,  // animated GIF, one 256-colour palette for the whole clip, looping
};

inline constexpr int kMinClipSide = 64;     // [px] room for the time readout
inline constexpr int kMaxClipWidth = 7680;  // [px] 8K UHD
inline constexpr int kMaxClipHeight = 4320; // [px]
inline constexpr int kMaxClipFps = 120;     // [frames/s]

// The format of a file name by its suffix (.mp4, .webm, .gif; any case), or nothing.
std::optional<ClipFormat> clipFormatOf(const std::string& path);
// "MP4 (H.264)", for messages.
std::string clipFormatName(ClipFormat format);

// Reads "1280x720" into width and height [px]; false for anything else.
bool parseClipSize(const std::string& text, int& width, int& height);
// Why a clip of this size cannot be written in this format (zero, beyond 8K, an odd side where the
// format stores chroma at half resolution), or empty when it can.
std::string clipSizeRefusal(ClipFormat format, int width, int height);

} // namespace pl
