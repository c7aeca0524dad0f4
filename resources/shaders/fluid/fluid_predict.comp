#version 430
// Algorithm 1, lines 1–4, fused with the counting sort (FluidModel::applyExternalForcesAndPredict):
// v ← v + Δt g; x* ← x + Δt v, confined. The count pass counts each particle into the cell of x*;
// the scatter pass recomputes the same prediction and writes x, v and x* in cell order.
layout(local_size_x = 256) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "fluid/fluid_boundaries.glsl"

layout(std430, binding = 0) readonly buffer PosIn { vec2 posIn[]; };
layout(std430, binding = 1) readonly buffer VelIn { vec2 velIn[]; };
layout(std430, binding = 4) writeonly buffer PosOut { vec2 posOut[]; };
layout(std430, binding = 5) writeonly buffer VelOut { vec2 velOut[]; };
layout(std430, binding = 6) writeonly buffer Predicted { vec2 predicted[]; };
layout(std430, binding = 7) buffer CellCounts { uint cellCounts[]; };
layout(std430, binding = 9) buffer CellSlots { uvec2 cellSlots[]; };
layout(std430, binding = 11) readonly buffer CellStartsIn { uint cellStartsIn[]; };

uniform uint count;
uniform float dt;
uniform vec2 gravity;
uniform bool scatterPass;

void main() {
    const uint i = itemIndex();
    if (i >= count) return;
    const vec2 v = velIn[i] + dt * gravity;
    vec2 p = posIn[i] + dt * v;
    confine(i, p);
    if (!scatterPass) {
        const uint cell = cellIndex(cellCoord(p));
        cellSlots[i] = uvec2(cell, atomicAdd(cellCounts[cell], 1u));
        return;
    }
    const uvec2 cs = cellSlots[i];
    const uint target = cellStartsIn[cs.x] + cs.y;
    posOut[target] = posIn[i];
    velOut[target] = v;
    predicted[target] = p;
}
