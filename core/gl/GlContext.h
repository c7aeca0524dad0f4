// OpenGL 4.3 contexts for the compute backends. The GL models only need "a current 4.3 core context";
// where it comes from is this interface: a headless EGL context here, a Qt context in the desktop app.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace pl::gl {

// No usable OpenGL 4.3 context: the message says what was tried and what failed.
class GlUnavailable : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ContextInfo {
    std::string vendor, renderer, version; // GL_VENDOR, GL_RENDERER, GL_VERSION
    std::string source;                    // how it was made, e.g. "EGL device 0 (EGL_NV_device_cuda)"
    bool software = false;                 // Mesa llvmpipe / softpipe
    std::string summary() const;           // one line for logs and benchmark headers
};

class GlContext {
public:
    virtual ~GlContext() = default;
    // Makes the context current on the calling thread (cheap when it already is).
    virtual void makeCurrent() = 0;
    virtual const ContextInfo& info() const = 0;
    // Whether the desktop's viewports share objects with this context (they can draw its buffers).
    virtual bool sharesWithViewports() const { return false; }
};

// A context with no window: EGL device enumeration preferring a hardware device, then Mesa's
// surfaceless platform, then the default display with a 1×1 pbuffer. PARTICLELAB_EGL_DEVICE picks a
// device by index, or "software" for Mesa's. Throws GlUnavailable.
std::shared_ptr<GlContext> createHeadlessContext();

// One headless context per process, made on first use; later calls rethrow the first failure.
std::shared_ptr<GlContext> sharedHeadlessContext();

// Reads GL_VENDOR / GL_RENDERER / GL_VERSION of the current context; throws GlUnavailable below 4.3.
ContextInfo queryCurrentContext(const std::string& source);

} // namespace pl::gl
