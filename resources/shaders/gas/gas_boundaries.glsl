// Walls, piston, thermal walls and obstacles acting on one disk centre after a drift: the GLSL twin of
// core/gas/GasBoundaries.cpp (pathEntry, reflectOffObstacle, collideObstacle, reflectOffWalls).
#include "common/philox.glsl"
#include "gas/gas_kernels.glsl"
#include "common/obstacles.glsl"

uniform vec4 box;              // left, right (the piston when enabled), bottom, top [L]
uniform float pistonVelocity;  // [L/T]
uniform float driftH;          // the drift's signed time step [T]
uniform bool thermalWalls, thermalRight;
uniform float wallKT;
uniform vec2 speciesMass;      // [M]
uniform vec2 speciesRadius;    // [L]
uniform uvec2 seedWords, drawWords; // 64-bit seed and draw index as (low, high)

const uint kRngThermalWall = 3u;

bool obstacleContains(GpuObstacle o, vec2 p, float margin) {
    const vec2 d = p - o.centre;
    if (o.shape == 0u) return dot(d, d) < (o.radius + margin) * (o.radius + margin);
    return abs(d.x) < o.halfSize.x + margin && abs(d.y) < o.halfSize.y + margin;
}

// Where the path p0 → p0 + delta enters the obstacle grown by radius: fraction s and outward normal n.
bool pathEntry(GpuObstacle o, float radius, vec2 p0, vec2 delta, out float s, out vec2 n) {
    s = 0.0;
    n = vec2(0.0);
    if (o.shape == 0u) {
        const float grown = o.radius + radius;
        const vec2 r = p0 - o.centre;
        const float a = dot(delta, delta), b = 2.0 * dot(delta, r), c = dot(r, r) - grown * grown;
        const float discriminant = b * b - 4.0 * a * c;
        if (a == 0.0 || c < 0.0 || discriminant < 0.0) return false;
        s = (-b - sqrt(discriminant)) / (2.0 * a);
        n = (r + s * delta) / grown;
    } else {
        const vec2 half_ = o.halfSize + radius;
        float sx = -1.0, sy = -1.0;
        if (p0.x < o.centre.x - half_.x && delta.x > 0.0) sx = (o.centre.x - half_.x - p0.x) / delta.x;
        if (p0.x > o.centre.x + half_.x && delta.x < 0.0) sx = (o.centre.x + half_.x - p0.x) / delta.x;
        if (p0.y < o.centre.y - half_.y && delta.y > 0.0) sy = (o.centre.y - half_.y - p0.y) / delta.y;
        if (p0.y > o.centre.y + half_.y && delta.y < 0.0) sy = (o.centre.y + half_.y - p0.y) / delta.y;
        if (sx < 0.0 && sy < 0.0) return false;
        s = max(sx, sy);
        n = s == sx ? vec2(delta.x > 0.0 ? -1.0 : 1.0, 0.0) : vec2(0.0, delta.y > 0.0 ? -1.0 : 1.0);
    }
    return s >= 0.0 && s <= 1.0;
}

void reflectOffObstacle(GpuObstacle o, vec2 n, float timeSign, inout vec2 v) {
    const float wn = dot(v - o.velocity, n);
    if (wn * timeSign < 0.0) v -= 2.0 * wn * n;
}

