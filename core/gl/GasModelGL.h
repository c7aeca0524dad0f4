// The gas on the GPU: the CPU model's parameters, presets, tools and observables, with the hot stages
// (drift + counting sort, forces, reductions, histograms) as OpenGL 4.3 compute shaders in float32.
// The CPU state is brought up to date only when something reads it (pullState).
#pragma once

#include "GlContext.h"
#include "GpuHandOver.h"
#include "gas/GasModel.h"

#include <memory>

namespace pl::gl {

struct GasGpu;
class GpuCellGrid;

class GasModelGL : public GpuHandOver<GasModel> {
public:
    // Needs a current-able 4.3 context; throws GlUnavailable or ShaderError. Builds the default gas.
    explicit GasModelGL(std::shared_ptr<GlContext> context);
    // Builds the preset's gas: one reset (throws PresetError as reset(preset) does).
    GasModelGL(std::shared_ptr<GlContext> context, const Preset& preset);
    ~GasModelGL() override;

    void finishPendingWork() const override; // glFinish in the model's context
    GasObservables observe() override;
    double totalEnergy() override;
    std::vector<NamedHistogram> histograms() const override;
    SceneView sceneViewSharingGpu() const override;

    // Whether the current settings run on the GPU (rk4 and the all-pairs comparison run on the CPU).
    bool stepsOnGpu() const;
    // Dispatches issued by the last step (for the benchmark's cost accounting).
    int dispatchesLastStep() const;
    // GPU time of each pass of the next steps, from timestamp queries (costs a sync per step).
    void setProfiling(bool on);
    // Pass name → nanoseconds, summed over the steps since profiling was switched on.
    std::vector<std::pair<std::string, double>> profile() const;
    // The counting-sort grid of the last step (tests check the order against it).
    const GpuCellGrid& cellGrid() const;
    // Invocations that share a disk in the force pass (gas_forces.comp): a power of two up to 32, or 0
    // (the default) to choose by the gas's size, one on a software rasteriser, whose invocations run on
    // the CPU's few cores. Throws std::invalid_argument for other counts. For the benchmark and the tests.
    void setForceLanesPerDisk(unsigned lanes);
    unsigned forceLanesPerDisk() const; // what the next force pass uses

private:
    void advance(double h) override;
    void afterStep() override;
    void createBuffers();
    void upload() override;
    void download() const override;
    void drift(double kickBefore, double h, double kickAfter);
    void forces(bool countContacts, double kick, bool energies = false);
    GasSums gpuSums(); // energies and reductions at the current positions
    void checkGpuHealth();

    std::unique_ptr<GasGpu> gpu_;
    unsigned forceLanes_ = 0; // 0: automatic
};

} // namespace pl::gl
