// One molecule's straight flight within the step, the GLSL twin of TunnelModel::fly (core/tunnel/
// TunnelMove.cpp; Bird 1994 §11.1): the events of the flight (a side, the piston, a body surface) are
// met in time order and applied at the exact time of the hit, and the rest of the flight continues.
// Bodies move during the step and are met in their own frame (obstacles[] holds their centres at the
// step's start). The gas's momentum change at each body is summed per work group in shared memory
// (64-bit fixed point) and added to the step's ring slot by flushImpulses(). Side codes SIDE_* come from
// TunnelBoundary (core/gl/TunnelModelGL.cpp defines them).
uniform int sides[4];         // left, right, bottom, top: SIDE_*
uniform float wallSigma;      // √(k T_wall / m) of diffuse sides [m/s]
uniform vec2 wallSpeeds;      // tangential (+x) speed of the bottom and top sides [m/s]
uniform float bodySigma;      // √(k T_body / m) [m/s]
uniform int bodiesDiffuse;    // 1: diffuse bodies, 0: specular
uniform int pistonOn;         // the left side is the piston
uniform float pistonStart;    // the piston's position at the start of the step [m]
uniform float pistonVelocity; // [m/s]
uniform uint surfacePurpose;  // RngPurpose of the re-emission draws

const int kMaxEvents = 32;     // as the CPU model: beyond it the molecule waits where it is
const uint kGroupBodies = 16u; // bodies summed in shared memory; any beyond add to the ring directly
// A reflected molecule is put this fraction of the body's size outside its surface: float positions
// need a larger margin than the CPU's double ones (1e-12) for rounding never to leave it inside.
const float kSurfaceNudge = 1e-5;
const int kNone = -1, kLeft = 0, kRight = 1, kBottom = 2, kTop = 3, kPiston = 4, kFirstBody = 5;

shared uint groupLow[kGroupBodies * 2u], groupHigh[kGroupBodies * 2u];

// Before any flight of the work group (all invocations call it, ahead of a barrier).
void clearImpulses() {
    const uint t = gl_LocalInvocationID.x;
    if (t < 2u * kGroupBodies) {
        groupLow[t] = 0u;
        groupHigh[t] = 0u;
    }
}

void addImpulse(uint body, vec2 dv) {
    const ivec2 q = ivec2(round(dv * kImpulseQuantum));
    for (uint c = 0u; c < 2u; ++c) {
        const uvec2 value = wide(q[c]);
        if (body < kGroupBodies) {
            const uint k = 2u * body + c;
            const uint before = atomicAdd(groupLow[k], value.x);
            atomicAdd(groupHigh[k], value.y + (before + value.x < before ? 1u : 0u));
        } else {
            addWideToRing(ringBase + 2u + 4u * body + 2u * c, value);
        }
    }
}

// After every flight of the work group (all invocations call it, after a barrier).
void flushImpulses() {
    const uint t = gl_LocalInvocationID.x;
    if (t < 2u * min(obstacleCount, kGroupBodies) && (groupLow[t] | groupHigh[t]) != 0u)
        addWideToRing(ringBase + 2u + 2u * t, uvec2(groupLow[t], groupHigh[t]));
}

// A body dragged or placed onto the molecule: to the nearest point of its surface, its velocity turned
// outward in the body's frame (TunnelModel::pushOutOfBodies).
void pushOutOfBodies(inout vec2 p, inout vec3 v) {
    for (uint b = 0u; b < obstacleCount; ++b) {
        const GpuObstacle o = obstacles[b];
        const vec2 r = p - o.centre;
        vec2 n = vec2(0.0), at;
        if (o.shape == 0u) {
            if (dot(r, r) >= o.radius * o.radius) continue;
            const float d = length(r);
            n = d > 0.0 ? r / d : vec2(1.0, 0.0);
            at = n * o.radius * (1.0 + kSurfaceNudge);
        } else {
            const vec2 gap = o.halfSize - abs(r);
            if (gap.x <= 0.0 || gap.y <= 0.0) continue;
            at = r;
            if (gap.x < gap.y) {
                n.x = r.x >= 0.0 ? 1.0 : -1.0;
                at.x = n.x * o.halfSize.x * (1.0 + kSurfaceNudge);
            } else {
                n.y = r.y >= 0.0 ? 1.0 : -1.0;
                at.y = n.y * o.halfSize.y * (1.0 + kSurfaceNudge);
            }
        }
        p = o.centre + at;
        const float wn = dot(v.xy - o.velocity, n);
        if (wn < 0.0) v.xy -= 2.0 * wn * n;
    }
}

// Time at which r + w t enters the disc of the given radius about the origin (tunnel::discHitTime):
// −1 when never; 0 for a point a hair inside moving inward.
float discHit(vec2 r, vec2 w, float radius) {
    const float b = dot(r, w);
    if (b >= 0.0) return -1.0;
    const float c = dot(r, r) - radius * radius;
    if (c <= 0.0) return 0.0;
    const float discriminant = b * b - dot(w, w) * c;
    if (discriminant < 0.0) return -1.0;
    return c / (-b + sqrt(discriminant)); // the smaller root, without cancellation
}

