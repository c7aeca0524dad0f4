// Replots a live plot at most kLiveReplotsPerSecond times a second: the data stay complete (every row
// reaches the graphs at once), only the drawing is coalesced, so plots cost a bounded share of a frame
// however fast rows arrive. A plot painted while its replot waits (a grab, an expose) is replotted first,
// so a picture of the window never shows a stale plot.
#pragma once

class QCustomPlot;

namespace pl::ui {

inline constexpr int kLiveReplotsPerSecond = 10;

// In place of plot->replot(QCustomPlot::rpQueuedReplot) for replots that follow new data.
void replotLive(QCustomPlot* plot);

} // namespace pl::ui
