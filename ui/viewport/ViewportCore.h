// What the GL and the software viewport share: the scene snapshot of the current frame, the world ↔
// widget transform, the mouse tools (an event filter on the viewport widget), the sampled field under the
// particles, the overlay drawn with QPainter (box, obstacles, piston, legends, tool previews, the click
// probe, the profile line) and the frame-rate meter.
#pragma once

#include "ColourScale.h"
#include "ViewTransform.h"
#include "common/SceneView.h"

#include <QElapsedTimer>
#include <QLineF>
#include <QObject>
#include <QPointF>
#include <QRectF>
#include <QStringList>
#include <cstdint>
#include <functional>
#include <optional>

class QPainter;
class QWidget;
class QMouseEvent;

namespace pl::ui {

class SimulationController;

// In the order of the Tools menu (MainWindow finds a tool's action by this index).
enum class ViewportTool { Drag, Spawn, AddDisc, AddBox, Remove, Piston, ProfileLine };

class ViewportCore : public QObject {
    Q_OBJECT
public:
    ViewportCore(SimulationController* controller, QWidget* widget);

    // Takes this frame's snapshot and fits the transform to the widget; call first in every paint.
    void beginPaint();
    // Counts a finished frame for the frame-rate meter, and keeps the widget's accessible name and
    // description (SceneDescription.h) up to date.
    void endPaint();
    // Describes the frame's scene to the accessibility tree now.
    void describe();
    const SceneView& scene() const { return scene_; }
    // The particles' colour scale: automatic (follows a heated gas) or the model's fixed one.
    ColourScale& colourScale() { return colourScale_; }
    // Set by a viewport that can draw particles straight from a GPU model's buffers (SceneView::gpu).
    void setDrawsGpuBuffers(bool on) { drawsGpuBuffers_ = on; }
    bool drawsGpuBuffers() const { return drawsGpuBuffers_; }
    const ViewTransform& transform() const { return transform_; }
    // Asks for the next frame. By default the widget's update(); a viewport that draws into a window of
    // its own (GLViewport) hands its own request here instead.
    void setFrameRequest(std::function<void()> request) { frameRequest_ = std::move(request); }
    void requestFrame() const;
    // The scene's sampled field under everything else (SceneView::field), when it has one.
    void paintField(QPainter& painter) const;
    // The QPainter path of the particles; the GL viewport draws them in a shader unless the scene is
    // dense enough to splat into an image (ParticleSplat.h), which both viewports then do here.
    void paintParticles(QPainter& painter) const;
    void paintOverlay(QPainter& painter) const;

    double framesPerSecond() const { return framesPerSecond_; }
    ViewportTool tool() const { return tool_; }
    void setTool(ViewportTool tool);
    void zoomToFit();

    // The click probe (the Drag tool on a scene with sampled fields, away from bodies): the world point
    // it reads [m], and what it shows there now, the position line first. A right click closes it.
    std::optional<QPointF> probePoint() const { return probe_; }
    QStringList probeText() const;
    void closeProbe();
    // The line the Profile line tool drew, in world units; the Profile dock plots the field along it.
    std::optional<QLineF> profileLine() const { return profileLine_; }
    void setProfileLine(std::optional<QLineF> line);

signals:
    void statusMessage(const QString& message);
    void profileLineChanged();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void press(QMouseEvent* event);
    void move(QMouseEvent* event);
    void release(QMouseEvent* event);
    // Hands the target to the controller: running, the model moves the body there at its tool speed;
    // paused, the body is placed at once.
    void steerObstacle(QPointF target);
    void steerPiston(double x);
    std::optional<std::size_t> obstacleAt(QPointF world) const;
    bool nearPiston(QPointF widgetPoint) const;
    bool hasSampledFields() const;
    void paintSteeredTarget(QPainter& painter) const;
    void updateCursor();

    SimulationController* controller_;
    QWidget* widget_;
    SceneView scene_;
    ColourScale colourScale_;
    std::int64_t paintedStep_ = 0; // the step count of the last frame drawn: a smaller one is a Reset
    ViewTransform transform_;
    ViewportTool tool_ = ViewportTool::Drag;

    // Gesture state
    // Pour: a spawn rectangle drawn with the Drag tool where the scene pours on drag (SceneView::dragPours).
    // Probe: the Drag tool reading the fields; Line: the Profile line tool drawing its line.
    enum class Gesture { None, DragObstacle, DragPiston, Rectangle, Pour, Pan, Probe, Line };
    Gesture gesture_ = Gesture::None;
    std::size_t grabbed_ = 0;
    QPointF grabOffset_;               // obstacle centre − mouse, in world units
    std::optional<QPointF> steeredTo_; // the last target handed to the model while time ran
    QPointF pressPx_, currentPx_;
    std::optional<std::size_t> hovered_;
    std::optional<QPointF> probe_;      // world point the probe reads
    std::optional<QLineF> profileLine_; // world units

    static constexpr int kDescribeIntervalMs = 1000;
    QElapsedTimer describedClock_;
    bool describeSoon_ = true; // a new model or parameters: described at the next frame

    QElapsedTimer frameClock_;
    int framesCounted_ = 0;
    double framesPerSecond_ = 0.0;
    bool drawsGpuBuffers_ = false;
    std::function<void()> frameRequest_;
};

} // namespace pl::ui
