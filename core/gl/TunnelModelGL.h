// The wind tunnel on the GPU: the CPU model's parameters, presets, tools, sampler and observables, with
// the step's passes (move with sides, bodies and piston; inflow; counting sort; NTC collisions and cell
// sums) as OpenGL 4.3 compute shaders in float32. Particles come to the CPU only when something reads
// them; the sampled fields, forces and counts come over on their own, when asked for.
#pragma once

#include "GlContext.h"
#include "GpuHandOver.h"
#include "tunnel/TunnelModel.h"

#include <array>
#include <memory>

namespace pl::gl {

struct TunnelGpu;

class TunnelModelGL : public GpuHandOver<TunnelModel> {
public:
    // Needs a current-able 4.3 context; throws GlUnavailable or ShaderError. Builds the default tunnel.
    explicit TunnelModelGL(std::shared_ptr<GlContext> context);
    // Builds the preset's tunnel: one reset (throws PresetError as reset(preset) does).
    TunnelModelGL(std::shared_ptr<GlContext> context, const Preset& preset);
    ~TunnelModelGL() override;

    void finishPendingWork() const override; // glFinish in the model's context
    std::size_t particleCount() const override;
    SceneView sceneViewSharingGpu() const override;

    int dispatchesLastStep() const;

private:
    void advance(double h) override;
    void afterStep() override;
    void upload() override;
    void download() const override;
    void pullSamples() const override { flushSamples(); }
    // The GPU's cell sums, body impulses and collision counts since the last hand-over go to the CPU
    // sampler, step by step as the CPU model hands them over (TunnelModel::step).
    void flushSamples() const;
    // Entering particles per side this step (TunnelModel::admitInflow's count, same remainders).
    std::array<double, 4> expectedInflow(double h) const;
    std::array<unsigned, 4> inflowCounts(double h);
    void ensureCapacity(std::size_t entering);
    void uploadCellArrays();
    void bindAll() const;
    void setCommonUniforms(class ComputeProgram& program, double h) const;

    std::unique_ptr<TunnelGpu> gpu_;
};

} // namespace pl::gl
