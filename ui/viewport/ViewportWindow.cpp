// ViewportWindow: GLSL 3.30 is enough for drawing (instancing, gl_VertexID); the simulation's compute
// shaders need 4.3, the viewport does not.
#include "ViewportWindow.h"

#include "FrameProfile.h"
#include "Palette.h"
#include "ParticleSplat.h"
#include "ViewportCore.h"

#include <QOpenGLFramebufferObject>
#include <QOpenGLPaintDevice>
#include <QPainter>
#include <cstring>
#include <omp.h>

namespace pl::ui {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec4 particle; // x, y [world], radius [world], colour value
uniform vec2 worldToNdcScale;
uniform vec2 worldToNdcOffset;
uniform vec2 pixelToNdc;
uniform float pixelsPerWorld;
uniform float pointRadiusPx;
out vec2 offsetPx;
out float radiusPx;
out float value;
const vec2 corners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
void main() {
    radiusPx = particle.z > 0.0 ? max(particle.z * pixelsPerWorld, 1.0) : pointRadiusPx;
    vec2 corner = corners[gl_VertexID] * (radiusPx + 1.0); // one pixel more for the antialiased rim
    offsetPx = corner;
    value = particle.w;
    gl_Position = vec4(particle.xy * worldToNdcScale + worldToNdcOffset + corner * pixelToNdc, 0.0, 1.0);
}
)";

// The same discs, read straight from a GPU model's storage buffers (std430, see SceneView::gpu): the
// instance index is the particle index, the colour value is the speed. Needs GLSL 4.30.
const char* kGpuVertexShader = R"(#version 430 core
layout(std430, binding = 0) readonly buffer Positions { vec2 positions[]; };
layout(std430, binding = 1) readonly buffer Velocities { vec2 velocities[]; };
layout(std430, binding = 2) readonly buffer Accelerations { vec2 accelerations[]; };
layout(std430, binding = 3) readonly buffer Tags { uint tags[]; };
uniform bool hasAccelerations, hasTags;
uniform float pendingKick, inverseColourMax;
uniform vec2 speciesRadius;
uniform vec2 worldToNdcScale;
uniform vec2 worldToNdcOffset;
uniform vec2 pixelToNdc;
uniform float pixelsPerWorld;
out vec2 offsetPx;
out float radiusPx;
out float value;
const vec2 corners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
void main() {
    const int i = gl_InstanceID;
    vec2 v = velocities[i];
    if (hasAccelerations) v += pendingKick * accelerations[i];
    const float radius = speciesRadius[hasTags ? int(tags[i] & 1u) : 0];
    radiusPx = max(radius * pixelsPerWorld, 1.0);
    vec2 corner = corners[gl_VertexID] * (radiusPx + 1.0);
    offsetPx = corner;
    value = length(v) * inverseColourMax;
    gl_Position = vec4(positions[i] * worldToNdcScale + worldToNdcOffset + corner * pixelToNdc, 0.0, 1.0);
}
)";

const char* kFragmentShader = R"(#version 330 core
in vec2 offsetPx;
in float radiusPx;
in float value;
uniform vec3 stops[10];
uniform int stopCount;
uniform bool categorical;
out vec4 colour;
vec3 palette(float v) {
    if (categorical) return stops[clamp(int(v), 0, stopCount - 1)];
    float x = clamp(v, 0.0, 1.0) * float(stopCount - 1);
    int i = min(int(floor(x)), stopCount - 2);
    return mix(stops[i], stops[i + 1], x - float(i));
}
void main() {
    // Coverage of the pixel by the disc: 1 inside, 0 outside, linear across the one-pixel rim.
    float coverage = clamp(radiusPx + 0.5 - length(offsetPx), 0.0, 1.0);
    if (coverage <= 0.0) discard;
    colour = vec4(palette(value), coverage);
}
)";

constexpr float kPointRadiusPx = 2.0f;

} // namespace

