// Headless EGL context creation (no X server, no Qt): device platform first, then fallbacks.
#include "GlContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <mutex>
#include <sstream>
#include <vector>

namespace pl::gl {

std::string ContextInfo::summary() const {
    return renderer + " | " + version + " | " + vendor + " | " + source;
}

ContextInfo queryCurrentContext(const std::string& source) {
    ContextInfo info;
    auto text = [](GLenum name) {
        const auto* s = reinterpret_cast<const char*>(glGetString(name));
        return std::string(s ? s : "");
    };
    info.vendor = text(GL_VENDOR);
    info.renderer = text(GL_RENDERER);
    info.version = text(GL_VERSION);
    info.source = source;
    info.software = info.renderer.find("llvmpipe") != std::string::npos ||
                    info.renderer.find("softpipe") != std::string::npos;
    if (epoxy_gl_version() < 43)
        throw GlUnavailable("OpenGL " + info.version + " (" + info.renderer +
                            ") is older than 4.3: no compute shaders");
    return info;
}

namespace {

bool hasExtension(const char* list, const std::string& name) {
    if (!list) return false;
    std::istringstream words(list);
    for (std::string w; words >> w;)
        if (w == name) return true;
    return false;
}

class EglContext : public GlContext {
public:
    ~EglContext() override {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }

    // Initialises display and creates a 4.3 core context on it; false (with why) when it cannot.
    bool open(EGLDisplay display, const std::string& source, std::string& why) {
        display_ = display;
        EGLint major = 0, minor = 0;
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
            why = source + ": eglInitialize failed";
            display_ = EGL_NO_DISPLAY;
            return false;
        }
        if (!eglBindAPI(EGL_OPENGL_API)) return fail(source + ": no desktop OpenGL API", why);
        const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                           EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint found = 0;
        const bool haveConfig = eglChooseConfig(display_, configAttributes, &config, 1, &found) && found > 0;
        const bool surfaceless =
            hasExtension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context");
        if (!haveConfig && !surfaceless) return fail(source + ": no pbuffer config", why);
        const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                            4,
                                            EGL_CONTEXT_MINOR_VERSION,
                                            3,
                                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                            EGL_NONE};
        context_ = eglCreateContext(display_, haveConfig ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                    contextAttributes);
        if (context_ == EGL_NO_CONTEXT) return fail(source + ": no OpenGL 4.3 core context", why);
        if (!surfaceless) {
            const EGLint pbufferAttributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
            surface_ = eglCreatePbufferSurface(display_, config, pbufferAttributes);
            if (surface_ == EGL_NO_SURFACE) return fail(source + ": no 1×1 pbuffer", why);
        }
        if (!eglMakeCurrent(display_, surface_, surface_, context_))
            return fail(source + ": eglMakeCurrent failed", why);
        try {
            info_ = queryCurrentContext(source);
        } catch (const GlUnavailable& e) {
            return fail(source + ": " + e.what(), why);
        }
        return true;
    }

    void makeCurrent() override {
        if (eglGetCurrentContext() == context_) return;
        if (!eglMakeCurrent(display_, surface_, surface_, context_))
            throw GlUnavailable("eglMakeCurrent failed for " + info_.source);
    }
    const ContextInfo& info() const override { return info_; }

private:
    bool fail(const std::string& message, std::string& why) {
        why = message;
        return false;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;
    ContextInfo info_;
};

struct Device {
    EGLDeviceEXT handle;
    int index;
    bool software;
    std::string extensions;
};

std::vector<Device> enumerateDevices() {
    std::vector<Device> devices;
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_EXT_device_enumeration") &&
        !hasExtension(clientExtensions, "EGL_EXT_device_base"))
        return devices;
    EGLint count = 0;
    if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return devices;
    std::vector<EGLDeviceEXT> handles(static_cast<std::size_t>(count));
    eglQueryDevicesEXT(count, handles.data(), &count);
    for (EGLint i = 0; i < count; ++i) {
        const char* ext = eglQueryDeviceStringEXT(handles[i], EGL_EXTENSIONS);
        devices.push_back({handles[i], i, hasExtension(ext, "EGL_MESA_device_software"), ext ? ext : ""});
    }
    return devices;
}

// Devices in the order to try them: the override first, then hardware, then software.
std::vector<Device> devicesToTry(std::string& why) {
    std::vector<Device> all = enumerateDevices(), order;
    const char* override = std::getenv("PARTICLELAB_EGL_DEVICE");
    if (override && *override) {
        const std::string choice = override;
        for (const auto& d : all)
            if ((choice == "software" && d.software) || choice == std::to_string(d.index)) order.push_back(d);
        if (order.empty())
            why = "PARTICLELAB_EGL_DEVICE=" + choice + " matches none of " + std::to_string(all.size()) +
                  " EGL devices";
        return order;
    }
    for (const auto& d : all)
        if (!d.software) order.push_back(d);
    for (const auto& d : all)
        if (d.software) order.push_back(d);
    return order;
}

} // namespace

std::shared_ptr<GlContext> createHeadlessContext() {
    std::vector<std::string> tried;
    std::string why;
    for (const Device& device : devicesToTry(why)) {
        auto context = std::make_shared<EglContext>();
        std::string source = "EGL device " + std::to_string(device.index);
        if (device.software) source += " (software)";
        const EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device.handle, nullptr);
        if (context->open(display, source, why)) return context;
        tried.push_back(why);
    }
    if (!why.empty() && tried.empty()) tried.push_back(why);
    if (!std::getenv("PARTICLELAB_EGL_DEVICE")) {
        const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
            auto context = std::make_shared<EglContext>();
            const EGLDisplay display =
                eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            if (context->open(display, "EGL surfaceless platform", why)) return context;
            tried.push_back(why);
        }
        auto context = std::make_shared<EglContext>();
        if (context->open(eglGetDisplay(EGL_DEFAULT_DISPLAY), "EGL default display", why)) return context;
        tried.push_back(why);
    }
    std::string message = "no OpenGL 4.3 context could be created";
    for (const auto& t : tried) message += "; " + t;
    throw GlUnavailable(message);
}

std::shared_ptr<GlContext> sharedHeadlessContext() {
    static std::mutex mutex;
    static std::shared_ptr<GlContext> context;
    static std::string failure;
    std::lock_guard lock(mutex);
    if (context) return context;
    if (!failure.empty()) throw GlUnavailable(failure);
    try {
        context = createHeadlessContext();
    } catch (const GlUnavailable& e) {
        failure = e.what();
        throw;
    }
    return context;
}

} // namespace pl::gl
