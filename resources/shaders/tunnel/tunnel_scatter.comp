#version 430
// The counting sort's second half: each moved particle that stayed goes to start[cell] + its slot in the
// sorted buffers. The first invocation records the new count and sizes the next step's move.
layout(local_size_x = 256) in;
#include "common/common.glsl"
#include "common/philox.glsl"
#include "tunnel/tunnel_common.glsl"

uniform uint cellCount;

void main() {
    const uint i = itemIndex();
    if (i == 0u) {
        sortedCount = cellStarts[cellCount];
        const uvec3 groups = groupsOf(sortedCount, 256u);
        moveGroups[0] = groups.x;
        moveGroups[1] = groups.y;
        moveGroups[2] = groups.z;
    }
    if (i >= movedCount) return;
    const uvec2 cell = movedCell[i];
    if (cell.x == kRemoved) return;
    const uint to = cellStarts[cell.x] + cell.y;
    sortedPosition[to] = movedPosition[i];
    sortedVelocity[to] = movedVelocity[i];
    sortedVz[to] = movedVz[i];
}
