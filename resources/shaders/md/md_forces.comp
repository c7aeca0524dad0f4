#version 430
// Force stage of the gas in cell order (MdModel::computeForcesNeighbourList): the 3×3 cells around each
// disk, gather form (invocation i writes only disk i). The kick that follows the forces is left to the
// next drift (MdModelGL keeps it as a pending kick), so no invocation writes what another reads.
layout(local_size_x = 128) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "md/md_kernels.glsl"

layout(std430, binding = 0) readonly buffer Pos { vec2 pos[]; };
layout(std430, binding = 1) readonly buffer Vel { vec2 vel[]; };
layout(std430, binding = 2) writeonly buffer Acc { vec2 acc[]; };
layout(std430, binding = 3) readonly buffer Tag { uint tag[]; };
layout(std430, binding = 8) readonly buffer CellStarts { uint cellStarts[]; };
layout(std430, binding = 10) buffer Status { uint status[]; }; // [1]: contacts begun (each pair twice)
layout(std430, binding = 12) writeonly buffer Energy { vec2 energy[]; }; // (½ Σ U, ¼ Σ r·f) per disk

uniform uint count;
uniform float stiffness, gravity;
uniform vec2 speciesDiameter, speciesInverseMass;
uniform float maxContact; // the largest contact distance present [L]
uniform bool countContacts, energies;
uniform float backtrackH; // contacts begun: the pair was apart at x − h v (one step back)

shared uint groupBegan;

void main() {
    const uint i = itemIndex();
    if (gl_LocalInvocationID.x == 0u) groupBegan = 0u;
    barrier();
    if (i < count) {
        const vec2 xi = pos[i];
        const uint si = tag[i] & 1u;
        const float di = speciesDiameter[si];
        const vec2 vi = vel[i];
        const ivec2 c = cellCoord(xi);
        vec2 f = vec2(0.0);
        float potential = 0.0, virial = 0.0;
        uint began = 0u;
        for (int cy = max(c.y - 1, 0); cy <= min(c.y + 1, cellDims.y - 1); ++cy) {
            const uint rowFirst = cellIndex(ivec2(max(c.x - 1, 0), cy));
            const uint rowLast = cellIndex(ivec2(min(c.x + 1, cellDims.x - 1), cy));
            // The cells of one row are contiguous in cell order: one range per row.
            for (uint j = cellStarts[rowFirst]; j < cellStarts[rowLast + 1u]; ++j) {
                if (j == i) continue;
                const vec2 d = xi - pos[j];
                // Most candidates are out of reach of any disk: reject them before reading their tag.
                if (dot(d, d) >= maxContact * maxContact) continue;
                const float dij = contactDiameter(di, speciesDiameter[tag[j] & 1u]);
                PairResult pair;
                if (!harmonicPair(d, dij, stiffness, pair)) continue;
                f += pair.f;
                potential += 0.5 * pair.potential; // each pair is visited from both ends
                virial += 0.25 * pair.virial;
                if (countContacts) {
                    const vec2 before = d - backtrackH * (vi - vel[j]);
                    began += dot(before, before) >= dij * dij ? 1u : 0u;
                }
            }
        }
        acc[i] = f * speciesInverseMass[si] - vec2(0.0, gravity);
        if (energies) energy[i] = vec2(potential, virial);
        if (began > 0u) atomicAdd(groupBegan, began);
    }
    barrier();
    if (gl_LocalInvocationID.x == 0u && groupBegan > 0u) atomicAdd(status[1], groupBegan);
}
