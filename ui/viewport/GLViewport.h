// The OpenGL viewport: particles as antialiased discs drawn by one instanced draw call (a quad per
// particle, the disc cut out in the fragment shader), then the QPainter overlay. Never created on the
// `offscreen` platform, where Qt 6.4's QOpenGLWidget crashes; SoftwareViewport stands in there.
#pragma once

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>

#include "common/SceneView.h"
#include <vector>

namespace pl::ui {

class SimulationController;
class ViewportCore;

class GLViewport : public QOpenGLWidget, protected QOpenGLExtraFunctions {
    Q_OBJECT
public:
    explicit GLViewport(SimulationController* controller, QWidget* parent = nullptr);
    ~GLViewport() override;
    ViewportCore* core() const { return core_; }
    // Frames whose particles came straight from a GPU model's buffers (no copy through the CPU).
    long long framesFromGpuBuffers() const { return gpuFrames_; }
    QSize sizeHint() const override { return {800, 800}; }

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    void contextGoingAway(); // the dock was floated or the widget re-parented: a new context follows
    void releaseGL();
    void paintFrame();
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
