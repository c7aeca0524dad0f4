#version 430
// The drift stage and the whole counting sort in one work group, for grids of at most 2047 cells
// (small gases): count into shared memory, scan there, then recompute the drift and scatter. One
// dispatch instead of three: at a few thousand disks a step costs what its dependent dispatches cost.
layout(local_size_x = 1024) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "gas/gas_boundaries.glsl"

layout(std430, binding = 0) readonly buffer PosIn { vec2 posIn[]; };
layout(std430, binding = 1) readonly buffer VelIn { vec2 velIn[]; };
layout(std430, binding = 2) readonly buffer AccIn { vec2 accIn[]; };
layout(std430, binding = 3) readonly buffer TagIn { uint tagIn[]; };
layout(std430, binding = 4) writeonly buffer PosOut { vec2 posOut[]; };
layout(std430, binding = 5) writeonly buffer VelOut { vec2 velOut[]; };
layout(std430, binding = 6) writeonly buffer TagOut { uint tagOut[]; };
layout(std430, binding = 8) writeonly buffer CellStarts { uint cellStarts[]; };
layout(std430, binding = 9) buffer CellSlots { uvec2 cellSlots[]; };
layout(std430, binding = 10) buffer Status { uint status[]; };
layout(std430, binding = 11) buffer ImpulseSums { float impulseSums[]; };

uniform uint count;
uniform float kickBefore, kickAfter;

const uint kThreads = 1024u;
shared uint cellCounts[2048];
shared uint partial[1024];
shared float groupImpulse[1024];

// The drift of GasModel::driftStage for disk i (the same arithmetic in both phases).
bool drifted(uint i, out vec2 x, out vec2 v, inout float impulse) {
    const uint tag = tagIn[i];
    const vec2 a = accIn[i];
    v = velIn[i] + kickBefore * a;
    x = posIn[i] + driftH * v;
    const bool ok = applyBoundaries(x, v, int(tag & 1u), tag >> 1, impulse);
    v += kickAfter * a;
    return ok;
}

void main() {
    const uint t = gl_LocalInvocationID.x;
    const uint cells = uint(cellDims.x * cellDims.y) + 1u; // the last entry stays 0: starts[cells] = N
    for (uint c = t; c < 2048u; c += kThreads) cellCounts[c] = 0u;
    barrier();
    float unused = 0.0;
    for (uint i = t; i < count; i += kThreads) {
        vec2 x, v;
        drifted(i, x, v, unused);
        const uint cell = cellIndex(cellCoord(x));
        cellSlots[i] = uvec2(cell, atomicAdd(cellCounts[cell], 1u)); // read back by this invocation only
    }
    barrier();
    // Exclusive scan of the 2048 counts: two per invocation, Hillis–Steele over the 1024 pair sums.
    const uint first = cellCounts[2u * t], second = cellCounts[2u * t + 1u];
    partial[t] = first + second;
    barrier();
    for (uint offset = 1u; offset < kThreads; offset <<= 1) {
        const uint add = t >= offset ? partial[t - offset] : 0u;
        barrier();
        partial[t] += add;
        barrier();
    }
    const uint start = partial[t] - first - second;
    barrier();
    cellCounts[2u * t] = start; // the counts become the starts
    cellCounts[2u * t + 1u] = start + first;
    if (2u * t < cells) cellStarts[2u * t] = start;
    if (2u * t + 1u < cells) cellStarts[2u * t + 1u] = start + first;
    barrier();
    float impulse = 0.0;
    bool escaped = false;
    for (uint i = t; i < count; i += kThreads) {
        vec2 x, v;
        escaped = !drifted(i, x, v, impulse) || escaped;
        const uvec2 cs = cellSlots[i];
        const uint target = cellCounts[cs.x] + cs.y;
        posOut[target] = x;
        velOut[target] = v;
        tagOut[target] = tagIn[i];
    }
    if (escaped) atomicOr(status[0], 1u);
    groupImpulse[t] = impulse;
    barrier();
    for (uint stride = kThreads / 2u; stride > 0u; stride >>= 1) {
        if (t < stride) groupImpulse[t] += groupImpulse[t + stride];
        barrier();
    }
    if (t == 0u && groupImpulse[0] != 0.0) impulseSums[0] += groupImpulse[0];
}
