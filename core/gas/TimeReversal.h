// Time reversal, measured (the methods lab): run a chaotic periodic soft-disk gas n steps forward,
// reverse it, run n steps back, and measure how far it lands from where it started (the Loschmidt
// echo). In double and float arithmetic round-off grows exponentially with n; in the bit-reversible
// integer scheme of Levesque & Verlet (J. Stat. Phys. 72, 519, 1993) the return is exact.
#pragma once

#include <cstdint>
#include <vector>

namespace pl::gas {

// A small gas in a periodic square box (no walls: periodic images keep every step reversible).
struct EchoSetup {
    int disks = 64;         // on a square lattice, random directions at one speed
    double box = 1.0;       // [L]
    double diameter = 0.08; // [L]; area fraction 0.32 at the defaults
    double stiffness = 1e4; // k of U = k/2 (d − r)² [M/T²], unit masses
    double speed = 1.0;     // [L/T]
    double dt = 1e-3;       // [T]; ω dt = √(2k) dt = 0.14
    std::uint64_t seed = 1;
};

struct EchoPoint {
    long long steps = 0;   // n forward, then n back
    double rmsDouble = 0;  // rms distance from the start after the return [L], velocity Verlet in double
    double rmsFloat = 0;   // the same in float
    double rmsInteger = 0; // the integer scheme (0 when it is exact)
};

// The echo after each n in steps (each run starts afresh from the same state).
std::vector<EchoPoint> loschmidtEcho(const EchoSetup& setup, const std::vector<long long>& steps);

// Levesque–Verlet: positions are integers on a lattice of spacing Δ = box / 2³², updated in position
// (Störmer) form X_{n+1} = 2 X_n − X_{n−1} + round(h² a(X_n) / Δ). The rounded force depends on X_n
// alone, so X_{n−1} = 2 X_n − X_{n+1} + the same integer: swapping the two stored configurations runs
// time backwards bit for bit. Positions are kept unwrapped (64-bit: no overflow in 10¹² steps at the
// defaults); forces use the minimum image.
class IntegerVerletGas {
public:
    explicit IntegerVerletGas(const EchoSetup& setup);
    void step();
    void reverse(); // exchange the previous and the current configuration
    const std::vector<std::int64_t>& x() const { return x_; }
    const std::vector<std::int64_t>& y() const { return y_; }
    double spacing() const { return spacing_; }
    // rms distance to another gas of the same setup [L]
    double rmsDistance(const IntegerVerletGas& other) const;

private:
    void forces(std::vector<std::int64_t>& fx, std::vector<std::int64_t>& fy) const;

    EchoSetup setup_;
    double spacing_;                          // Δ [L]
    std::vector<std::int64_t> x_, y_;         // X_n
    std::vector<std::int64_t> xPrev_, yPrev_; // X_{n−1}
    std::vector<std::int64_t> fx_, fy_;       // scratch
};

} // namespace pl::gas