ViewportWindow::ViewportWindow(ViewportCore* core)
    // In the share group of the GPU models' context (QtGlContext), so it can draw from their buffers.
    : QOpenGLWindow(QOpenGLContext::globalShareContext(), NoPartialUpdate), core_(core) {
    setFlags(flags() | Qt::WindowTransparentForInput | Qt::WindowDoesNotAcceptFocus);
}

ViewportWindow::~ViewportWindow() {
    if (!isValid()) return;
    // QOpenGLWindow's own destructor destroys the context after this one has run: no slot of ours then.
    disconnect(context(), nullptr, this, nullptr);
    makeCurrent();
    releaseGL();
    doneCurrent();
}

void ViewportWindow::contextGoingAway() {
    makeCurrent();
    releaseGL();
    doneCurrent();
}

void ViewportWindow::releaseGL() {
    if (!ready_) return;
    instances_.destroy();
    vao_.destroy();
    program_.removeAllShaders();
    gpuProgram_.removeAllShaders();
    ready_ = gpuReady_ = false;
    core_->setDrawsGpuBuffers(false);
}

void ViewportWindow::initializeGL() {
    initializeOpenGLFunctions();
    // A context that goes away (the window re-created) takes its objects along: drop our handles first.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWindow::contextGoingAway,
            Qt::UniqueConnection);
    if (!program_.addShaderFromSourceCode(QOpenGLShader::Vertex, kVertexShader) ||
        !program_.addShaderFromSourceCode(QOpenGLShader::Fragment, kFragmentShader) || !program_.link()) {
        qWarning("ViewportWindow: cannot build the particle shader: %s", qPrintable(program_.log()));
        return;
    }
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    softwareRasteriser_ =
        renderer && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe"));
    vao_.create();
    instances_.create();
    instances_.setUsagePattern(QOpenGLBuffer::StreamDraw);
    ready_ = true;
    // Drawing from a GPU model's buffers needs GLSL 4.30 and a context in the models' share group.
    const bool canShare = context()->format().version() >= qMakePair(4, 3) && context()->shareContext() &&
                          QOpenGLContext::globalShareContext();
    gpuReady_ = canShare && gpuProgram_.addShaderFromSourceCode(QOpenGLShader::Vertex, kGpuVertexShader) &&
                gpuProgram_.addShaderFromSourceCode(QOpenGLShader::Fragment, kFragmentShader) &&
                gpuProgram_.link();
    core_->setDrawsGpuBuffers(gpuReady_);
}

void ViewportWindow::setCommonUniforms(QOpenGLShaderProgram& program, const SceneView& scene) {
    const ViewTransform& t = core_->transform();
    const auto w = static_cast<float>(t.size().width()), h = static_cast<float>(t.size().height());
    const auto s = static_cast<float>(t.scale());
    program.setUniformValue("worldToNdcScale", 2 * s / w, 2 * s / h);
    program.setUniformValue("worldToNdcOffset", static_cast<float>(-2 * s * t.centreX() / w),
                            static_cast<float>(-2 * s * t.centreY() / h));
    program.setUniformValue("pixelToNdc", 2 / w, 2 / h);
    program.setUniformValue("pixelsPerWorld", s);
    const QVector<QColor>& stops = paletteStops(scene.colours);
    QVector<QVector3D> rgb;
    for (const QColor& c : stops) rgb << QVector3D(c.redF(), c.greenF(), c.blueF());
    program.setUniformValueArray("stops", rgb.constData(), static_cast<int>(rgb.size()));
    program.setUniformValue("stopCount", static_cast<int>(rgb.size()));
    program.setUniformValue("categorical", isCategorical(scene.colours));
}

