// Backend factory: CPU reference or GPU model, with a clear message whenever the GPU is not used.
#include "Backends.h"

#include "GpuModels.h"
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
    return findGpuModel(kind) != nullptr;
}

std::size_t autoGpuThreshold(const ContextInfo& info) {
    // Measured (BENCHMARKS.md): on an H100 the GPU gas passes the 16-core CPU at 4 096 disks (1.2×),
    // the fluid at 10 000 particles (9×).
    return info.software ? std::numeric_limits<std::size_t>::max() : 4096;
}

namespace {

// preset null: the kind's defaults (its CPU model as constructed; a GPU model reset to defaultPreset).
BackendChoice create(const ModelDescriptor& descriptor, Backend backend, const Preset* preset,
                     std::shared_ptr<GlContext> context) {
    BackendChoice choice;
    auto cpu = [&] {
        choice.model = preset ? instantiate(*preset) : descriptor.create();
        choice.backend = Backend::Cpu;
    };
    const GpuModel* gpu = findGpuModel(descriptor.kind);
    if (backend == Backend::Cpu) {
        cpu();
        return choice;
    }
    if (!gpu) {
        cpu();
        if (backend == Backend::Gl)
            choice.message = "the " + descriptor.kind + " scene has no GPU model: it runs on the CPU";
        return choice;
    }
    try {
        if (!context) context = sharedHeadlessContext();
    } catch (const GlUnavailable& e) {
        cpu();
        choice.message = std::string("GPU backend unavailable, running on the CPU: ") + e.what();
        return choice;
    }
    const Preset defaults = preset ? Preset{} : defaultPreset(descriptor);
    const Preset& target = preset ? *preset : defaults;
    if (backend == Backend::Auto && particleCount(target) < autoGpuThreshold(context->info())) {
        cpu();
        return choice;
    }
    try {
        choice.model = gpu->create(context, target);
        choice.backend = Backend::Gl;
    } catch (const PresetError&) {
        throw;
    } catch (const std::exception& e) { // a shader that does not build on this driver, out of memory
        cpu();
        choice.message = std::string("GPU backend failed, running on the CPU: ") + e.what();
    }
    return choice;
}

const ModelDescriptor& registered(const std::string& kind) {
    const ModelDescriptor* descriptor = findModel(kind);
    if (!descriptor) throw PresetError("model", unknownScene(kind));
    return *descriptor;
}

} // namespace

BackendChoice createModel(const Preset& preset, Backend backend, std::shared_ptr<GlContext> context) {
    return create(registered(preset.model), backend, &preset, std::move(context));
}

BackendChoice createModel(const std::string& kind, Backend backend, const Preset* preset,
                          std::shared_ptr<GlContext> context) {
    return create(registered(preset ? preset->model : kind), backend, preset, std::move(context));
}

} // namespace pl::gl
