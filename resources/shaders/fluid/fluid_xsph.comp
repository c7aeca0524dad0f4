#version 430
// Algorithm 1, line 22, second half (FluidModel::applyXsphViscosity, eq. 17): v_i += c Σ_j (v_j − v_i) W_ij.
layout(local_size_x = 128) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "common/cell_rows.glsl"
#include "fluid/fluid_kernels.glsl"

layout(std430, binding = 0) readonly buffer Predicted { vec2 p[]; };
layout(std430, binding = 1) readonly buffer VelIn { vec2 vIn[]; };
layout(std430, binding = 3) writeonly buffer VelOut { vec2 vOut[]; };

uniform uint count;
#include "fluid/fluid_neighbour_walk.glsl"
uniform float viscosity;

void main() {
    const uint i = itemIndex();
    if (i >= count) return;
    const vec2 pi = p[i];
    const vec2 vi = vIn[i];
    const NeighbourWalk walk = neighbourWalk(i, pi);
    vec2 sum = vec2(0.0);
    for (uint k = 0u; k < walk.length; ++k) {
        const uint j = neighbourAt(walk, i, k);
        const vec2 d = pi - p[j];
        const float r2 = dot(d, d);
        if (r2 >= kernelH2 || j == i) continue;
        sum += (vIn[j] - vi) * w(r2);
    }
    vOut[i] = vi + viscosity * sum;
}
