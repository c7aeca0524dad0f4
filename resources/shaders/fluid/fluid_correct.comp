#version 430
// Algorithm 1, lines 13–16 (FluidModel::applyPositionCorrections): Δx_i = (1/ρ₀) Σ_j (λ_i + λ_j + s_corr)
// ∇W_ij (eq. 14), then collision response. Jacobi: the result goes to a second buffer. The CPU keeps the
// pair gradients of the λ pass; here they are recomputed, which costs less than storing them.
layout(local_size_x = 128) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "common/cell_rows.glsl"
#include "fluid/fluid_kernels.glsl"
#include "fluid/fluid_boundaries.glsl"

layout(std430, binding = 0) readonly buffer Predicted { vec2 p[]; };
layout(std430, binding = 1) readonly buffer Lambda { float lambda[]; };
layout(std430, binding = 2) writeonly buffer Corrected { vec2 corrected[]; };

uniform uint count;
#include "fluid/fluid_neighbour_walk.glsl"
uniform float inverseRest;

void main() {
    const uint i = itemIndex();
    if (i >= count) return;
    const vec2 pi = p[i];
    const float li = lambda[i];
    const NeighbourWalk walk = neighbourWalk(i, pi);
    vec2 delta = vec2(0.0);
    for (uint k = 0u; k < walk.length; ++k) {
        const uint j = neighbourAt(walk, i, k);
        const vec2 d = pi - p[j];
        const float r2 = dot(d, d);
        if (r2 >= kernelH2 || j == i) continue;
        delta += (li + lambda[j] + artificialPressure(w(r2))) * gradFactor(r2) * d;
    }
    vec2 next = pi + delta * inverseRest;
    confine(i, next);
    corrected[i] = next;
}
