// A VideoEncoder on a thread of its own: the caller hands over frames and goes on stepping and drawing
// while the previous frames are converted and encoded. At most kClipQueueFrames wait; a caller that is
// faster than the encoder waits for room (or asks hasRoom() first), so memory stays bounded and no frame
// is dropped. Beside a live scene the worker runs at a lower priority, so the encoder takes the time the
// scene leaves rather than the scene's; what is still queued at finish() is encoded on the caller's
// thread, at the caller's priority, so a user waiting for the clip never waits for the leftovers.
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
               std::size_t queueFrames = kClipQueueFrames, EncoderShare share = EncoderShare::Alone);
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
    bool hasRoom() const;            // whether write() would return without waiting
    std::string codecDescription() const { return encoder_.codecDescription(); }

private:
    void run();
    bool encodeFront(); // the first queued frame; false when none is queued
    void rethrow();
    void dropWaiting(); // with the lock held

    VideoEncoder encoder_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::function<QImage()>> queue_;
    std::size_t capacity_;
    EncoderShare share_;
    bool closing_ = false, finished_ = false;
    bool failed_ = false; // the encoding thread's own copy of "an error was met", read without the lock
    long long written_ = 0;
    std::exception_ptr error_;
    std::thread worker_;
};

} // namespace pl::ui
