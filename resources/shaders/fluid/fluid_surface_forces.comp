#version 430
// Surface forces (FluidModel::applySurfaceForces; Akinci et al. 2013, eqs. 1, 2, 6, 7, their splines
// scaled to 1 at their peaks): v_i += Δt (−γ Σ_j C(r_ij/h) x̂_ij + β Σ_walls A(d/h) towards the wall).
layout(local_size_x = 128) in;
#include "common/common.glsl"
#include "common/cells.glsl"
#include "common/cell_rows.glsl"
#include "fluid/fluid_kernels.glsl"
#include "common/obstacles.glsl"

layout(std430, binding = 0) readonly buffer Predicted { vec2 p[]; };
layout(std430, binding = 1) buffer Vel { vec2 v[]; };

uniform uint count;
#include "fluid/fluid_neighbour_walk.glsl"
uniform float cohesion, adhesion; // γ, β [L/s²]
uniform vec2 world;               // the box [0, W] × [0, H]
uniform float dt;

float cohesionSpline(float q) {
    if (!(q > 0.0) || q >= 1.0) return 0.0;
    const float product = (1.0 - q) * q;
    const float spline = 64.0 * product * product * product;
    return q > 0.5 ? spline : 2.0 * spline - 1.0;
}

float adhesionSpline(float q) {
    if (!(q > 0.5) || q >= 1.0) return 0.0;
    return sqrt(sqrt(-16.0 * q * q + 24.0 * q - 8.0));
}

vec2 adhesionPull(vec2 pi) {
    const float inverseH = 1.0 / kernelH;
    vec2 a = adhesion * vec2(adhesionSpline((world.x - pi.x) * inverseH) - adhesionSpline(pi.x * inverseH),
                             adhesionSpline((world.y - pi.y) * inverseH) - adhesionSpline(pi.y * inverseH));
    for (uint k = 0u; k < obstacleCount; ++k) {
        const GpuObstacle o = obstacles[k];
        const vec2 d = pi - o.centre;
        float distance;
        vec2 away;
        if (o.shape == 0u) {
            const float centre = length(d);
            if (!(centre > 0.0)) continue;
            distance = centre - o.radius;
            away = d / centre;
        } else {
            const vec2 outside = max(abs(d) - o.halfSize, vec2(0.0));
            distance = length(outside);
            if (!(distance > 0.0)) continue;
            away = sign(d) * outside / distance;
        }
        a -= adhesion * adhesionSpline(distance * inverseH) * away;
    }
    return a;
}

void main() {
    const uint i = itemIndex();
    if (i >= count) return;
    const vec2 pi = p[i];
    const NeighbourWalk walk = neighbourWalk(i, pi);
    vec2 a = vec2(0.0);
    for (uint k = 0u; k < walk.length; ++k) {
        const uint j = neighbourAt(walk, i, k);
        const vec2 d = pi - p[j];
        const float r = length(d);
        if (!(r > 0.0)) continue;
        a -= cohesionSpline(r / kernelH) / r * d;
    }
    a *= cohesion;
    if (adhesion > 0.0) a += adhesionPull(pi);
    v[i] += dt * a;
}
