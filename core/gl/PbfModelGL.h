// The fluid on the GPU: the CPU model's parameters, presets, tools and observables, with Algorithm 1's
// passes (predict + counting sort, λ, Δx, velocities, vorticity, XSPH) as OpenGL 4.3 compute shaders in
// float32, in gather form over the cell-ordered particles. The CPU state is brought up to date only
// when something reads it.
#pragma once

#include "GlContext.h"
#include "GpuHandOver.h"
#include "pbf/PbfModel.h"

#include <memory>

namespace pl::gl {

struct PbfGpu;

class PbfModelGL : public GpuHandOver<PbfModel> {
public:
    // Needs a current-able 4.3 context; throws GlUnavailable or ShaderError. Builds the default tank.
    explicit PbfModelGL(std::shared_ptr<GlContext> context);
    // Builds the preset's tank: one reset (throws PresetError as reset(preset) does).
    PbfModelGL(std::shared_ptr<GlContext> context, const Preset& preset);
    ~PbfModelGL() override;

    void step() override;
    void finishPendingWork() const override; // glFinish in the model's context
    SceneView sceneViewSharingGpu() const override;
    int dispatchesLastStep() const;

private:
    void createBuffers();
    void upload() override;
    // Also brings the per-iteration errors of the last GPU step to the CPU.
    void download() const override;
    void setCommonUniforms(class ComputeProgram& p) const;
    void checkGpuHealth();

    std::unique_ptr<PbfGpu> gpu_;
};

} // namespace pl::gl
