// The fluid on the GPU: the CPU model's parameters, presets, tools and observables, with Algorithm 1's
// passes (predict + counting sort, λ, Δx, velocities, vorticity, XSPH) as OpenGL 4.3 compute shaders in
// float32, in gather form over the cell-ordered particles. The CPU state is brought up to date only
// when something reads it.
#pragma once

#include "GlContext.h"
#include "pbf/PbfModel.h"

#include <memory>

namespace pl::gl {

struct PbfGpu;

class PbfModelGL : public PbfModel {
public:
    explicit PbfModelGL(std::shared_ptr<GlContext> context); // throws GlUnavailable or ShaderError
    ~PbfModelGL() override;

    void step() override;
    std::string backend() const override { return "gl"; }
    void finishPendingWork() const override; // glFinish in the model's context
    SceneView sceneViewSharingGpu() const override;
    const ContextInfo& contextInfo() const;
    int dispatchesLastStep() const;

protected:
    void pullState() const override;
    void stateEdited() override;

private:
    void upload();
    void setCommonUniforms(class ComputeProgram& p) const;
    void checkGpuHealth();

    std::unique_ptr<PbfGpu> gpu_;
};

} // namespace pl::gl
