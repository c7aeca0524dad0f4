// The wind tunnel's GPU state (core/gl/TunnelModelGL): the particles in cell order ("sorted"), their
// moved copies before the counting sort ("moved"), the cell counts and starts, the step's bookkeeping
// and the per-step ring of collision counts and body impulses. Velocities have three components: (x, y)
// in one vec2 buffer (what the viewport draws from) and z in its own.
const uint kRemoved = 0xFFFFFFFFu; // the cell of a particle that left the domain

layout(std430, binding = 0) buffer SortedPositions { vec2 sortedPosition[]; };
layout(std430, binding = 1) buffer SortedVelocities { vec2 sortedVelocity[]; };
layout(std430, binding = 2) buffer SortedVz { float sortedVz[]; };
layout(std430, binding = 3) buffer MovedPositions { vec2 movedPosition[]; };
layout(std430, binding = 4) buffer MovedVelocities { vec2 movedVelocity[]; };
layout(std430, binding = 5) buffer MovedVz { float movedVz[]; };
layout(std430, binding = 6) buffer MovedCells { uvec2 movedCell[]; }; // (cell, slot in cell) or kRemoved
layout(std430, binding = 7) buffer CellCounts { uint cellCounts[]; };  // cells + 1, zero between sorts
layout(std430, binding = 8) buffer CellStarts { uint cellStarts[]; };  // cells + 1: [cells] = particles
// Bookkeeping the host never waits for: counts and the group counts of the indirect dispatches.
layout(std430, binding = 9) buffer Book {
    uint sortedCount;       // particles in the sorted buffers
    uint movedCount;        // particles in the moved buffers (sorted ones plus those entering)
    uint moveGroups[3];     // indirect dispatch over sortedCount
    uint scatterGroups[3];  // indirect dispatch over movedCount
};
// Per step (ring slot): [0] accepted collisions, [1] unused, then per body b the gas's momentum change
// per molecular mass Σ Δv as 64-bit fixed point (x low, x high, y low, y high words) at 2⁻¹² m/s.
layout(std430, binding = 10) buffer StepRing { uint stepRing[]; };

uniform uvec2 seedWords;
uniform uint stepIndex;    // the model's step counter (low word): the sequence of every draw this step
uniform float dt;          // [s]
uniform vec4 domain;       // left, bottom, right, top [m]
uniform ivec2 cellDims;    // cells along x and y
uniform vec2 cellInverse;  // 1 / cell width, 1 / cell height [1/m]
uniform uint ringBase;     // first word of this step's ring slot

const float kImpulseQuantum = 4096.0; // fixed-point steps per m/s of Σ Δv

uint cellOf(vec2 p) {
    // Clamped: a particle on the far edge (or a rounding past it) belongs to the last cell.
    const ivec2 c = clamp(ivec2(floor((p - domain.xy) * cellInverse)), ivec2(0), cellDims - 1);
    return uint(c.y * cellDims.x + c.x);
}

uvec3 groupsOf(uint items, uint localSize) {
    const uint groups = (items + localSize - 1u) / localSize;
    const uint x = min(groups, 65535u);
    return uvec3(x, x == 0u ? 1u : (groups + x - 1u) / x, 1u);
}

// A signed 32-bit value as a 64-bit two's-complement (low, high) pair.
uvec2 wide(int value) {
    return uvec2(uint(value), value < 0 ? 0xFFFFFFFFu : 0u);
}

// Adds a 64-bit (low, high) value into a sum kept as two words of the ring: the low word's carry goes
// into the high word, so the sum is exact modulo 2⁶⁴ in any order of additions.
void addWideToRing(uint lowIndex, uvec2 value) {
    const uint before = atomicAdd(stepRing[lowIndex], value.x);
    const uint carry = before + value.x < before ? 1u : 0u;
    if (value.y + carry != 0u) atomicAdd(stepRing[lowIndex + 1u], value.y + carry);
}

// Two standard normal deviates from two words (Box–Muller).
vec2 gaussianPair(uint a, uint b) {
    const float r = sqrt(-2.0 * log(unitOpen32(a)));
    const float phi = 6.28318530718 * unitOpen32(b);
    return r * vec2(cos(phi), sin(phi));
}

// Full accommodation (Bird 1994 §12.4; docs/wind-tunnel.md#boundaries): the re-emitted molecules are
// the flux of a Maxwellian at the wall's temperature, σ = √(kT_w/m): the normal speed
// σ √(−2 ln u) (flux-weighted half-range), the tangential and z components N(0, σ²), all in the frame
// of the wall, which moves at wallVelocity.
vec3 diffuseVelocity(vec2 inwardNormal, float sigma, vec2 wallVelocity, uvec4 w) {
    const float normalSpeed = sigma * sqrt(-2.0 * log(unitOpen32(w.x)));
    const vec2 other = sigma * gaussianPair(w.y, w.z);
    const vec2 tangent = vec2(-inwardNormal.y, inwardNormal.x);
    return vec3(wallVelocity + inwardNormal * normalSpeed + tangent * other.x, other.y);
}
