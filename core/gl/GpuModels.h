// The GPU models of this library: one entry per model kind that has one, keyed by the kind of its
// registration (core/catalog/ModelDescriptor.h). The backend factory (Backends.h) is their only user.
#pragma once

#include "GlContext.h"
#include "common/Model.h"
#include "common/Preset.h"

#include <memory>
#include <string>
#include <vector>

namespace pl::gl {

struct GpuModel {
    std::string kind; // a registered kind: "gas"
    // The GPU model on context, reset to preset. Throws PresetError for a bad preset, GlUnavailable or
    // ShaderError where the driver cannot run it.
    std::unique_ptr<Model> (*create)(std::shared_ptr<GlContext> context, const Preset& preset);
};

const std::vector<GpuModel>& gpuModels();
// The kind's entry, or nullptr when the kind runs on the CPU only.
const GpuModel* findGpuModel(const std::string& kind);

} // namespace pl::gl