void collideObstacle(GpuObstacle o, float radius, float h, inout vec2 x, inout vec2 v) {
    if (!obstacleContains(o, x, radius)) return;
    const float timeSign = h >= 0.0 ? 1.0 : -1.0;
    const vec2 delta = h * v;
    float s;
    vec2 n;
    if (pathEntry(o, radius, x - delta, delta, s, n)) {
        const vec2 hit = x - delta + s * delta;
        reflectOffObstacle(o, n, timeSign, v);
        x = hit + (1.0 - s) * h * v;
        return;
    }
    // Already inside (the obstacle was dragged onto it): pushed out the shortest way.
    const vec2 r = x - o.centre;
    float depth;
    if (o.shape == 0u) {
        const float dist = length(r);
        n = dist > 0.0 ? r / dist : vec2(1.0, 0.0);
        depth = o.radius + radius - dist;
    } else {
        const vec2 pen = o.halfSize + radius - abs(r);
        n = pen.x < pen.y ? vec2(r.x >= 0.0 ? 1.0 : -1.0, 0.0) : vec2(0.0, r.y >= 0.0 ? 1.0 : -1.0);
        depth = min(pen.x, pen.y);
    }
    x += 2.0 * depth * n;
    reflectOffObstacle(o, n, 1.0, v);
}

// Reflects off the box walls (diffusely for thermal walls); adds the normal momentum given to the walls
// to impulse; false when the disk is still outside after one mirror (a blow-up, or NaN).
bool reflectOffWalls(inout vec2 x, inout vec2 v, int species, uint id, inout float impulse) {
    const float timeSign = driftH >= 0.0 ? 1.0 : -1.0;
    const float m = speciesMass[species];
    const vec2 vIn = v;
    const float hitLeft = reflectPlane(x.x, v.x, box.x, -1.0, 0.0, timeSign);
    const float hitRight = reflectPlane(x.x, v.x, box.y, 1.0, pistonVelocity, timeSign);
    const float hitBottom = reflectPlane(x.y, v.y, box.z, -1.0, 0.0, timeSign);
    const float hitTop = reflectPlane(x.y, v.y, box.w, 1.0, 0.0, timeSign);
    if (thermalWalls && (hitLeft != 0.0 || (thermalRight && hitRight != 0.0) || hitBottom != 0.0 || hitTop != 0.0)) {
        // Flux-weighted normal speed (Rayleigh) and Gaussian tangential speed at the wall temperature.
        const uvec4 w = randomWords(seedWords, kRngThermalWall, id, drawWords);
        const float sigma = sqrt(wallKT / m);
        const float normal = sigma * sqrt(-2.0 * log(unitOpen32(w.x)));
        const float tangential = sigma * sqrt(-2.0 * log(unitOpen32(w.z))) * cos(6.28318530718 * unitOpen32(w.w));
        if (hitLeft != 0.0 || hitRight != 0.0)
            v = vec2((hitLeft != 0.0 ? 1.0 : -1.0) * normal, tangential);
        else
            v = vec2(tangential, (hitBottom != 0.0 ? 1.0 : -1.0) * normal);
    }
    float given = 0.0;
    if (hitLeft != 0.0 || hitRight != 0.0) given += abs(v.x - vIn.x);
    if (hitBottom != 0.0 || hitTop != 0.0) given += abs(v.y - vIn.y);
    impulse += timeSign * m * given;
    const bool ok = x.x >= box.x && x.x <= box.y && x.y >= box.z && x.y <= box.w;
    if (!ok) {
        x.x = isnan(x.x) || isinf(x.x) ? 0.0 : clamp(x.x, box.x, box.y);
        x.y = isnan(x.y) || isinf(x.y) ? 0.0 : clamp(x.y, box.z, box.w);
    }
    return ok;
}

// Boundaries::apply: the common case, inside the box and no obstacles, costs four comparisons.
bool applyBoundaries(inout vec2 x, inout vec2 v, int species, uint id, inout float impulse) {
    const bool inside = x.x > box.x && x.x < box.y && x.y > box.z && x.y < box.w;
    if (inside && obstacleCount == 0u) return true;
    bool ok = true;
    if (!inside) ok = reflectOffWalls(x, v, species, id, impulse);
    if (obstacleCount > 0u) {
        for (uint k = 0u; k < obstacleCount; ++k) collideObstacle(obstacles[k], speciesRadius[species], driftH, x, v);
        x = clamp(x, box.xz, box.yw);
    }
    return ok;
}
