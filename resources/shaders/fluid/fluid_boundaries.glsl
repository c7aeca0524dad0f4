// Collision response of the fluid: the GLSL twin of core/fluid/FluidBoundaries.h (projectOutOfObstacle,
// WallJitter, clampToBox, confine, obstacleVelocity).
#include "common/philox.glsl"
#include "common/obstacles.glsl"

uniform vec4 confinement; // left, bottom, right, top: where centres may be [L]
uniform float margin;     // particle radius [L]
uniform uvec2 seedWords, stepWords; // wall jitter key: seed and step as (low, high)
uniform float jitterAmount;          // [L]

const uint kRngWallJitter = 7u;

bool projectOutOfObstacle(GpuObstacle o, float reachMargin, inout vec2 p, out vec2 n) {
    const vec2 d = p - o.centre;
    n = vec2(0.0);
    if (o.shape == 0u) {
        const float reach = o.radius + reachMargin;
        const float d2 = dot(d, d);
        if (d2 >= reach * reach) return false;
        const float dist = sqrt(d2);
        n = dist > 0.0 ? d / dist : vec2(0.0, 1.0);
        p = o.centre + reach * n;
        return true;
    }
    const vec2 half_ = o.halfSize + reachMargin;
    const vec2 pen = half_ - abs(d);
    if (pen.x <= 0.0 || pen.y <= 0.0) return false;
    if (pen.x < pen.y) {
        n.x = d.x >= 0.0 ? 1.0 : -1.0;
        p.x = o.centre.x + n.x * half_.x;
    } else {
        n.y = d.y >= 0.0 ? 1.0 : -1.0;
        p.y = o.centre.y + n.y * half_.y;
    }
    return true;
}

// Tiny random offsets off the walls (WallJitter): corner particles must not coincide.
float jitterDraw(uint particle, uint word) {
    if (jitterAmount == 0.0) return 0.0;
    return jitterAmount * unitOpen32(randomWords(seedWords, kRngWallJitter, particle, stepWords)[word]);
}

void clampToBox(uint particle, inout vec2 p) {
    if (p.x < confinement.x) p.x = confinement.x + jitterDraw(particle, 0u);
    if (p.x > confinement.z) p.x = confinement.z - jitterDraw(particle, 1u);
    if (p.y < confinement.y) p.y = confinement.y + jitterDraw(particle, 2u);
    if (p.y > confinement.w) p.y = confinement.w - jitterDraw(particle, 3u);
}

void confine(uint particle, inout vec2 p) {
    clampToBox(particle, p);
    if (obstacleCount == 0u) return;
    vec2 n;
    for (uint k = 0u; k < obstacleCount; ++k) projectOutOfObstacle(obstacles[k], margin, p, n);
    clampToBox(particle, p);
}

void obstacleVelocity(vec2 p, inout vec2 v) {
    const float kContact = 1e-6;
    for (uint k = 0u; k < obstacleCount; ++k) {
        vec2 q = p, n;
        if (!projectOutOfObstacle(obstacles[k], margin * (1.0 + kContact) + kContact, q, n)) continue;
        const float normal = dot(v - obstacles[k].velocity, n);
        if (normal < 0.0) v -= normal * n;
    }
}
