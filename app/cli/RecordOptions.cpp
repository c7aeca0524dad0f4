// The record command's options checked without Qt or FFmpeg (core/media/ClipFormat.h): particlelab-cli
// refuses a clip it cannot make before it starts the media program, and the media program checks the same.
#include "MediaCommands.h"

#include <cmath>

namespace pl::cli {

std::string recordOptionsRefusal(const RecordOptions& options, ClipFormat& format, int& width, int& height,
                                 long long& frames) {
    const auto clip = clipFormatOf(options.out);
    if (!clip) return "--out '" + options.out + "' needs the suffix of a clip format: .mp4, .webm or .gif";
    format = *clip;
    if (!parseClipSize(options.size, width, height))
        return "--size '" + options.size + "' is not a size such as 1280x720 (width x height in pixels)";
    if (std::string refusal = clipSizeRefusal(format, width, height); !refusal.empty()) return refusal;
    const double exact = options.seconds * options.fps;
    frames = std::llround(exact);
    if (frames < 1) return "the clip would have no frame: --seconds × --fps is below one";
    if (std::abs(exact - static_cast<double>(frames)) > 1e-6)
        return "--seconds × --fps must be a whole number of frames (it is " + std::to_string(exact) + ")";
    return {};
}

} // namespace pl::cli
