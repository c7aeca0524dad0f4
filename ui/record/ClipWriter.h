// A VideoEncoder on a thread of its own: the caller hands over frames and goes on stepping and drawing
// while the previous frames are converted and encoded. At most kClipQueueFrames wait; a caller that is
// faster than the encoder waits for room, so memory stays bounded and no frame is dropped.
#pragma once

#include "VideoEncoder.h"

#include <QImage>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace pl::ui {

inline constexpr std::size_t kClipQueueFrames = 4;

class ClipWriter {
public:
    // Opens the clip at once (so an unwritable file or refused size throws VideoError here). queueFrames:
    // how many frames may wait for the encoder before write() waits for room.
    ClipWriter(const std::string& path, int width, int height, int fps, std::vector<QRgb> paletteHints = {},
               std::size_t queueFrames = kClipQueueFrames);
    ~ClipWriter(); // finishes the clip
    ClipWriter(const ClipWriter&) = delete;
    ClipWriter& operator=(const ClipWriter&) = delete;

    // Queues the next frame. Throws the VideoError the encoder met on an earlier frame (a full disk).
    void write(QImage frame);
    // Queues a frame that the worker draws first (the app hands over the scene, so drawing too leaves
    // the window's thread).
    void writeDrawn(std::function<QImage()> draw);
    // Encodes what is queued (or, with dropQueued, drops it: a cancelled encode), drains the encoder and
    // finishes the container. Throws a VideoError met on the way, once.
    void finish(bool dropQueued = false);
    // Drops the frames queued and not yet being encoded, from any thread (also while finish() drains
    // them): a cancelled encode that still ends in a playable clip.
    void dropQueued();

    long long framesWritten() const; // encoded and handed to the file
    long long framesQueued() const;  // handed over and not yet encoded
    std::string codecDescription() const { return encoder_.codecDescription(); }

private:
    void run();
    void rethrow();
    void dropWaiting(); // with the lock held

    VideoEncoder encoder_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::function<QImage()>> queue_;
    std::size_t capacity_;
    bool closing_ = false, finished_ = false;
    long long written_ = 0;
    std::exception_ptr error_;
    std::thread worker_;
};

} // namespace pl::ui
