// The Qt-made GL 4.3 context for the GPU models, and the choice of the app's compute context.
#include "QtGlContext.h"

#include <QGuiApplication>
#include <QSurfaceFormat>

namespace pl::ui {

namespace {
// Qt 6.4 gives compatibility contexts (or crashes) on these: the GPU models use EGL there instead.
bool platformDrawsWithOpenGl() {
    const QString platform = QGuiApplication::platformName();
    return platform != "offscreen" && platform != "minimal";
}
} // namespace

std::shared_ptr<QtGlContext> QtGlContext::create() {
    if (!platformDrawsWithOpenGl())
        throw gl::GlUnavailable("the '" + QGuiApplication::platformName().toStdString() +
                                "' platform has no OpenGL");
    std::shared_ptr<QtGlContext> c(new QtGlContext);
    QSurfaceFormat format;
    format.setVersion(4, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    c->context_ = std::make_unique<QOpenGLContext>();
    c->context_->setFormat(format);
    c->context_->setShareContext(QOpenGLContext::globalShareContext());
    if (!c->context_->create()) throw gl::GlUnavailable("Qt could not create an OpenGL 4.3 core context");
    const QSurfaceFormat got = c->context_->format();
    if (got.version() < qMakePair(4, 3) || got.profile() != QSurfaceFormat::CoreProfile)
        throw gl::GlUnavailable("Qt gave OpenGL " + std::to_string(got.majorVersion()) + "." +
                                std::to_string(got.minorVersion()) + " without the 4.3 core profile");
    // Sharing needs Qt::AA_ShareOpenGLContexts and a driver that shares between these formats.
    c->shared_ = QOpenGLContext::globalShareContext() && c->context_->shareContext();
    c->surface_ = std::make_unique<QOffscreenSurface>();
    c->surface_->setFormat(got);
    c->surface_->create();
    if (!c->context_->makeCurrent(c->surface_.get()))
        throw gl::GlUnavailable("Qt could not make its context current");
    c->info_ = gl::queryCurrentContext("Qt " + QGuiApplication::platformName().toStdString() + " context");
    return c;
}

void QtGlContext::makeCurrent() {
    if (QOpenGLContext::currentContext() == context_.get()) return;
    if (!context_->makeCurrent(surface_.get()))
        throw gl::GlUnavailable("Qt could not make its context current");
}

namespace {
std::shared_ptr<gl::GlContext> appContext;
bool appContextTried = false;
} // namespace

std::shared_ptr<gl::GlContext> appComputeContext() {
    if (!appContextTried) {
        appContextTried = true;
        try {
            appContext = QtGlContext::create();
            // A Qt context must go before the application that made it.
            qAddPostRoutine([] { appContext.reset(); });
        } catch (const gl::GlUnavailable&) {
            appContext = nullptr; // the factory falls back to a headless EGL context, then to the CPU
        }
    }
    return appContext;
}

} // namespace pl::ui
