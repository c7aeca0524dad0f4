// The tunnel's undo of a step a stop request abandoned (common/StopRequest.h): a step of 4e7 molecules
// takes seconds, and a copy of the whole state before it, put back through restoreState(), took as long
// again. Here the move copies each chunk of molecules just before it moves it (the chunk is then in
// cache), everything else a step changes is per cell, per side or per body, and undoing copies back only
// the chunks the move reached, or swaps the whole arrays back once the move finished.
#include "TunnelModel.h"

#include "common/Parallel.h"

namespace pl {

bool TunnelModel::keepStepStart() {
    // The GPU twin steps on the device, which no stop request interrupts: it is kept whole.
    if (backend() != "cpu") return false;
    StepStart& k = stepStart_;
    k.keeping = true;
    k.moved = k.sorted = false;
    k.chunkKept.clear();
    k.cellStart = cellStart_;
    k.remainder = remainder_;
    k.cellSigmaCrMax = cellSigmaCrMax_;
    k.inflowRemainder = inflowRemainder_;
    k.openFraction = openFraction_;
    k.obstacles = obstacles_;
    k.obstacleDrive = obstacleDrive_;
    k.pistonDrive = pistonDrive_;
    k.pistonX = pistonX_;
    k.pistonVelocity = pistonVelocity_;
    k.sigmaCrMax = sigmaCrMax_;
    k.pistonExperiment = pistonExperiment_;
    k.sampleFrom = sampleFrom_;
    k.collisionsThisStep = collisionsThisStep_;
    k.sampler = sampler_;
    return true;
}

void TunnelModel::keepChunk(std::size_t c, std::size_t first, std::size_t end) {
    TunnelState& kept = stepStart_.molecules;
    std::copy(state_.x.begin() + first, state_.x.begin() + end, kept.x.begin() + first);
    std::copy(state_.y.begin() + first, state_.y.begin() + end, kept.y.begin() + first);
    std::copy(state_.vx.begin() + first, state_.vx.begin() + end, kept.vx.begin() + first);
    std::copy(state_.vy.begin() + first, state_.vy.begin() + end, kept.vy.begin() + first);
    std::copy(state_.vz.begin() + first, state_.vz.begin() + end, kept.vz.begin() + first);
    std::copy(state_.cell.begin() + first, state_.cell.begin() + end, kept.cell.begin() + first);
    stepStart_.chunkKept[c] = 1;
}

void TunnelModel::undoStep() {
    StepStart& k = stepStart_;
    if (!k.keeping) return; // the step finished: there is nothing to undo
    k.keeping = false;
    TunnelState& kept = k.molecules;
    if (k.moved) {
        // After the move the inflow appended, the sort dropped and reordered, the collisions changed
        // velocities: the arrays of the step's start replace them whole.
        state_.x.swap(kept.x), state_.y.swap(kept.y);
        state_.vx.swap(kept.vx), state_.vy.swap(kept.vy), state_.vz.swap(kept.vz);
        state_.cell.swap(kept.cell);
    } else {
        // The move stopped half way (the molecules are where they were, in number and order): the
        // chunks it reached go back.
        const std::size_t chunks = k.chunkKept.size();
        const std::size_t n = state_.size();
        const std::size_t chunk = k.chunkSize;
        const bool parallel = static_cast<long long>(n) >= kParallelMinParticles;
#pragma omp parallel for schedule(static) if (parallel)
        for (std::size_t c = 0; c < chunks; ++c) {
            if (!k.chunkKept[c]) continue;
            const std::size_t first = c * chunk, end = std::min(n, first + chunk);
            std::copy(kept.x.begin() + first, kept.x.begin() + end, state_.x.begin() + first);
            std::copy(kept.y.begin() + first, kept.y.begin() + end, state_.y.begin() + first);
            std::copy(kept.vx.begin() + first, kept.vx.begin() + end, state_.vx.begin() + first);
            std::copy(kept.vy.begin() + first, kept.vy.begin() + end, state_.vy.begin() + first);
            std::copy(kept.vz.begin() + first, kept.vz.begin() + end, state_.vz.begin() + first);
            std::copy(kept.cell.begin() + first, kept.cell.begin() + end, state_.cell.begin() + first);
        }
    }
    if (k.sorted) order_.swap(k.order);
    cellStart_ = k.cellStart;
    remainder_ = k.remainder;
    cellSigmaCrMax_ = k.cellSigmaCrMax;
    inflowRemainder_ = k.inflowRemainder;
    openFraction_ = k.openFraction;
    obstacles_ = k.obstacles;
    obstacleDrive_ = k.obstacleDrive;
    pistonDrive_ = k.pistonDrive;
    pistonX_ = k.pistonX;
    pistonVelocity_ = k.pistonVelocity;
    sigmaCrMax_ = k.sigmaCrMax;
    pistonExperiment_ = k.pistonExperiment;
    sampleFrom_ = k.sampleFrom;
    collisionsThisStep_ = k.collisionsThisStep;
    sampler_ = k.sampler;
    stateEdited();
}

} // namespace pl
