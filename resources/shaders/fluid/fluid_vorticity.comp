#version 430
// Algorithm 1, line 22, first half (FluidModel::applyVorticityConfinement, eqs. 15–16 in 2D). Pass 0:
// ω_i = Σ_j v_ij × ∇_j W_ij. Pass 1: η = ∇|ω|, N = η/|η|, v_i += ε Δt ω_i (N_y, −N_x).
layout(local_size_x = 128) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "common/cell_rows.glsl"
#include "fluid/fluid_kernels.glsl"

layout(std430, binding = 0) readonly buffer Predicted { vec2 p[]; };
layout(std430, binding = 1) readonly buffer VelIn { vec2 vIn[]; };
layout(std430, binding = 2) buffer Omega { float omega[]; };
layout(std430, binding = 3) writeonly buffer VelOut { vec2 vOut[]; };

uniform uint count;
#include "fluid/fluid_neighbour_walk.glsl"
uniform int pass_;
uniform float strength, inverseRest; // ε_vort · Δt; 1/ρ₀

void main() {
    const uint i = itemIndex();
    if (i >= count) return;
    const vec2 pi = p[i];
    const NeighbourWalk walk = neighbourWalk(i, pi);
    if (pass_ == 0) {
        float wi = 0.0;
        for (uint k = 0u; k < walk.length; ++k) {
            const uint j = neighbourAt(walk, i, k);
            const vec2 d = pi - p[j];
            const float r2 = dot(d, d);
            if (r2 >= kernelH2 || j == i) continue;
            const float f = gradFactor(r2);
            const vec2 u = vIn[j] - vIn[i];
            wi -= u.x * (f * d.y) - u.y * (f * d.x);
        }
        omega[i] = wi;
        return;
    }
    vec2 eta = vec2(0.0);
    const float oi = abs(omega[i]);
    for (uint k = 0u; k < walk.length; ++k) {
        const uint j = neighbourAt(walk, i, k);
        const vec2 d = pi - p[j];
        const float r2 = dot(d, d);
        if (r2 >= kernelH2 || j == i) continue;
        eta += gradFactor(r2) * (abs(omega[j]) - oi) * d;
    }
    eta *= inverseRest;
    const float len = length(eta);
    vec2 v = vIn[i];
    if (len >= 1e-12) v += strength * omega[i] * vec2(eta.y, -eta.x) / len;
    vOut[i] = v;
}
