// The pictures of a clip: the scene as the viewport draws it (ScenePainter.h), alone or beside one plot
// (the present-mode layout), with the experiment's name over the opening second and the simulated time
// in the corner; captions off gives the bare scene.
#pragma once

#include "common/SceneView.h"

#include <QImage>
#include <QRgb>
#include <QSize>
#include <QString>
#include <vector>

class QCustomPlot;

namespace pl::ui {

struct ClipLook {
    QSize size{1280, 720};       // [px]
    int fps = 30;                // [frames/s] how long the title shows: the opening second
    bool captions = true;        // the title and the time readout
    QString title;               // the preset's name
    QString timeUnit;            // the kind's unit of time ("T", "s")
    QCustomPlot* plot = nullptr; // drawn beside the scene when set
    QImage plotImage;            // or a plot drawn already (plotPicture), which any thread may compose
};

// The share of a frame's width the plot takes beside the scene.
inline constexpr double kClipPlotShare = 0.42;

// The plot as it is now, at the size it takes beside the scene in a frame of frameSize. Call it on the
// plot's thread: the app draws it there and hands the picture to the clip's worker.
QImage plotPicture(QCustomPlot* plot, QSize frameSize);

// Frame `index` of the clip (0 is the first), showing `scene` at simulated time `time` [the kind's unit].
QImage clipFrame(const ClipLook& look, const SceneView& scene, double time, long long index);

// The colours of the scene's colour scale, for a GIF's palette (VideoEncoder's paletteHints).
std::vector<QRgb> colourScaleHints(const SceneView& scene);

} // namespace pl::ui
