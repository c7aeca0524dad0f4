#version 430
// Algorithm 1, lines 5–7 (FluidModel::findNeighbours): the neighbours of each particle within the search
// radius of its prediction, found once a step and kept through the iterations and the velocity stage, as
// on the CPU. Neighbour k of particle i is entry k · count + i, so that the invocations of a work group,
// reading their k-th neighbours together, read one contiguous block. A particle with more neighbours than
// the list holds keeps only its count (the pair passes scan its cells instead: fluid_neighbour_walk.glsl)
// and raises status[1] to that count, so that the host can make the list longer.
layout(local_size_x = 128) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "common/cell_rows.glsl"

layout(std430, binding = 0) readonly buffer Predicted { vec2 p[]; };
layout(std430, binding = 10) buffer Status { uint status[]; }; // [1]: the most neighbours of one particle
layout(std430, binding = 12) writeonly buffer NeighbourCounts { uint neighbourCount[]; };
layout(std430, binding = 13) writeonly buffer NeighbourList { uint neighbourList[]; };

uniform uint count, neighbourCapacity;
uniform float searchRadius2; // (neighbour factor · h)²

void main() {
    const uint i = itemIndex();
    if (i >= count) return;
    const vec2 pi = p[i];
    const ivec2 c = cellCoord(pi);
    uint found = 0u;
    for (int dy = -cellReach; dy <= cellReach; ++dy) {
        const uvec2 range = cellRowRange(c, dy);
        for (uint j = range.x; j < range.y; ++j) {
            const vec2 d = pi - p[j];
            if (dot(d, d) >= searchRadius2 || j == i) continue;
            if (found < neighbourCapacity) neighbourList[found * count + i] = j;
            ++found;
        }
    }
    neighbourCount[i] = found;
    if (found > neighbourCapacity) atomicMax(status[1], found);
}
