// LiveReplot: one throttle object per plot, a child of the plot (found by its object name), so it lives
// and dies with the plot.
#include "LiveReplot.h"

#include <QElapsedTimer>
#include <QEvent>
#include <QTimer>
#include <qcustomplot.h>

namespace pl::ui {

namespace {

constexpr int kIntervalMs = 1000 / kLiveReplotsPerSecond;
const char* const kThrottleName = "pl_liveReplot";

class ReplotThrottle : public QObject {
public:
    explicit ReplotThrottle(QCustomPlot* plot) : QObject(plot), plot_(plot) {
        setObjectName(kThrottleName);
        waiting_.setSingleShot(true);
        connect(&waiting_, &QTimer::timeout, this, &ReplotThrottle::replotNow);
        plot->installEventFilter(this);
    }

    void request() {
        if (!lastReplot_.isValid() || lastReplot_.elapsed() >= kIntervalMs)
            replotNow();
        else if (!waiting_.isActive())
            waiting_.start(static_cast<int>(kIntervalMs - lastReplot_.elapsed()));
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        // Redraws the layers into the plot's buffers before its paintEvent shows them.
        if (watched == plot_ && event->type() == QEvent::Paint && waiting_.isActive()) {
            waiting_.stop();
            lastReplot_.start();
            plot_->replot(QCustomPlot::rpQueuedRefresh);
        }
        return false;
    }

private:
    void replotNow() {
        waiting_.stop();
        lastReplot_.start();
        plot_->replot(QCustomPlot::rpQueuedReplot);
    }

    QCustomPlot* plot_;
    QElapsedTimer lastReplot_;
    QTimer waiting_;
};

} // namespace

void replotLive(QCustomPlot* plot) {
    // ReplotThrottle has no meta-object of its own: it is found by its name.
    auto* throttle =
        static_cast<ReplotThrottle*>(plot->findChild<QObject*>(kThrottleName, Qt::FindDirectChildrenOnly));
    if (!throttle) throttle = new ReplotThrottle(plot);
    throttle->request();
}

} // namespace pl::ui
