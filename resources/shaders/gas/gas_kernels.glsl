// Per-pair and per-wall formulas of the gas: the GLSL twin of core/gas/GasKernels.h (same names, argument
// order and equations; float instead of double).

// Pairs closer than this are treated as coincident: no direction, no force [L²].
const float kCoincidentR2 = 1e-24;

struct PairResult {
    vec2 f;          // force on i from j [M·L/T²]
    float potential; // U(r) = k/2 (d − r)² [energy]
    float virial;    // r_ij · f_ij = k (d − r) r [energy]
};

// Harmonic repulsion (docs/gas.md#pair-force): f_ij = k (d − r) r̂_ij for r < d, zero beyond.
bool harmonicPair(vec2 d, float contactDiameter, float stiffness, out PairResult result) {
    const float r2 = dot(d, d);
    if (r2 >= contactDiameter * contactDiameter || r2 < kCoincidentR2) return false;
    const float r = sqrt(r2);
    const float overlap = contactDiameter - r;
    result.f = (stiffness * overlap / r) * d;
    result.potential = 0.5 * stiffness * overlap * overlap;
    result.virial = stiffness * overlap * r;
    return true;
}

// Contact distance of two disks: the mean of their diameters.
float contactDiameter(float di, float dj) {
    return 0.5 * (di + dj);
}

// Mirror reflection off a plane wall at w with outward normal sign·axis, moving with velocity u; only a
// disk moving into the wall in the drift's direction of time is reflected (GasKernels.h explains why).
// Returns (before − after)·sign of the normal velocity, 0 when no crossing happened.
float reflectPlane(inout float p, inout float v, float w, float sign_, float u, float timeSign) {
    if ((p - w) * sign_ <= 0.0) return 0.0;
    p = 2.0 * w - p;
    const float before = v;
    if ((v - u) * sign_ * timeSign > 0.0) v = 2.0 * u - v;
    return (before - v) * sign_;
}
