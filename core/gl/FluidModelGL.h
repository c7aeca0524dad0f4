// The fluid on the GPU: the CPU model's parameters, presets, tools and observables, with Algorithm 1's
// passes (predict + counting sort, the neighbour search, λ, Δx, velocities, vorticity, XSPH) as OpenGL 4.3
// compute shaders in float32, in gather form over the cell-ordered particles. The CPU state is brought up to
// date only when something reads it.
#pragma once

#include "GlContext.h"
#include "GpuHandOver.h"
#include "fluid/FluidModel.h"

#include <memory>

namespace pl::gl {

struct FluidGpu;

class FluidModelGL : public GpuHandOver<FluidModel> {
public:
    // Needs a current-able 4.3 context; throws GlUnavailable or ShaderError. Builds the default tank.
    explicit FluidModelGL(std::shared_ptr<GlContext> context);
    // Builds the preset's tank: one reset (throws PresetError as reset(preset) does).
    FluidModelGL(std::shared_ptr<GlContext> context, const Preset& preset);
    ~FluidModelGL() override;

    void finishPendingWork() const override; // glFinish in the model's context
    SceneView sceneViewSharingGpu() const override;
    int dispatchesLastStep() const;
    // Neighbours each particle's list holds now: it grows at a health check after particles had more.
    unsigned neighbourListLength() const;

private:
    void advance(double h) override;
    void afterStep() override;
    void createBuffers();
    void upload() override;
    // Also brings the per-iteration errors of the last GPU step to the CPU.
    void download() const override;
    void setCommonUniforms(class ComputeProgram& p) const;
    void checkGpuHealth();

    std::unique_ptr<FluidGpu> gpu_;
};

} // namespace pl::gl
