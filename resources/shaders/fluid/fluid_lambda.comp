#version 430
// Algorithm 1, lines 9–11 (FluidModel::computeLambdas): ρ_i = Σ_j W(x_i − x_j) (eq. 2), C_i = ρ_i/ρ₀ − 1
// (eq. 1), λ_i = −C_i / (Σ_k |∇_k C_i|² + ε) (eq. 11). Also the group's sum and maximum of the
// compression max(C_i, 0) for the density-error profile. The bounded release (FluidSolver.cpp,
// measureOldCompression, solveNewCompression; FluidLambdaPass.cpp, finishBlock): oldCompressionMode 2 stores
// b_i = max(C_i, 0) of the step's starting positions, 1 solves C_i − b_i; compressionOnly projects
// max(target, 0), the inequality ρ_i ≤ ρ₀.
layout(local_size_x = 128) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "common/cell_rows.glsl"
#include "fluid/fluid_kernels.glsl"

layout(std430, binding = 0) readonly buffer Predicted { vec2 p[]; };
layout(std430, binding = 1) writeonly buffer Lambda { float lambda[]; };
layout(std430, binding = 2) writeonly buffer ErrorSums { vec2 errorSums[]; }; // (sum, max) per group
layout(std430, binding = 3) buffer OldCompression { float oldCompression[]; }; // b_i

uniform uint count;
#include "fluid/fluid_neighbour_walk.glsl"
uniform float inverseRest, epsilon;
uniform uint errorOffset; // this iteration's first group slot
uniform int oldCompressionMode; // 0: C_i; 1: C_i − b_i; 2: store b_i = max(C_i, 0)
uniform bool compressionOnly;

shared float groupSum[128], groupMax[128];

void main() {
    const uint i = itemIndex();
    float compression = 0.0;
    if (i < count) {
        const vec2 pi = p[i];
        const NeighbourWalk walk = neighbourWalk(i, pi);
        float rho = selfWeight, sumSquares = 0.0;
        vec2 g = vec2(0.0);
        for (uint k = 0u; k < walk.length; ++k) {
            const uint j = neighbourAt(walk, i, k);
            const vec2 d = pi - p[j];
            const float r2 = dot(d, d);
            if (r2 >= kernelH2 || j == i) continue;
            const float f = gradFactor(r2);
            rho += w(r2);
            g += f * d;
            sumSquares += f * f * r2;
        }
        const float constraint = rho * inverseRest - 1.0;
        if (oldCompressionMode == 2) oldCompression[i] = max(constraint, 0.0);
        float target = oldCompressionMode == 1 ? constraint - oldCompression[i] : constraint;
        if (compressionOnly) target = max(target, 0.0);
        lambda[i] = -target / ((dot(g, g) + sumSquares) * inverseRest * inverseRest + epsilon);
        compression = max(constraint, 0.0);
    }
    const uint t = gl_LocalInvocationID.x;
    groupSum[t] = compression;
    groupMax[t] = compression;
    barrier();
    for (uint stride = 64u; stride > 0u; stride >>= 1) {
        if (t < stride) {
            groupSum[t] += groupSum[t + stride];
            groupMax[t] = max(groupMax[t], groupMax[t + stride]);
        }
        barrier();
    }
    if (t == 0u) errorSums[errorOffset + workgroupIndex()] = vec2(groupSum[0], groupMax[0]);
}
