#version 430
// Force stage of the gas in cell order (GasModel::computeForcesNeighbourList): the 3×3 cells around each
// disk, gather form (only disk i's invocations write disk i). The kick that follows the forces is left to
// the next drift (GasModelGL keeps it as a pending kick), so no invocation writes what another reads.
//
// lanesPerDisk invocations share a disk: lane k takes candidates k, k + lanes, … of the disk's three cell
// rows, and lane 0 adds the lanes' sums in lane order. A small gas (4096 disks: 32 work groups of 128
// with one lane) would leave most of a large GPU idle while each invocation waits on ~18 dependent
// loads; with 8 lanes it runs on 256 groups, ~2 candidates each.
//
// Tiles: a work group's disks are consecutive in cell order, from cell a to cell b. For each of the three
// rows of cells around a disk, the cells all the group's disks need are one contiguous run in cell order,
// from (a.x − 1, a.y − 1 + k) to (b.x + 1, b.y − 1 + k), even when the group spans rows of cells. The
// group copies those three runs' positions and species into shared memory, adjacent invocations reading
// adjacent disks, and every disk reads its ~18 candidates from there instead of with one scattered
// global load each. The candidates and the order they are summed in are the same either way: the
// forces are the same bits. A group whose runs exceed the tile reads globally.
layout(local_size_x = 128) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "gas/gas_kernels.glsl"

layout(std430, binding = 0) readonly buffer Pos { vec2 pos[]; };
layout(std430, binding = 1) readonly buffer Vel { vec2 vel[]; };
layout(std430, binding = 2) writeonly buffer Acc { vec2 acc[]; };
layout(std430, binding = 3) readonly buffer Tag { uint tag[]; };
layout(std430, binding = 8) readonly buffer CellStarts { uint cellStarts[]; };
layout(std430, binding = 10) buffer Status { uint status[]; }; // [1]: contacts begun (each pair twice),
                                                               // [2]: groups that read from tiles
layout(std430, binding = 12) writeonly buffer Energy { vec2 energy[]; }; // (½ Σ U, ¼ Σ r·f) per disk

uniform uint count;
uniform uint lanesPerDisk; // a power of two up to 32: divides the work group
uniform float stiffness, gravity;
uniform vec2 speciesDiameter, speciesInverseMass;
uniform float maxContact; // the largest contact distance present [L]
uniform bool countContacts, energies;
uniform float backtrackH; // contacts begun: the pair was apart at x − h v (one step back)
uniform bool useTiles, countTiles;

// Each run holds the group's 128 disks' span of cells and two more, ~3 × 132 disks in all at ~2 a cell.
// 512 leaves room for uneven rows in 4 KB: a small footprint keeps many groups on a multiprocessor.
// Only positions: a candidate's species is read for the few within reach. After the pairs, the tile
// holds the lanes' sums (2 entries a lane).
const uint kTileCapacity = 512u;
shared vec2 tilePos[kTileCapacity];
shared uint tileFirst[3];  // first disk of each tile row
shared uint tileOffset[4]; // where each row starts in the tile; [3]: the tile's size
shared bool tiled;

shared uint groupBegan;

// The disks of cells x0 … x1 of row y: [first, last) in cell order, empty outside the grid.
uvec2 rowRange(int x0, int x1, int y) {
    if (y < 0 || y >= cellDims.y) return uvec2(0u);
    const uint first = cellStarts[cellIndex(ivec2(max(x0, 0), y))];
    return uvec2(first, cellStarts[cellIndex(ivec2(min(x1, cellDims.x - 1), y)) + 1u]);
}

// The disks from cell (x0, y0) to cell (x1, y1) in cell order, clipped to the grid.
uvec2 runRange(int x0, int y0, int x1, int y1) {
    const int cells = cellDims.x * cellDims.y;
    const int first = max(y0 * cellDims.x + max(x0, 0), 0);
    const int last = min(y1 * cellDims.x + min(x1, cellDims.x - 1), cells - 1);
    if (last < first) return uvec2(0u);
    return uvec2(cellStarts[first], cellStarts[last + 1]);
}

// Invocation 0 finds the group's three runs and whether they fit the tile.
void planTile() {
    tiled = false;
    const uint groupFirst = workgroupIndex() * gl_WorkGroupSize.x / lanesPerDisk;
    if (!useTiles || groupFirst >= count) return;
    const uint groupLast = min((workgroupIndex() + 1u) * gl_WorkGroupSize.x / lanesPerDisk, count) - 1u;
    const ivec2 a = cellCoord(pos[groupFirst]), b = cellCoord(pos[groupLast]);
    uint size = 0u;
    for (int k = 0; k < 3; ++k) {
        const uvec2 run = runRange(a.x - 1, a.y - 1 + k, b.x + 1, b.y - 1 + k);
        tileFirst[k] = run.x;
        tileOffset[k] = size;
        size += run.y - run.x;
    }
    tileOffset[3] = size;
    tiled = size <= kTileCapacity;
}

