// Writes a clip through FFmpeg's libraries (libavformat, libavcodec, libswscale): MP4 with H.264 from
// libx264, WebM with VP9 from libvpx-vp9, or an animated GIF with one palette for the clip. Frames go to
// the file as they are encoded, and the container is finished on every path (finish(), the destructor),
// so a stopped or failed recording leaves a clip that plays up to its last frame. The container goes to
// the file in pieces that decode on their own (an MP4 fragment or WebM cluster of a second, a GIF frame),
// so a process killed outright leaves a clip that decodes without error up to about its last second.
#pragma once

#include "media/ClipFormat.h"

#include <QImage>
#include <QRgb>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace pl::ui {

// A clip that cannot be opened or written; what() is one sentence.
class VideoError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Whose machine the encoder works on. A headless recording has it to itself: the encoder picks its own
// threads and x264 its "veryfast" preset. The app's recording shares it with the live scene: one thread
// (the clip's worker, which the scheduler serves after the scene) and x264's "ultrafast" preset, which
// needs under a third of "veryfast"'s time for a 720p frame at the same CRF and writes a file about three
// times larger (BENCHMARKS.md, "Recording beside the live scene").
enum class EncoderShare { Alone, BesideLiveScene };

class VideoEncoder {
public:
    // Opens path for a clip of width × height pixels at fps frames per second in the format of its
    // suffix (clipFormatOf, sizes checked by clipSizeRefusal). paletteHints: colours a GIF's palette
    // keeps besides those of its first frame (a scene's colour scale, whose hot end may come later).
    // Throws VideoError.
    VideoEncoder(const std::string& path, int width, int height, int fps, std::vector<QRgb> paletteHints = {},
                 EncoderShare share = EncoderShare::Alone);
    ~VideoEncoder(); // finishes the clip if finish() was not called
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // Encodes the next frame (any format; converted to the clip's size and pixel format). Throws
    // VideoError when the file cannot take it (a full disk); the frames before it stay playable.
    void write(const QImage& frame);
    // Drains the encoder and writes the container's end. Safe to call more than once; after a write
    // error it finishes what it can and does not throw again.
    void finish();

    long long framesWritten() const { return frames_; }
    // The codec and its library, e.g. "H.264 (libx264)".
    std::string codecDescription() const;

private:
    struct Impl;
    void encode(bool flush);
    std::vector<QRgb> gifPalette(const QImage& first) const;
    void mapToPalette(const QImage& rgb);

    std::unique_ptr<Impl> d_;
    ClipFormat format_;
    int width_, height_, fps_;
    long long frames_ = 0;
    bool finished_ = false, failed_ = false;
    std::vector<QRgb> paletteHints_;
};

} // namespace pl::ui
