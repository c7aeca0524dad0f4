// Counter-based random numbers (Philox4x32-10, Salmon et al., SC'11): the same stream for a given
// (seed, particle id, step, purpose) whatever the thread count or backend. The GLSL twin uses the
// same rounds and constants.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace pl {

using Philox4x32 = std::array<std::uint32_t, 4>;

namespace philox_detail {
constexpr std::uint32_t kMul0 = 0xD2511F53u;
constexpr std::uint32_t kMul1 = 0xCD9E8D57u;
constexpr std::uint32_t kWeyl0 = 0x9E3779B9u; // golden ratio
constexpr std::uint32_t kWeyl1 = 0xBB67AE85u; // sqrt(3) - 1
constexpr int kRounds = 10;
} // namespace philox_detail

constexpr Philox4x32 philox4x32(Philox4x32 ctr, std::array<std::uint32_t, 2> key) {
    using namespace philox_detail;
    for (int round = 0; round < kRounds; ++round) {
        if (round > 0) {
            key[0] += kWeyl0;
            key[1] += kWeyl1;
        }
        const std::uint64_t p0 = std::uint64_t{kMul0} * ctr[0];
        const std::uint64_t p1 = std::uint64_t{kMul1} * ctr[2];
        ctr = {static_cast<std::uint32_t>(p1 >> 32) ^ ctr[1] ^ key[0], static_cast<std::uint32_t>(p1),
               static_cast<std::uint32_t>(p0 >> 32) ^ ctr[3] ^ key[1], static_cast<std::uint32_t>(p0)};
    }
    return ctr;
}

// What a random draw is for; part of the counter so that purposes never share numbers.
enum class RngPurpose : std::uint32_t {
    InitialPosition = 1,
    InitialVelocity = 2,
    ThermalWall = 3,
    Spawn = 4,
    Shuffle = 5,
    Collision = 6,
    WallJitter = 7,
    TunnelFill = 8,       // the wind tunnel's initial gas and spawned rectangles
    TunnelInflow = 9,     // molecules entering through an inflow side
    TunnelSurface = 10,   // diffuse re-emission from a side or a body
    TunnelCollision = 11, // NTC pair selection and scattering per cell
};

// Four independent words for (seed, purpose, subject, sequence). subject is usually a particle id and
// sequence a step number or a draw index.
inline Philox4x32 randomWords(std::uint64_t seed, RngPurpose purpose, std::uint32_t subject,
                              std::uint64_t sequence) {
    return philox4x32({subject, static_cast<std::uint32_t>(sequence),
                       static_cast<std::uint32_t>(sequence >> 32), static_cast<std::uint32_t>(purpose)},
                      {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)});
}

// Uniform double in the open interval (0, 1) from two words (53 random bits, never 0 or 1).
inline double unitOpen(std::uint32_t hi, std::uint32_t lo) {
    const std::uint64_t bits = (std::uint64_t{hi} << 21) ^ (lo >> 11);
    return (static_cast<double>(bits & ((std::uint64_t{1} << 53) - 1)) + 0.5) * 0x1.0p-53;
}

// Uniform double in (0, 1) from one word (32 random bits), for draws where that resolution suffices.
inline double unitOpen32(std::uint32_t w) {
    return (static_cast<double>(w) + 0.5) * 0x1.0p-32;
}

struct UniformPair {
    double a, b;
};

inline UniformPair uniformPair(const Philox4x32& w) {
    return {unitOpen(w[0], w[1]), unitOpen(w[2], w[3])};
}

// Two independent standard normal deviates (Box–Muller).
inline UniformPair gaussianPair(const Philox4x32& w) {
    const auto [u1, u2] = uniformPair(w);
    const double r = std::sqrt(-2.0 * std::log(u1));
    return {r * std::cos(2.0 * std::numbers::pi * u2), r * std::sin(2.0 * std::numbers::pi * u2)};
}

} // namespace pl
