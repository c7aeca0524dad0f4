#version 430
// Move (docs/wind-tunnel.md#move): one invocation per particle pushes it out of any body moved onto it,
// flies it for the step (tunnel_fly.glsl), and counts it into the cell it ends in (the counting sort's
// first half; a molecule that left gets no cell).
layout(local_size_x = 256) in;
#include "common/common.glsl"
#include "common/philox.glsl"
#include "common/obstacles.glsl"
#include "tunnel/tunnel_common.glsl"
#include "tunnel/tunnel_fly.glsl"

void main() {
    const uint i = itemIndex();
    clearImpulses();
    barrier();
    if (i < sortedCount) {
        vec2 p = sortedPosition[i];
        vec3 v = vec3(sortedVelocity[i], sortedVz[i]);
        if (obstacleCount > 0u) pushOutOfBodies(p, v);
        const bool inside = fly(p, v, 0.0, i);
        movedPosition[i] = p;
        movedVelocity[i] = v.xy;
        movedVz[i] = v.z;
        if (inside) {
            const uint c = cellOf(p);
            movedCell[i] = uvec2(c, atomicAdd(cellCounts[c], 1u));
        } else {
            movedCell[i] = uvec2(kRemoved, 0u);
        }
    }
    barrier();
    flushImpulses();
}
