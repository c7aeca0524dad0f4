#version 430
// Sums of the gas's observables per work group (GasModel::observe's loop), added up in double on the
// CPU: the only readback a sample needs besides the histogram.
layout(local_size_x = 256) in;
#include "common/common.glsl"

layout(std430, binding = 0) readonly buffer Pos { vec2 pos[]; };
layout(std430, binding = 1) readonly buffer Vel { vec2 vel[]; };
layout(std430, binding = 2) readonly buffer Acc { vec2 acc[]; };
layout(std430, binding = 3) readonly buffer Tag { uint tag[]; };
layout(std430, binding = 12) readonly buffer Energy { vec2 energy[]; };
layout(std430, binding = 13) writeonly buffer Sums { float sums[]; }; // kSums per work group

uniform uint count;
uniform float pendingKick; // true velocity = vel + pendingKick · acc
uniform float gravity, bottom;
uniform vec2 speciesMass;

const uint kSums = 9u; // count A, count B, kinetic A, kinetic B, px, py, potential, virial, (unused)
shared float partial[256];

void main() {
    const uint i = itemIndex();
    float values[kSums];
    for (uint k = 0u; k < kSums; ++k) values[k] = 0.0;
    if (i < count) {
        const uint s = tag[i] & 1u;
        const float m = speciesMass[s];
        const vec2 v = vel[i] + pendingKick * acc[i];
        values[s] = 1.0;
        values[2u + s] = 0.5 * m * dot(v, v);
        values[4] = m * v.x;
        values[5] = m * v.y;
        values[6] = energy[i].x + m * gravity * (pos[i].y - bottom);
        values[7] = energy[i].y;
    }
    const uint t = gl_LocalInvocationID.x;
    for (uint k = 0u; k < kSums; ++k) {
        partial[t] = values[k];
        barrier();
        for (uint stride = 128u; stride > 0u; stride >>= 1) {
            if (t < stride) partial[t] += partial[t + stride];
            barrier();
        }
        if (t == 0u) sums[workgroupIndex() * kSums + k] = partial[0];
        barrier();
    }
}
