#version 430
// Algorithm 1, lines 20–21 (FluidModel::updateVelocities): v ← (x* − x)/Δt; in contact with an obstacle a
// particle does not move into it faster than it moves. Flags non-finite velocities (a diverged solve).
// With the bounded release (FluidSolver.cpp, limitRelease) x* is x_v = x_new + (x_full − x_new) shortened to
// at most releaseLimit [L].
layout(local_size_x = 256) in;
#include "common/common.glsl"
#include "fluid/fluid_boundaries.glsl"

layout(std430, binding = 0) readonly buffer Pos { vec2 x[]; };
layout(std430, binding = 1) readonly buffer Predicted { vec2 p[]; };
layout(std430, binding = 2) writeonly buffer Vel { vec2 v[]; };
layout(std430, binding = 3) readonly buffer NewSolve { vec2 newSolve[]; }; // x_new
layout(std430, binding = 10) buffer Status { uint status[]; }; // [0]: a velocity is not finite

uniform uint count;
uniform float inverseDt;
uniform bool limited;
uniform float releaseLimit; // [L]

void main() {
    const uint i = itemIndex();
    if (i >= count) return;
    vec2 target = p[i];
    if (limited) {
        const vec2 release = p[i] - newSolve[i];
        const float len = length(release);
        target = newSolve[i] + release * (len > releaseLimit ? releaseLimit / len : 1.0);
    }
    vec2 velocity = (target - x[i]) * inverseDt;
    if (obstacleCount > 0u) obstacleVelocity(p[i], velocity);
    if (any(isnan(velocity)) || any(isinf(velocity))) atomicOr(status[0], 1u);
    v[i] = velocity;
}
