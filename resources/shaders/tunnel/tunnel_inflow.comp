#version 430
// Inflow (docs/wind-tunnel.md#inflow; TunnelModel::admitInflow): the molecules that enter through the
// inflow sides this step, one invocation each, appended after the moved ones (their number comes from
// the host, which keeps the half-range flux's remainder as the CPU model does). Each crosses its side at
// a uniform point and a uniform moment of the step with the velocity of the Maxwellian flux through the
// side, and flies the rest of the step. The first invocation also sizes the scatter that follows.
layout(local_size_x = 256) in;
#include "common/common.glsl"
#include "common/philox.glsl"
#include "common/obstacles.glsl"
#include "tunnel/tunnel_common.glsl"
#include "tunnel/tunnel_fly.glsl"

uniform uint inflowEnd[4];    // entering particles through left, right, bottom, top, accumulated
uniform float streamSigma;    // √(k T / m) of the free stream [m/s]
uniform vec2 streamVelocity;  // [m/s]
uniform uint inflowPurpose;   // RngPurpose of these draws

const int kMaxTries = 32;

// The normal speed of molecules crossing a surface, in units of √2 σ: density x e^{−(x − s)²} on
// x > 0 for the stream's normal speed ratio s (Bird 1994 §12.5; docs/wind-tunnel.md#inflow; the CPU
// model's tunnel::inflowNormalSpeedRatio draws the same density another way). Rejection from the
// Gaussian e^{−(x − c)²} centred on the density's mode c = (s + √(s² + 2)) / 2: the ratio of the two
// is ∝ x e^{−2 (c − s) x}, largest at x = 1 / (2 (c − s)), so a proposal is kept with probability
// 2 (c − s) e · x e^{−2 (c − s) x}: about 1.5 proposals per molecule at s = 0, 1.02 at s = 3.5 and
// 2.2 at s = −1 (none are lost: after kMaxTries the mode stands in, at odds below 10⁻⁸ for s ≥ −1).
float normalSpeedRatio(float s, uint k) {
    const float c = 0.5 * (s + sqrt(s * s + 2.0));
    const float d = c - s;
    for (int attempt = 0; attempt < kMaxTries; ++attempt) {
        const uvec4 w = randomWords(seedWords, inflowPurpose, k, uvec2(uint(attempt) + 1u, stepIndex));
        const float x = c + 0.70710678 * gaussianPair(w.x, w.y).x;
        if (x > 0.0 && unitOpen32(w.z) < 2.0 * d * 2.718281828 * x * exp(-2.0 * d * x)) return x;
    }
    return c;
}

void main() {
    const uint k = itemIndex();
    const uint entering = inflowEnd[3];
    if (k == 0u) {
        movedCount = sortedCount + entering;
        const uvec3 groups = groupsOf(movedCount, 256u);
        scatterGroups[0] = groups.x;
        scatterGroups[1] = groups.y;
        scatterGroups[2] = groups.z;
    }
    clearImpulses();
    barrier();
    if (k < entering) {
        const int side = k < inflowEnd[0] ? 0 : k < inflowEnd[1] ? 1 : k < inflowEnd[2] ? 2 : 3;
        const vec2 inward = side == 0   ? vec2(1, 0)
                          : side == 1   ? vec2(-1, 0)
                          : side == 2   ? vec2(0, 1)
                                        : vec2(0, -1);
        const vec2 tangent = side <= 1 ? vec2(0, 1) : vec2(1, 0);
        const vec2 start = side == 0 ? domain.xy : side == 1 ? domain.zy : side == 2 ? domain.xy : domain.xw;
        const float sideLength = side <= 1 ? domain.w - domain.y : domain.z - domain.x;

        const float scale = 1.41421356 * streamSigma; // √(2kT/m)
        const float normalSpeed = scale * normalSpeedRatio(dot(streamVelocity, inward) / scale, k);
        const uvec4 w = randomWords(seedWords, inflowPurpose, k, uvec2(0u, stepIndex));
        const vec2 thermal = streamSigma * gaussianPair(w.x, w.y);
        vec3 v = vec3(inward * normalSpeed + tangent * (dot(streamVelocity, tangent) + thermal.x), thermal.y);
        vec2 p = start + tangent * (sideLength * unitOpen32(w.z));
        const uint i = sortedCount + k;
        const bool inside = fly(p, v, dt * (1.0 - unitOpen32(w.w)), i);
        movedPosition[i] = p;
        movedVelocity[i] = v.xy;
        movedVz[i] = v.z;
        if (inside) {
            const uint c = cellOf(p);
            movedCell[i] = uvec2(c, atomicAdd(cellCounts[c], 1u));
        } else {
            movedCell[i] = uvec2(kRemoved, 0u);
        }
    }
    barrier();
    flushImpulses();
}
