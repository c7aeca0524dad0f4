// The GPU models' context inside the desktop app: a Qt OpenGL 4.3 core context on an offscreen surface,
// sharing objects with the viewports (Qt::AA_ShareOpenGLContexts), so Qt keeps track of which context
// is current and the viewports can draw from the simulation's buffers.
#pragma once

#include "gl/GlContext.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <memory>

namespace pl::ui {

class QtGlContext : public gl::GlContext {
public:
    // Throws gl::GlUnavailable where the platform has no OpenGL (offscreen, minimal) or no 4.3 core.
    static std::shared_ptr<QtGlContext> create();

    void makeCurrent() override;
    const gl::ContextInfo& info() const override { return info_; }
    bool sharesWithViewports() const override { return shared_; }

private:
    QtGlContext() = default;
    std::unique_ptr<QOpenGLContext> context_;
    std::unique_ptr<QOffscreenSurface> surface_;
    gl::ContextInfo info_;
    bool shared_ = false;
};

// The context the app's GPU models use: the Qt one where the platform draws with OpenGL, else none
// (the factory then makes a headless EGL one). Made once, on first use.
std::shared_ptr<gl::GlContext> appComputeContext();

} // namespace pl::ui
