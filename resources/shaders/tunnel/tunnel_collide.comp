#version 430
// Collide and sample (docs/wind-tunnel.md#collisions): one invocation per cell over its particles, which
// the sort made contiguous. Bird's No-Time-Counter scheme (Bird 1994 eq. 11.3, as the CPU model's
// TunnelCollide.cpp): ½ N (N − 1) F_N (σ c_r)_max Δt / V_c candidate pairs, the fraction carried in the
// cell's remainder, each accepted with probability σ c_r / (σ c_r)_max and scattered isotropically
// (Bird 1994 §2.4), with a Philox stream keyed by (cell, step). A pair above the cell's (σ c_r)_max
// raises it at once (Bird 1994 §11.1). Then, on sampled steps, the cell's sums of v and v² per
// component are added to its window sums (double: a long window of float additions would lose the
// temperature, a small difference of large squares).
layout(local_size_x = 64) in;
#include "common/common.glsl"
#include "common/philox.glsl"
#include "tunnel/tunnel_common.glsl"

layout(std430, binding = 11) buffer Remainders { float remainders[]; };
layout(std430, binding = 12) buffer WindowSums { double windowSums[]; }; // 7 per cell: N, Σv, Σv²
layout(std430, binding = 13) readonly buffer OpenFractions { float openFractions[]; };
layout(std430, binding = 14) buffer CellSigmaCrMax { float cellSigmaCrMax[]; }; // [m³/s]

uniform uint cellCount;
uniform float candidateFactor; // F_N Δt / V_c of a full cell [s/m³]
uniform float sigmaPrefactor;  // σ c_r = A c_r^exponent [m³/s]
uniform float sigmaExponent;   // 2 − 2ω
uniform uint collisionPurpose;
uniform int sampleStep;        // 1: add this step to the window sums
uniform float minOpenFraction; // cut cells collide as if at least this open (TunnelCollide.cpp)

shared uint groupCollisions;

float sigmaCr(float cr) {
    return sigmaExponent == 0.0 ? sigmaPrefactor : sigmaPrefactor * pow(cr, sigmaExponent);
}

uint randomIndex(uint bits, uint n) {
    uint high, low;
    umulExtended(bits, n, high, low);
    return high;
}

void main() {
    const uint c = itemIndex();
    if (gl_LocalInvocationID.x == 0u) groupCollisions = 0u;
    barrier();
    if (c < cellCount) {
        const uint first = cellStarts[c];
        const uint n = cellStarts[c + 1u] - first;
        const float open = openFractions[c];
        float sigmaMax = cellSigmaCrMax[c];
        uint candidates = 0u;
        if (n >= 2u && open > 0.0) {
            const float volumeShare = max(open, minOpenFraction);
            const float pairs = 0.5 * float(n) * float(n - 1u);
            const float wanted = pairs * candidateFactor * sigmaMax / volumeShare + remainders[c];
            candidates = uint(wanted);
            remainders[c] = wanted - float(candidates);
        }
        uint accepted = 0u;
        for (uint k = 0u; k < candidates; ++k) {
            const uvec4 w = randomWords(seedWords, collisionPurpose, c, uvec2(2u * k, stepIndex));
            const uint i = first + randomIndex(w.x, n);
            uint j = first + randomIndex(w.y, n - 1u);
            if (j >= i) ++j;
            const vec3 a = vec3(sortedVelocity[i], sortedVz[i]), b = vec3(sortedVelocity[j], sortedVz[j]);
            const float cr = length(a - b);
            const float s = sigmaCr(cr);
            if (s > sigmaMax) sigmaMax = s;
            if (unitOpen32(w.z) * sigmaMax >= s) continue;
            // Isotropic scattering of equal masses: the centre of mass kept, c_r turned to a uniform
            // direction (cos θ = 2u₁ − 1, φ = 2π u₂).
            const uvec4 angles = randomWords(seedWords, collisionPurpose, c, uvec2(2u * k + 1u, stepIndex));
            const float cosTheta = 2.0 * unitOpen32(angles.x) - 1.0;
            const float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
            const float phi = 6.28318530718 * unitOpen32(angles.y);
            const vec3 half_ = 0.5 * cr * vec3(cosTheta, sinTheta * cos(phi), sinTheta * sin(phi));
            const vec3 centre = 0.5 * (a + b);
            sortedVelocity[i] = (centre + half_).xy;
            sortedVz[i] = (centre + half_).z;
            sortedVelocity[j] = (centre - half_).xy;
            sortedVz[j] = (centre - half_).z;
            ++accepted;
        }
        cellSigmaCrMax[c] = sigmaMax;
        if (accepted > 0u) atomicAdd(groupCollisions, accepted);
        if (sampleStep != 0 && n > 0u) {
            vec3 sum = vec3(0.0), squares = vec3(0.0);
            for (uint i = first; i < first + n; ++i) {
                const vec3 v = vec3(sortedVelocity[i], sortedVz[i]);
                sum += v;
                squares += v * v;
            }
            const uint base = 7u * c;
            windowSums[base] += double(n);
            for (int q = 0; q < 3; ++q) {
                windowSums[base + 1u + uint(q)] += double(sum[q]);
                windowSums[base + 4u + uint(q)] += double(squares[q]);
            }
        }
    }
    barrier();
    if (gl_LocalInvocationID.x == 0u && groupCollisions > 0u) atomicAdd(stepRing[ringBase], groupCollisions);
}
