#version 430
// Drift stage of the gas fused with the counting sort (GasModel::driftStage): v += kickBefore a;
// x += h v; walls and obstacles; v += kickAfter a. Run twice per drift: first to count each disk into
// its cell (slot from an atomic), then, after the prefix sum, to recompute the same drift and write the
// disk straight into its cell-ordered place. Recomputing costs less than storing the drifted state.
layout(local_size_x = 256) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "gas/gas_boundaries.glsl"

layout(std430, binding = 0) readonly buffer PosIn { vec2 posIn[]; };
layout(std430, binding = 1) readonly buffer VelIn { vec2 velIn[]; };
layout(std430, binding = 2) readonly buffer AccIn { vec2 accIn[]; };
layout(std430, binding = 3) readonly buffer TagIn { uint tagIn[]; }; // id << 1 | species
layout(std430, binding = 4) writeonly buffer PosOut { vec2 posOut[]; };
layout(std430, binding = 5) writeonly buffer VelOut { vec2 velOut[]; };
layout(std430, binding = 6) writeonly buffer TagOut { uint tagOut[]; };
layout(std430, binding = 7) buffer CellCounts { uint cellCounts[]; };
layout(std430, binding = 8) readonly buffer CellStarts { uint cellStarts[]; };
layout(std430, binding = 9) buffer CellSlots { uvec2 cellSlots[]; }; // (cell, slot in cell)
layout(std430, binding = 10) buffer Status { uint status[]; };      // [0]: a disk escaped or is NaN
layout(std430, binding = 11) buffer ImpulseSums { float impulseSums[]; }; // per work group, since sampled

uniform uint count;
uniform float kickBefore, kickAfter;
uniform bool scatterPass;

shared float groupImpulse[256];

void main() {
    const uint i = itemIndex();
    float impulse = 0.0;
    if (i < count) {
        const uint tag = tagIn[i];
        const vec2 a = accIn[i];
        vec2 v = velIn[i] + kickBefore * a;
        vec2 x = posIn[i] + driftH * v;
        const bool ok = applyBoundaries(x, v, int(tag & 1u), tag >> 1, impulse);
        v += kickAfter * a;
        if (!scatterPass) {
            const uint cell = cellIndex(cellCoord(x));
            cellSlots[i] = uvec2(cell, atomicAdd(cellCounts[cell], 1u));
        } else {
            const uvec2 cs = cellSlots[i];
            const uint target = cellStarts[cs.x] + cs.y;
            posOut[target] = x;
            velOut[target] = v;
            tagOut[target] = tag;
            if (!ok) atomicOr(status[0], 1u);
        }
    }
    if (!scatterPass) return;
    // Wall impulse: summed in the group, added to the group's slot (no float atomics in GL 4.3).
    groupImpulse[gl_LocalInvocationID.x] = impulse;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1) {
        if (gl_LocalInvocationID.x < stride)
            groupImpulse[gl_LocalInvocationID.x] += groupImpulse[gl_LocalInvocationID.x + stride];
        barrier();
    }
    if (gl_LocalInvocationID.x == 0u && groupImpulse[0] != 0.0) impulseSums[workgroupIndex()] += groupImpulse[0];
}
