#version 430
// Exclusive prefix sum of one block of 2048 counts per work group (4 per invocation), the block's total
// to blockSums; scan_add.comp then adds the scanned block totals (Blelloch-style two-level scan).
layout(local_size_x = 512) in;
#include "common/common.glsl"

layout(std430, binding = 0) buffer Input { uint values[]; };
layout(std430, binding = 1) writeonly buffer Output { uint prefix[]; };
layout(std430, binding = 2) writeonly buffer BlockSums { uint blockSums[]; };

uniform uint count;
uniform bool clearInput; // counts are zeroed as they are read, ready for the next counting pass

shared uint partial[512];

void main() {
    const uint t = gl_LocalInvocationID.x;
    const uint base = workgroupIndex() * 2048u + 4u * t;
    uint v[4];
    uint sum = 0u;
    for (uint k = 0u; k < 4u; ++k) {
        const uint index = base + k;
        v[k] = index < count ? values[index] : 0u;
        if (clearInput && index < count) values[index] = 0u;
        sum += v[k];
    }
    partial[t] = sum;
    barrier();
    // Hillis–Steele inclusive scan of the 512 partial sums.
    for (uint offset = 1u; offset < 512u; offset <<= 1) {
        const uint add = t >= offset ? partial[t - offset] : 0u;
        barrier();
        partial[t] += add;
        barrier();
    }
    uint running = partial[t] - sum;
    for (uint k = 0u; k < 4u; ++k) {
        const uint index = base + k;
        if (index < count) prefix[index] = running;
        running += v[k];
    }
    if (t == 511u) blockSums[workgroupIndex()] = partial[511];
}