void ViewportWindow::drawGpuParticles(const GpuParticles& particles) {
    if (particles.count == 0) return;
    gpuProgram_.bind();
    setCommonUniforms(gpuProgram_, core_->scene());
    gpuProgram_.setUniformValue("hasAccelerations", particles.accelerations != 0);
    gpuProgram_.setUniformValue("hasTags", particles.tags != 0);
    gpuProgram_.setUniformValue("pendingKick", particles.pendingKick);
    gpuProgram_.setUniformValue("inverseColourMax", particles.inverseColourMax);
    gpuProgram_.setUniformValue("speciesRadius", particles.radius[0], particles.radius[1]);
    // Unused bindings get the positions: always a valid buffer, never read.
    const GLuint buffers[4] = {particles.positions, particles.velocities,
                               particles.accelerations ? particles.accelerations : particles.positions,
                               particles.tags ? particles.tags : particles.positions};
    for (GLuint b = 0; b < 4; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, buffers[b]);
    vao_.bind();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(particles.count));
    glDisable(GL_BLEND);
    vao_.release();
    gpuProgram_.release();
    ++gpuFrames_;
}

void ViewportWindow::drawParticles() {
    const SceneView& scene = core_->scene();
    if (!ready_ || !scene.drawParticles || splatsParticles(scene)) return;
    if (scene.gpu) {
        if (gpuReady_) drawGpuParticles(*scene.gpu);
        return;
    }
    if (scene.size() == 0) return;
    packed_.resize(4 * scene.size());
    for (std::size_t i = 0; i < scene.size(); ++i) {
        packed_[4 * i] = scene.x[i];
        packed_[4 * i + 1] = scene.y[i];
        packed_[4 * i + 2] = scene.radius[i];
        packed_[4 * i + 3] = scene.value[i];
    }
    program_.bind();
    setCommonUniforms(program_, scene);
    program_.setUniformValue("pointRadiusPx", kPointRadiusPx);

    vao_.bind();
    instances_.bind();
    instances_.allocate(packed_.data(), static_cast<int>(packed_.size() * sizeof(float)));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
    glVertexAttribDivisor(0, 1);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(scene.size()));
    glDisable(GL_BLEND);
    instances_.release();
    vao_.release();
    program_.release();
}

void ViewportWindow::paintGL() {
    {
        const FramePartTimer timer(FramePart::Viewport);
        core_->beginPaint();
        // A GPU model handing over its buffers made its own context current (to finish its steps): take
        // ours back, with the window's framebuffer bound.
        makeCurrent();
        paintFrame(*this);
    }
    FrameProfile::instance().frameShown();
}

void ViewportWindow::frameAdvanced() {
    // A software rasteriser (Mesa llvmpipe) draws the frame on the CPU cores that the model's OpenMP
    // workers keep spinning on, waiting for the next step: let them go right after the frame's steps (the
    // paint comes a few milliseconds later, when the window's update request is answered), so the frame
    // gets the cores. The next step starts them again (tens of µs).
    if (softwareRasteriser_) omp_pause_resource_all(omp_pause_soft);
    update();
}

QImage ViewportWindow::renderImage() {
    if (!isValid() || !ready_) return {};
    core_->beginPaint();
    makeCurrent();
    const qreal ratio = devicePixelRatio();
    QOpenGLFramebufferObject target(size() * ratio);
    target.bind();
    QOpenGLPaintDevice device(target.size());
    device.setDevicePixelRatio(ratio);
    paintFrame(device);
    QImage image = target.toImage();
    target.release();
    image.setDevicePixelRatio(ratio);
    return image;
}

void ViewportWindow::paintFrame(QPaintDevice& device) {
    QPainter painter(&device);
    painter.beginNativePainting(); // Qt's documented way to mix raw GL with QPainter
    const auto& bg = core_->scene().background;
    glClearColor(bg[0], bg[1], bg[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (core_->scene().field) { // under the particles: QPainter's GL engine draws it as one texture
        painter.endNativePainting();
        core_->paintField(painter);
        painter.beginNativePainting();
    }
    drawParticles();
    painter.endNativePainting();
    if (splatsParticles(core_->scene())) core_->paintParticles(painter);
    core_->paintOverlay(painter);
    painter.end();
    core_->endPaint();
}

} // namespace pl::ui