// Time at which r + w t enters the box |r| < halfSize (tunnel::boxHitTime, slab method), −1 when never
// or when already inside; normal: the outward normal of the face hit.
float boxHit(vec2 r, vec2 w, vec2 halfSize, out vec2 normal) {
    float enter = -1e30, leave = 1e30;
    normal = vec2(0.0);
    vec2 face = vec2(0.0);
    for (int a = 0; a < 2; ++a) {
        if (w[a] == 0.0) {
            if (abs(r[a]) >= halfSize[a]) return -1.0;
            continue;
        }
        const float t0 = (-halfSize[a] - r[a]) / w[a], t1 = (halfSize[a] - r[a]) / w[a];
        if (min(t0, t1) > enter) {
            enter = min(t0, t1);
            face = vec2(0.0);
            face[a] = w[a] > 0.0 ? -1.0 : 1.0;
        }
        leave = min(leave, max(t0, t1));
    }
    if (enter > leave || leave <= 0.0 || enter < 0.0) return -1.0;
    normal = face;
    return enter;
}

// Flies the molecule from τ0 to dt; false when it left through an inflow or outflow side. subject keys
// its re-emission draws (unique among this step's flights).
bool fly(inout vec2 p, inout vec3 v, float tau0, uint subject) {
    float tau = tau0;
    bool inside = true;
    for (int e = 0; e < kMaxEvents; ++e) {
        float first = dt - tau;
        int event = kNone;
        vec2 normal = vec2(0.0);
        if (pistonOn != 0) {
            const float gap = p.x - (pistonStart + pistonVelocity * tau);
            if (v.x < pistonVelocity) {
                const float t = max(gap, 0.0) / (pistonVelocity - v.x);
                if (t < first) {
                    first = t;
                    event = kPiston;
                }
            }
        } else if (v.x < 0.0) {
            const float t = max(p.x - domain.x, 0.0) / -v.x;
            if (t < first) {
                first = t;
                event = kLeft;
            }
        }
        if (v.x > 0.0) {
            const float t = max(domain.z - p.x, 0.0) / v.x;
            if (t < first) {
                first = t;
                event = kRight;
            }
        }
        if (v.y < 0.0) {
            const float t = max(p.y - domain.y, 0.0) / -v.y;
            if (t < first) {
                first = t;
                event = kBottom;
            }
        }
        if (v.y > 0.0) {
            const float t = max(domain.w - p.y, 0.0) / v.y;
            if (t < first) {
                first = t;
                event = kTop;
            }
        }
        for (uint b = 0u; b < obstacleCount; ++b) {
            const GpuObstacle o = obstacles[b];
            const vec2 r = p - (o.centre + o.velocity * tau), w = v.xy - o.velocity;
            vec2 n;
            const float t = o.shape == 0u ? discHit(r, w, o.radius) : boxHit(r, w, o.halfSize, n);
            if (t >= 0.0 && t < first) {
                first = t;
                event = kFirstBody + int(b);
                normal = o.shape == 0u ? normalize(r + w * t) : n;
                if (o.shape == 0u && any(isnan(normal))) normal = vec2(1.0, 0.0);
            }
        }
        p += v.xy * first;
        tau += first;
        if (event == kNone) break;
        if (event == kPiston) { // a mirror in the piston's frame
            p.x = pistonStart + pistonVelocity * tau;
            v.x = 2.0 * pistonVelocity - v.x;
            continue;
        }
        const uvec4 words = randomWords(seedWords, surfacePurpose, subject, uvec2(uint(e), stepIndex));
        if (event < kPiston) {
            const int kind = sides[event];
            const bool alongX = event <= kRight;
            const float wall = event == kLeft    ? domain.x
                             : event == kRight   ? domain.z
                             : event == kBottom  ? domain.y
                                                 : domain.w;
            if (alongX) p.x = wall; else p.y = wall;
            if (kind == SIDE_INFLOW || kind == SIDE_OUTFLOW) {
                inside = false;
                break;
            }
            if (kind == SIDE_PERIODIC) {
                if (event == kLeft) p.x = domain.z;
                else if (event == kRight) p.x = domain.x;
                else if (event == kBottom) p.y = domain.w;
                else p.y = domain.y;
            } else if (kind == SIDE_SPECULAR) {
                if (alongX) v.x = -v.x; else v.y = -v.y;
            } else { // diffuse, the wall moving along itself
                const vec2 inward = event == kLeft    ? vec2(1, 0)
                                  : event == kRight   ? vec2(-1, 0)
                                  : event == kBottom  ? vec2(0, 1)
                                                      : vec2(0, -1);
                const float speed = event == kBottom ? wallSpeeds.x : event == kTop ? wallSpeeds.y : 0.0;
                v = diffuseVelocity(inward, wallSigma, vec2(speed, 0.0), words);
            }
            continue;
        }
        // A body: reflect in its frame; the gas's momentum change to the body's sum.
        const uint b = uint(event - kFirstBody);
        const GpuObstacle o = obstacles[b];
        const vec2 before = v.xy;
        if (bodiesDiffuse != 0) {
            v = diffuseVelocity(normal, bodySigma, o.velocity, words);
        } else {
            const vec2 w = v.xy - o.velocity;
            v.xy = o.velocity + w - 2.0 * dot(w, normal) * normal;
        }
        addImpulse(b, v.xy - before);
        const vec2 centre = o.centre + o.velocity * tau;
        if (o.shape == 0u) {
            p = centre + normal * o.radius * (1.0 + kSurfaceNudge);
        } else {
            if (normal.x != 0.0) p.x = centre.x + normal.x * o.halfSize.x * (1.0 + kSurfaceNudge);
            if (normal.y != 0.0) p.y = centre.y + normal.y * o.halfSize.y * (1.0 + kSurfaceNudge);
        }
    }
    p = clamp(p, domain.xy, domain.zw);
    return inside;
}
