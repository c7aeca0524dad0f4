#version 430
// The bandwidth reference of the benchmarks: a plain vec4 copy, one element per invocation.
layout(local_size_x = 256) in;
#include "common/common.glsl"

layout(std430, binding = 0) readonly buffer From { vec4 from_[]; };
layout(std430, binding = 1) writeonly buffer To { vec4 to_[]; };

uniform uint count;

void main() {
    const uint i = itemIndex();
    if (i < count) to_[i] = from_[i];
}
