// The neighbours of fluid_neighbours.comp as the pair passes walk them (needs common/cells.glsl,
// common/cell_rows.glsl and the pass's `count`):
//     const NeighbourWalk walk = neighbourWalk(i, pi);
//     for (uint k = 0u; k < walk.length; ++k) { const uint j = neighbourAt(walk, i, k); … }
// A particle whose neighbours did not fit the list walks the candidates of its cell rows around pi
// instead, as every pass did before the list: the passes test r < h either way, so both walks give every
// pair within h of the step's neighbours, and the rare long walk costs only the particles that need it.
layout(std430, binding = 12) readonly buffer NeighbourCounts { uint neighbourCount[]; };
layout(std430, binding = 13) readonly buffer NeighbourList { uint neighbourList[]; };
uniform uint neighbourCapacity;

const int kMaxCellRows = 5; // 2 · cellReach + 1 with cellReach = 2 (FluidModelGL.cpp)

struct NeighbourWalk {
    uint length;
    bool listed;
    uvec2 rows[kMaxCellRows]; // (first, length) of each cell row, when not listed
};

NeighbourWalk neighbourWalk(uint i, vec2 pi) {
    NeighbourWalk walk;
    walk.length = neighbourCount[i];
    walk.listed = walk.length <= neighbourCapacity;
    if (walk.listed) return walk; // rows unused
    const ivec2 c = cellCoord(pi);
    walk.length = 0u;
    for (int r = 0; r < kMaxCellRows; ++r) {
        const uvec2 range = r <= 2 * cellReach ? cellRowRange(c, r - cellReach) : uvec2(0u);
        walk.rows[r] = uvec2(range.x, range.y - range.x);
        walk.length += walk.rows[r].y;
    }
    return walk;
}

uint neighbourAt(NeighbourWalk walk, uint i, uint k) {
    if (walk.listed) return neighbourList[k * count + i];
    for (int r = 0; r < kMaxCellRows; ++r) {
        if (k < walk.rows[r].y) return walk.rows[r].x + k;
        k -= walk.rows[r].y;
    }
    return i; // not reached: k < walk.length
}
