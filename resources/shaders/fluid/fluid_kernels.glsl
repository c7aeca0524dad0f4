// The SPH kernels and per-pair terms of Position-Based Fluids: the GLSL twin of core/fluid/FluidKernels.h
// (same names and equations, float instead of double; the constants come from Kernels::make()).
uniform float kernelH, kernelH2;  // support h and h² [L, L²]
uniform float poly6;              // W(r) = poly6 (h² − r²)³
uniform float spikyGrad;          // ∇W(r) = −spikyGrad (h − r)² r̂
uniform float selfWeight;         // W(0) when the self term is on, else 0
uniform float scorrK, scorrInverseReference; // s_corr = −k (W / W(Δq h))ⁿ (eq. 13)
uniform int scorrN;

// Poly6 from the squared distance; a pair at r = 0 weighs nothing (Kernels::w).
float w(float r2) {
    if (r2 >= kernelH2 || r2 <= 0.0) return 0.0;
    const float d = kernelH2 - r2;
    return poly6 * d * d * d;
}

// ∇_i W_spiky(x_i − x_j) as the factor multiplying x_i − x_j; zero at r = 0 and beyond h.
float gradFactor(float r2) {
    if (r2 >= kernelH2 || r2 <= 0.0) return 0.0;
    const float r = sqrt(r2);
    const float d = kernelH - r;
    return -spikyGrad * d * d / r;
}

// Artificial pressure (eq. 13).
float artificialPressure(float weight) {
    if (scorrK == 0.0) return 0.0;
    const float ratio = weight * scorrInverseReference;
    float p = ratio;
    for (int e = 1; e < scorrN; ++e) p *= ratio;
    return -scorrK * p;
}
