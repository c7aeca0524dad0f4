// What the GL and the software viewport share: the scene snapshot of the current frame, the world ↔
// widget transform, the mouse tools (an event filter on the viewport widget), the overlay drawn with
// QPainter (box, obstacles, piston, legend, tool previews) and the frame-rate meter.
#pragma once

#include "ViewTransform.h"
#include "common/SceneView.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointF>
#include <QRectF>
#include <optional>

class QPainter;
class QWidget;
class QMouseEvent;

namespace pl::ui {

class SimulationController;

enum class ViewportTool { Drag, Spawn, AddDisc, AddBox, Remove, Piston };

class ViewportCore : public QObject {
    Q_OBJECT
public:
    ViewportCore(SimulationController* controller, QWidget* widget);

    // Takes this frame's snapshot and fits the transform to the widget; call first in every paint.
    void beginPaint();
    // Counts a finished frame for the frame-rate meter.
    void endPaint();
    const SceneView& scene() const { return scene_; }
    // Set by a viewport that can draw particles straight from a GPU model's buffers (SceneView::gpu).
    void setDrawsGpuBuffers(bool on) { drawsGpuBuffers_ = on; }
    bool drawsGpuBuffers() const { return drawsGpuBuffers_; }
    const ViewTransform& transform() const { return transform_; }
    void paintParticles(QPainter& painter) const; // the CPU path; the GL viewport draws them in a shader
    void paintOverlay(QPainter& painter) const;

    double framesPerSecond() const { return framesPerSecond_; }
    ViewportTool tool() const { return tool_; }
    void setTool(ViewportTool tool);
    void zoomToFit();

signals:
    void statusMessage(const QString& message);

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
    void paintLegend(QPainter& painter) const;
    void paintSteeredTarget(QPainter& painter) const;
    void updateCursor();

    SimulationController* controller_;
    QWidget* widget_;
    SceneView scene_;
    ViewTransform transform_;
    ViewportTool tool_ = ViewportTool::Drag;

    // Gesture state
    // Pour: a spawn rectangle drawn with the Drag tool where the scene pours on drag (SceneView::dragPours).
    enum class Gesture { None, DragObstacle, DragPiston, Rectangle, Pour, Pan };
    Gesture gesture_ = Gesture::None;
    std::size_t grabbed_ = 0;
    QPointF grabOffset_;               // obstacle centre − mouse, in world units
    std::optional<QPointF> steeredTo_; // the last target handed to the model while time ran
    QPointF pressPx_, currentPx_;
    std::optional<std::size_t> hovered_;

    QElapsedTimer frameClock_;
    int framesCounted_ = 0;
    double framesPerSecond_ = 0.0;
    bool drawsGpuBuffers_ = false;
};

} // namespace pl::ui
