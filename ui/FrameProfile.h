// Where the desktop app's frames spend their time: wall time per part (model steps, sampling with the
// plots' data refresh, plot replots, the viewport's paint), grouped per frame shown (from one viewport
// paint to the next). Off unless --measure-fps switches it on; then it costs two clock reads per part.
#pragma once

#include <QElapsedTimer>
#include <QString>
#include <algorithm>
#include <array>
#include <vector>

namespace pl::ui {

enum class FramePart { Step, Sample, Replot, Viewport, Count };

class FrameProfile {
public:
    static FrameProfile& instance() {
        static FrameProfile profile;
        return profile;
    }
    void setEnabled(bool on) {
        enabled_ = on;
        frames_.clear();
        current_ = {};
        frameClock_.invalidate();
    }
    bool enabled() const { return enabled_; }
    void add(FramePart part, qint64 nanoseconds) { current_[static_cast<int>(part)] += nanoseconds; }
    // The viewport finished a frame: what was added since the previous one belongs to it.
    void frameShown() {
        if (!enabled_) return;
        if (frameClock_.isValid()) {
            Parts frame = current_;
            frame[kTotal] = frameClock_.nsecsElapsed();
            frames_.push_back(frame);
        }
        frameClock_.start();
        current_ = {};
    }
    // Frames shown since the profile was switched on.
    std::size_t frames() const { return frames_.size(); }
    // JSON object: per part the mean and the median over frames [ms]; "other" is the rest of a frame
    // (the window's composition and flush, waiting for the GL rasteriser and for the frame timer).
    QString report() const {
        static const char* const names[] = {"step", "sample", "replot", "viewport"};
        QString out = QStringLiteral("{\"frames\": %1").arg(frames_.size());
        const auto add = [&](const char* name, auto value) {
            std::vector<double> ms;
            for (const Parts& f : frames_) ms.push_back(1e-6 * static_cast<double>(value(f)));
            double mean = 0, median = 0;
            if (!ms.empty()) {
                for (double v : ms) mean += v / static_cast<double>(ms.size());
                std::nth_element(ms.begin(), ms.begin() + static_cast<long>(ms.size() / 2), ms.end());
                median = ms[ms.size() / 2];
            }
            out +=
                QStringLiteral(", \"%1_ms\": [%2, %3]").arg(name).arg(mean, 0, 'f', 2).arg(median, 0, 'f', 2);
        };
        for (int p = 0; p < kTotal; ++p) add(names[p], [p](const Parts& f) { return f[p]; });
        add("other", [](const Parts& f) {
            qint64 rest = f[kTotal];
            for (int p = 0; p < kTotal; ++p) rest -= f[p];
            return std::max<qint64>(rest, 0);
        });
        add("frame", [](const Parts& f) { return f[kTotal]; });
        return out + QStringLiteral("}");
    }

private:
    static constexpr int kTotal = static_cast<int>(FramePart::Count);
    using Parts = std::array<qint64, kTotal + 1>; // the parts, then the whole frame [ns]
    bool enabled_ = false;
    Parts current_{};
    std::vector<Parts> frames_;
    QElapsedTimer frameClock_;
};

// Adds the wall time of its scope to a part of the current frame (when the profile is on).
class FramePartTimer {
public:
    explicit FramePartTimer(FramePart part) : part_(part) {
        if (FrameProfile::instance().enabled()) clock_.start();
    }
    ~FramePartTimer() {
        if (clock_.isValid()) FrameProfile::instance().add(part_, clock_.nsecsElapsed());
    }
    FramePartTimer(const FramePartTimer&) = delete;
    FramePartTimer& operator=(const FramePartTimer&) = delete;

private:
    FramePart part_;
    QElapsedTimer clock_;
};

} // namespace pl::ui
