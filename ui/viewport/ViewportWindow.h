// The OpenGL drawing of the desktop viewport: particles as antialiased discs drawn by one instanced draw
// call (a quad per particle, the disc cut out in the fragment shader), then the QPainter overlay. A
// native window of its own (inside GLViewport), so a frame swaps only the viewport's pixels: a
// QOpenGLWidget would make Qt compose the whole main window through OpenGL on every frame, which on a
// software rasteriser cost more than the simulation (BENCHMARKS.md, "App frame rate"). It takes no
// input: the mouse and the keys reach GLViewport, the widget around it, as on any other widget.
#pragma once

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWindow>

#include "common/SceneView.h"
#include <vector>

namespace pl::ui {

class ViewportCore;

class ViewportWindow : public QOpenGLWindow, protected QOpenGLExtraFunctions {
    Q_OBJECT
public:
    explicit ViewportWindow(ViewportCore* core);
    ~ViewportWindow() override;
    // Frames whose particles came straight from a GPU model's buffers (no copy through the CPU).
    long long framesFromGpuBuffers() const { return gpuFrames_; }
    // The current frame drawn into an image of the window's size (an offscreen framebuffer, so it does
    // not depend on what the window's back buffer holds after a swap); null before GL is ready.
    QImage renderImage();
    // The simulation advanced a frame: asks for a paint.
    void frameAdvanced();

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    void contextGoingAway();
    void releaseGL();
    // Draws the frame into the bound framebuffer of the given device's size.
    void paintFrame(QPaintDevice& device);
    void drawParticles();
    void drawGpuParticles(const GpuParticles& particles);
    void setCommonUniforms(QOpenGLShaderProgram& program, const SceneView& scene);

    ViewportCore* core_;
    QOpenGLShaderProgram program_;
    QOpenGLShaderProgram gpuProgram_; // particles from SceneView::gpu
    QOpenGLVertexArrayObject vao_;
    QOpenGLBuffer instances_{QOpenGLBuffer::VertexBuffer};
    std::vector<float> packed_; // x, y, radius, value per particle
    bool ready_ = false;
    bool gpuReady_ = false;
    bool softwareRasteriser_ = false; // the GL renderer runs on the CPU cores (llvmpipe)
    long long gpuFrames_ = 0;
};

} // namespace pl::ui
