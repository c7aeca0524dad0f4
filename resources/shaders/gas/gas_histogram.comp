#version 430
// Speed histograms of both species on the GPU: the plot's bins over [0, plotMax_s) plus an overflow
// bin, and fine bins over [0, fineMax_s) for the KS distance (the last fine bin holds what lies beyond).
layout(local_size_x = 256) in;
#include "common/common.glsl"

layout(std430, binding = 1) readonly buffer Vel { vec2 vel[]; };
layout(std430, binding = 2) readonly buffer Acc { vec2 acc[]; };
layout(std430, binding = 3) readonly buffer Tag { uint tag[]; };
layout(std430, binding = 14) buffer Bins { uint bins[]; }; // [species][plotBins + 1], [species][fineBins]

uniform uint count;
uniform float pendingKick;
uniform uint plotBins, fineBins;
uniform vec2 plotMax, fineMax;

void main() {
    const uint i = itemIndex();
    if (i >= count) return;
    const uint s = tag[i] & 1u;
    const float speed = length(vel[i] + pendingKick * acc[i]);
    const uint plot = speed < plotMax[s] ? min(uint(speed / plotMax[s] * float(plotBins)), plotBins - 1u) : plotBins;
    const uint fine = min(uint(speed / fineMax[s] * float(fineBins)), fineBins - 1u);
    atomicAdd(bins[s * (plotBins + 1u) + plot], 1u);
    atomicAdd(bins[2u * (plotBins + 1u) + s * fineBins + fine], 1u);
}
