#version 430
// Force stage of the gas in cell order (GasModel::computeForcesNeighbourList): the 3×3 cells around each
// disk, gather form (only disk i's invocations write disk i). The kick that follows the forces is left to
// the next drift (GasModelGL keeps it as a pending kick), so no invocation writes what another reads.
//
// lanesPerDisk invocations share a disk: lane k takes candidates k, k + lanes, … of the disk's three cell
// rows, and lane 0 adds the lanes' sums in lane order. A small gas (4096 disks: 32 work groups of 128
// with one lane) would leave most of a large GPU idle while each invocation waits on ~18 dependent
// loads; with 8 lanes it runs on 256 groups, ~2 candidates each.
layout(local_size_x = 128) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "gas/gas_kernels.glsl"

layout(std430, binding = 0) readonly buffer Pos { vec2 pos[]; };
layout(std430, binding = 1) readonly buffer Vel { vec2 vel[]; };
layout(std430, binding = 2) writeonly buffer Acc { vec2 acc[]; };
layout(std430, binding = 3) readonly buffer Tag { uint tag[]; };
layout(std430, binding = 8) readonly buffer CellStarts { uint cellStarts[]; };
layout(std430, binding = 10) buffer Status { uint status[]; }; // [1]: contacts begun (each pair twice)
layout(std430, binding = 12) writeonly buffer Energy { vec2 energy[]; }; // (½ Σ U, ¼ Σ r·f) per disk

uniform uint count;
uniform uint lanesPerDisk; // a power of two up to 32: divides the work group
uniform float stiffness, gravity;
uniform vec2 speciesDiameter, speciesInverseMass;
uniform float maxContact; // the largest contact distance present [L]
uniform bool countContacts, energies;
uniform float backtrackH; // contacts begun: the pair was apart at x − h v (one step back)

shared uint groupBegan;
shared vec4 laneSums[128]; // (f, ½ U, ¼ r·f) of each lane

void main() {
    const uint t = gl_LocalInvocationID.x;
    const uint i = itemIndex() / lanesPerDisk, lane = itemIndex() % lanesPerDisk;
    if (t == 0u) groupBegan = 0u;
    barrier();
    vec4 sums = vec4(0.0);
    if (i < count) {
        const vec2 xi = pos[i];
        const uint si = tag[i] & 1u;
        const float di = speciesDiameter[si];
        const vec2 vi = vel[i];
        const ivec2 c = cellCoord(xi);
        // The disk's three rows of cells, each one contiguous range in cell order.
        uvec2 rows[3];
        uint candidates = 0u;
        for (int k = 0; k < 3; ++k) {
            const int cy = c.y - 1 + k;
            rows[k] = uvec2(0u);
            if (cy < 0 || cy >= cellDims.y) continue;
            const uint first = cellStarts[cellIndex(ivec2(max(c.x - 1, 0), cy))];
            const uint last = cellStarts[cellIndex(ivec2(min(c.x + 1, cellDims.x - 1), cy)) + 1u];
            rows[k] = uvec2(first, last - first);
            candidates += last - first;
        }
        uint began = 0u;
        for (uint n = lane; n < candidates; n += lanesPerDisk) {
            uint j;
            if (n < rows[0].y) j = rows[0].x + n;
            else if (n < rows[0].y + rows[1].y) j = rows[1].x + (n - rows[0].y);
            else j = rows[2].x + (n - rows[0].y - rows[1].y);
            if (j == i) continue;
            const vec2 d = xi - pos[j];
            // Most candidates are out of reach of any disk: reject them before reading their tag.
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
        if (began > 0u) atomicAdd(groupBegan, began);
    }
    laneSums[t] = sums;
    barrier();
    if (i < count && lane == 0u) {
        for (uint k = 1u; k < lanesPerDisk; ++k) sums += laneSums[t + k];
        acc[i] = sums.xy * speciesInverseMass[tag[i] & 1u] - vec2(0.0, gravity);
        if (energies) energy[i] = sums.zw;
    }
    barrier();
    if (t == 0u && groupBegan > 0u) atomicAdd(status[1], groupBegan);
}
