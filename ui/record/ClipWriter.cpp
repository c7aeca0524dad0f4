// ClipWriter: one worker per clip; the queue is the only state the two threads share.
#include "ClipWriter.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>

namespace pl::ui {

namespace {
// The worker's nice value beside a live scene: the scheduler serves the scene's threads (nice 0) first
// and the worker on what they leave, while a worker that falls behind still gets a share of a busy core.
constexpr int kBesideSceneNice = 10;

void serveAfterTheScene() {
    // Linux keeps a nice value per thread (setpriority(2)); raising it needs no privilege. Where it fails
    // the worker simply runs at the scene's priority.
    ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), kBesideSceneNice);
}
} // namespace

ClipWriter::ClipWriter(const std::string& path, int width, int height, int fps,
                       std::vector<QRgb> paletteHints, std::size_t queueFrames, EncoderShare share)
    : encoder_(path, width, height, fps, std::move(paletteHints), share),
      capacity_(std::max<std::size_t>(1, queueFrames)), share_(share), worker_([this] { run(); }) {}

ClipWriter::~ClipWriter() {
    try {
        finish();
    } catch (...) { // a destructor that runs while unwinding must not throw
    }
}

void ClipWriter::run() {
    if (share_ == EncoderShare::BesideLiveScene) serveAfterTheScene();
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
            // Closing beside a live scene: finish() encodes the rest at its caller's priority.
            if (queue_.empty() || (closing_ && share_ == EncoderShare::BesideLiveScene)) return;
        }
        encodeFront();
    }
}

bool ClipWriter::encodeFront() {
    std::function<QImage()> draw;
    {
        std::lock_guard lock(mutex_);
        if (queue_.empty()) return false;
        draw = queue_.front(); // stays queued while it is encoded: dropWaiting() keeps the first
    }
    std::exception_ptr error;
    try {
        if (!failed_) encoder_.write(draw());
    } catch (...) {
        error = std::current_exception();
        failed_ = true;
    }
    std::lock_guard lock(mutex_);
    if (error) error_ = error;
    queue_.pop_front();
    if (!failed_) written_ = encoder_.framesWritten();
    changed_.notify_all();
    return true;
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
    while (encodeFront()) {
    }
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

bool ClipWriter::hasRoom() const {
    std::lock_guard lock(mutex_);
    return queue_.size() < capacity_;
}

long long ClipWriter::framesQueued() const {
    std::lock_guard lock(mutex_);
    return static_cast<long long>(queue_.size());
}

} // namespace pl::ui