void fillTile() {
    for (uint n = gl_LocalInvocationID.x; n < tileOffset[3]; n += gl_WorkGroupSize.x) {
        const uint k = n < tileOffset[1] ? 0u : (n < tileOffset[2] ? 1u : 2u);
        const uint j = tileFirst[k] + (n - tileOffset[k]);
        tilePos[n] = pos[j];
    }
}

// One disk's candidates: its three rows of cells, each one contiguous range [first, first + count) in
// cell order, and where each begins in the tile when there is one.
struct Candidates {
    uvec2 rows[3];
    uint inTile[3];
    uint total;
};

Candidates candidatesOf(ivec2 c) {
    Candidates s;
    s.total = 0u;
    for (int k = 0; k < 3; ++k) {
        const uvec2 range = rowRange(c.x - 1, c.x + 1, c.y - 1 + k);
        s.rows[k] = uvec2(range.x, range.y - range.x);
        s.inTile[k] = tiled ? tileOffset[k] + (range.x - tileFirst[k]) : 0u;
        s.total += s.rows[k].y;
    }
    return s;
}

// (f, ½ U, ¼ r·f) of disk i from this lane's share of its candidates. Called with a constant fromTile,
// so that each copy reads only shared or only global memory: a select between the two would issue both
// loads.
vec4 pairSums(uint i, vec2 xi, vec2 vi, float di, Candidates s, uint lane, const bool fromTile,
              inout uint began) {
    vec4 sums = vec4(0.0);
    for (uint n = lane; n < s.total; n += lanesPerDisk) {
        // Constant indices only: an array indexed by a variable would live in local memory.
        uint j, slot;
        if (n < s.rows[0].y) {
            j = s.rows[0].x + n;
            slot = s.inTile[0] + n;
        } else if (n < s.rows[0].y + s.rows[1].y) {
            j = s.rows[1].x + (n - s.rows[0].y);
            slot = s.inTile[1] + (n - s.rows[0].y);
        } else {
            j = s.rows[2].x + (n - s.rows[0].y - s.rows[1].y);
            slot = s.inTile[2] + (n - s.rows[0].y - s.rows[1].y);
        }
        if (j == i) continue;
        const vec2 d = xi - (fromTile ? tilePos[slot] : pos[j]);
        // Most candidates are out of reach of any disk: reject them before reading their species.
        if (dot(d, d) >= maxContact * maxContact) continue;
        const float dij = contactDiameter(di, speciesDiameter[tag[j] & 1u]);
        PairResult pair;
        if (!harmonicPair(d, dij, stiffness, pair)) continue;
        sums += vec4(pair.f, 0.5 * pair.potential, 0.25 * pair.virial); // each pair seen from both ends
        if (countContacts) {
            const vec2 before = d - backtrackH * (vi - vel[j]);
            began += dot(before, before) >= dij * dij ? 1u : 0u;
        }
    }
    return sums;
}

void main() {
    const uint t = gl_LocalInvocationID.x;
    const uint i = itemIndex() / lanesPerDisk, lane = itemIndex() % lanesPerDisk;
    if (t == 0u) {
        groupBegan = 0u;
        planTile();
    }
    barrier();
    if (tiled) fillTile();
    barrier();
    vec4 sums = vec4(0.0);
    if (i < count) {
        const vec2 xi = pos[i];
        const float di = speciesDiameter[tag[i] & 1u];
        const vec2 vi = vel[i];
        const Candidates s = candidatesOf(cellCoord(xi));
        uint began = 0u;
        if (tiled)
            sums = pairSums(i, xi, vi, di, s, lane, true, began);
        else
            sums = pairSums(i, xi, vi, di, s, lane, false, began);
        if (began > 0u) atomicAdd(groupBegan, began);
    }
    barrier(); // every lane is done with the tile
    tilePos[2u * t] = sums.xy;
    tilePos[2u * t + 1u] = sums.zw;
    barrier();
    if (i < count && lane == 0u) {
        for (uint k = 1u; k < lanesPerDisk; ++k) sums += vec4(tilePos[2u * (t + k)], tilePos[2u * (t + k) + 1u]);
        acc[i] = sums.xy * speciesInverseMass[tag[i] & 1u] - vec2(0.0, gravity);
        if (energies) energy[i] = sums.zw;
    }
    barrier();
    if (t == 0u && groupBegan > 0u) atomicAdd(status[1], groupBegan);
    if (t == 0u && tiled && countTiles) atomicAdd(status[2], 1u);
}
