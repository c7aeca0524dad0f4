#version 430
// Second half of the two-level scan: each 2048-element block adds the scanned total of the blocks
// before it.
layout(local_size_x = 512) in;
#include "common/common.glsl"

layout(std430, binding = 1) buffer Output { uint prefix[]; };
layout(std430, binding = 3) readonly buffer BlockOffsets { uint blockOffsets[]; };

uniform uint count;

void main() {
    const uint block = workgroupIndex();
    const uint add = blockOffsets[block];
    for (uint k = 0u; k < 4u; ++k) {
        const uint index = block * 2048u + 4u * gl_LocalInvocationID.x + k;
        if (index < count) prefix[index] += add;
    }
}
