// The GPU model table: a kind with a GPU model adds one line here.
#include "GpuModels.h"

#include "FluidModelGL.h"
#include "GasModelGL.h"
#include "TunnelModelGL.h"

namespace pl::gl {

namespace {
// Built straight from the preset: one reset per load (throws PresetError for a bad preset).
template <class GpuModelType>
std::unique_ptr<Model> buildOnGpu(std::shared_ptr<GlContext> context, const Preset& preset) {
    return std::make_unique<GpuModelType>(std::move(context), preset);
}
} // namespace

const std::vector<GpuModel>& gpuModels() {
    static const std::vector<GpuModel> list{
        {"gas", &buildOnGpu<GasModelGL>},
        {"fluid", &buildOnGpu<FluidModelGL>},
        {"tunnel", &buildOnGpu<TunnelModelGL>},
    };
    return list;
}

const GpuModel* findGpuModel(const std::string& kind) {
    for (const GpuModel& m : gpuModels())
        if (m.kind == kind) return &m;
    return nullptr;
}

} // namespace pl::gl
