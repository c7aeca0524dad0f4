// The wind tunnel's GPU buffers and programs, shared by TunnelModelGL.cpp (hand-over) and
// TunnelStepGL.cpp (the step's passes). Layouts: resources/shaders/tunnel/tunnel_common.glsl.
#pragma once

#include "GlProgram.h"
#include "GpuCellGrid.h"
#include "tunnel/TunnelParams.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace pl::gl {

inline constexpr unsigned kTunnelParticleLocal = 256, kTunnelCellLocal = 64; // the shaders' local sizes
// Steps whose collision counts and body impulses the ring holds; a full ring is handed over.
inline constexpr std::size_t kRingSlots = 256;
inline constexpr std::size_t kRingHeader = 2;     // words before the bodies: collisions, unused
inline constexpr double kImpulseQuantum = 4096.0; // tunnel_common.glsl: fixed-point steps per m/s
inline constexpr std::size_t kSumsPerCell = 7;    // N, Σv, Σv²
// Book words (tunnel_common.glsl): sortedCount, movedCount, moveGroups[3], scatterGroups[3].
inline constexpr std::size_t kBookWords = 8;
inline constexpr GLintptr kMoveGroupsOffset = 2 * sizeof(std::uint32_t);
inline constexpr GLintptr kScatterGroupsOffset = 5 * sizeof(std::uint32_t);

// The SIDE_* codes of tunnel_fly.glsl, from TunnelBoundary.
inline std::string tunnelSideDefines() {
    auto line = [](const char* name, TunnelBoundary b) {
        return std::string("#define ") + name + " " + std::to_string(static_cast<int>(b)) + "\n";
    };
    return line("SIDE_INFLOW", TunnelBoundary::Inflow) + line("SIDE_OUTFLOW", TunnelBoundary::Outflow) +
           line("SIDE_SPECULAR", TunnelBoundary::Specular) + line("SIDE_DIFFUSE", TunnelBoundary::Diffuse) +
           line("SIDE_PERIODIC", TunnelBoundary::Periodic);
}

template <class T> std::vector<float> toFloats(const std::vector<T>& v) {
    return std::vector<float>(v.begin(), v.end());
}

struct TunnelGpu {
    ComputeProgram move{"tunnel/tunnel_move.comp", tunnelSideDefines()},
        inflow{"tunnel/tunnel_inflow.comp", tunnelSideDefines()}, scatter{"tunnel/tunnel_scatter.comp"},
        collide{"tunnel/tunnel_collide.comp"};
    GpuCellGrid prefix; // used as a prefix sum over the tunnel's cells (a row of unit cells)
    // Particles in cell order (sorted) and after the move (moved), the bookkeeping, the step ring, and
    // per cell the NTC remainders, the window sums, the open fractions and (σ c_r)_max.
    Buffer sortedPosition, sortedVelocity, sortedVz, movedPosition, movedVelocity, movedVz, movedCell, book,
        ring, remainders, windowSums, openFractions, cellSigmaCrMax, obstacles;
    std::size_t capacity = 0;   // particles the particle buffers hold
    std::size_t roomWanted = 0; // the least capacity the next upload gives
    std::size_t countBound = 0; // at least the particles on the GPU (exact after a look at the count)
    std::size_t cells = 0;
    std::size_t ringStride = kRingHeader; // words per ring slot
    std::vector<bool> pendingSampled;     // per GPU step since the last hand-over: in the fields window
    std::int64_t pendingSampledSteps = 0;
    std::size_t knownCount = 0;
    bool countKnown = true;
    int dispatches = 0;
};

} // namespace pl::gl
