// The OpenGL viewport: a plain widget that takes the mouse and the keys (ViewportCore's tools), around a
// native window that draws (ViewportWindow). Never created on the `offscreen` platform, which has no
// OpenGL windows; SoftwareViewport stands in there.
#pragma once

#include <QImage>
#include <QWidget>

namespace pl::ui {

class SimulationController;
class ViewportCore;
class ViewportWindow;

class GLViewport : public QWidget {
    Q_OBJECT
public:
    explicit GLViewport(SimulationController* controller, QWidget* parent = nullptr);
    ~GLViewport() override;
    ViewportCore* core() const { return core_; }
    // Frames whose particles came straight from a GPU model's buffers (no copy through the CPU).
    long long framesFromGpuBuffers() const;
    // The current frame as an image of the viewport's size.
    QImage grabFramebuffer();
    QSize sizeHint() const override { return {800, 800}; }

private:
    ViewportCore* core_;
    ViewportWindow* window_;
    QWidget* container_; // owns window_
};

} // namespace pl::ui
