// ClipWriter: one worker per clip; the queue is the only state the two threads share.
#include "ClipWriter.h"

#include <algorithm>

namespace pl::ui {

ClipWriter::ClipWriter(const std::string& path, int width, int height, int fps,
                       std::vector<QRgb> paletteHints, std::size_t queueFrames)
    : encoder_(path, width, height, fps, std::move(paletteHints)),
      capacity_(std::max<std::size_t>(1, queueFrames)), worker_([this] { run(); }) {}

ClipWriter::~ClipWriter() {
    try {
        finish();
    } catch (...) { // a destructor that runs while unwinding must not throw
    }
}

void ClipWriter::run() {
    bool failed = false; // the worker's own copy of "error_ is set", read without the lock
    for (;;) {
        std::function<QImage()> draw;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
            if (queue_.empty()) return; // closing, and everything was encoded
            draw = queue_.front();
        }
        std::exception_ptr error;
        try {
            if (!failed) encoder_.write(draw());
        } catch (...) {
            error = std::current_exception();
            failed = true;
        }
        std::lock_guard lock(mutex_);
        if (error) error_ = error;
        queue_.pop_front();
        if (!failed) written_ = encoder_.framesWritten();
        changed_.notify_all();
    }
}

void ClipWriter::rethrow() {
    if (error_) {
        std::exception_ptr error = std::exchange(error_, nullptr);
        std::rethrow_exception(error);
    }
}

void ClipWriter::write(QImage frame) {
    writeDrawn([frame = std::move(frame)] { return frame; });
}

void ClipWriter::writeDrawn(std::function<QImage()> draw) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return queue_.size() < capacity_ || error_; });
    rethrow();
    queue_.push_back(std::move(draw));
    changed_.notify_all();
}

void ClipWriter::finish(bool dropQueued) {
    {
        std::lock_guard lock(mutex_);
        if (finished_) return;
        finished_ = true;
        if (dropQueued) dropWaiting();
        closing_ = true;
        changed_.notify_all();
    }
    worker_.join();
    std::exception_ptr error;
    {
        std::lock_guard lock(mutex_);
        error = std::exchange(error_, nullptr);
    }
    encoder_.finish(); // after a write error it finishes what it can without throwing
    if (error) std::rethrow_exception(error);
}

void ClipWriter::dropWaiting() {
    if (queue_.size() > 1) queue_.erase(queue_.begin() + 1, queue_.end()); // the first is being encoded
}

void ClipWriter::dropQueued() {
    std::lock_guard lock(mutex_);
    dropWaiting();
    changed_.notify_all();
}

long long ClipWriter::framesWritten() const {
    std::lock_guard lock(mutex_);
    return written_;
}

long long ClipWriter::framesQueued() const {
    std::lock_guard lock(mutex_);
    return static_cast<long long>(queue_.size());
}

} // namespace pl::ui
