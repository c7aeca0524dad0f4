// The lazy CPU ↔ GPU hand-over every GPU model shares. The CPU model's state is what the CPU code reads
// and edits; the GPU keeps its own copy while it steps. This tracks which copy is current, so the GPU
// copy goes down only when the CPU code reads it (pullState) and up only after the CPU code changed it
// (stateEdited, then pushState before the next GPU step). A GPU model derives from GpuHandOver<CpuModel>
// and supplies upload(), download() and finishPendingWork() (this header stays free of GL headers, so
// that Qt code may include a GPU model's header).
#pragma once

#include "GlContext.h"

#include <memory>
#include <string>
#include <utility>

namespace pl::gl {

template <class CpuModel> class GpuHandOver : public CpuModel {
public:
    std::string backend() const override { return "gl"; }
    const ContextInfo& contextInfo() const { return context_->info(); }

protected:
    // The CPU model starts empty: the GPU model resets once, when its buffers exist.
    explicit GpuHandOver(std::shared_ptr<GlContext> context)
        : CpuModel(typename CpuModel::DeferReset{}), context_(std::move(context)) {
        context_->makeCurrent();
    }

    // Copies the CPU state into fresh GPU buffers (the context is current).
    virtual void upload() = 0;
    // Copies the GPU state into the CPU state (the context is current; only the GPU copy was current).
    virtual void download() const = 0;

    void pullState() const final {
        if (cpuCurrent_ || !gpuCurrent_) return;
        context_->makeCurrent();
        download();
        cpuCurrent_ = true;
    }
    void stateEdited() final { gpuCurrent_ = false; }
    // Before a GPU step: uploads the CPU state when the CPU code changed it. Returns true when it did.
    bool pushState() {
        if (gpuCurrent_) return false;
        upload();
        gpuCurrent_ = cpuCurrent_ = true;
        return true;
    }
    // After a GPU step: only the GPU copy is current now.
    void steppedOnGpu() { cpuCurrent_ = false; }
    // The GPU buffers hold the state (the GPU's observables and histograms may read them).
    bool gpuCurrent() const { return gpuCurrent_; }
    // A viewport sharing the context may draw the particles straight from the buffers: they hold the
    // latest state and the CPU copy does not.
    bool drawsFromGpu() const { return context_->sharesWithViewports() && gpuCurrent_ && !cpuCurrent_; }

    std::shared_ptr<GlContext> context_;

private:
    bool gpuCurrent_ = false;        // the GPU buffers hold the latest state
    mutable bool cpuCurrent_ = true; // the CPU state matches the GPU buffers
};

} // namespace pl::gl
