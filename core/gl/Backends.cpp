// Backend factory: CPU reference or GPU model, with a clear message whenever the GPU is not used.
#include "Backends.h"

#include "MdModelGL.h"
#include "PbfModelGL.h"
#include "catalog/ModelCatalog.h"

#include <limits>
#include <stdexcept>

namespace pl::gl {

Backend backendFromName(const std::string& name) {
    if (name == "cpu") return Backend::Cpu;
    if (name == "gl") return Backend::Gl;
    if (name == "auto") return Backend::Auto;
    throw std::invalid_argument("unknown backend '" + name + "' (cpu, gl or auto)");
}

std::string backendName(Backend backend) {
    switch (backend) {
    case Backend::Cpu:
        return "cpu";
    case Backend::Gl:
        return "gl";
    case Backend::Auto:
        return "auto";
    }
    return "cpu";
}

const std::vector<std::string>& backendNames() {
    static const std::vector<std::string> names{"auto", "cpu", "gl"};
    return names;
}

bool hasGpuModel(const std::string& kind) {
    return kind == "gas" || kind == "fluid";
}

std::size_t autoGpuThreshold(const ContextInfo& info) {
    // Measured (BENCHMARKS.md): on an H100 the GPU gas passes the 16-core CPU at 4 096 disks (1.2×),
    // the fluid at 10 000 particles (9×).
    return info.software ? std::numeric_limits<std::size_t>::max() : 4096;
}

namespace {

std::unique_ptr<Model> makeGpuModel(const std::string& kind, std::shared_ptr<GlContext> context) {
    if (kind == "gas") return std::make_unique<MdModelGL>(std::move(context));
    return std::make_unique<PbfModelGL>(std::move(context)); // hasGpuModel(kind) holds
}

} // namespace

BackendChoice createModel(const std::string& kind, Backend backend, const Preset* preset,
                          std::shared_ptr<GlContext> context) {
    BackendChoice choice;
    auto cpu = [&] {
        choice.model = preset ? instantiate(*preset) : pl::createModel(kind);
        choice.backend = Backend::Cpu;
    };
    if (backend == Backend::Cpu) {
        cpu();
        return choice;
    }
    if (!hasGpuModel(kind)) {
        cpu();
        if (backend == Backend::Gl)
            choice.message = "the " + kind + " scene has no GPU model: it runs on the CPU";
        return choice;
    }
    try {
        if (!context) context = sharedHeadlessContext();
    } catch (const GlUnavailable& e) {
        cpu();
        choice.message = std::string("GPU backend unavailable, running on the CPU: ") + e.what();
        return choice;
    }
    if (backend == Backend::Auto) {
        cpu();
        const std::size_t threshold = autoGpuThreshold(context->info());
        if (choice.model->particleCount() < threshold) return choice;
    }
    try {
        auto model = makeGpuModel(kind, context);
        if (preset) model->reset(*preset);
        choice.model = std::move(model);
        choice.backend = Backend::Gl;
        choice.message.clear();
    } catch (const PresetError&) {
        throw;
    } catch (const std::exception& e) { // a shader that does not build on this driver, out of memory
        cpu();
        choice.message = std::string("GPU backend failed, running on the CPU: ") + e.what();
    }
    return choice;
}

} // namespace pl::gl
