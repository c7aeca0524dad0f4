// Initial velocities: the write-up's two beams, a single Maxwellian, or the BKW distribution.
#include "DsmcModel.h"

#include "common/Philox.h"

#include <cmath>

namespace pl {

namespace {
// Independent streams of initial draws.
constexpr std::uint32_t kBeamOneStream = 1, kBeamTwoStream = 2, kBkwStream = 3;

// Subtracts the mean velocity of particles [first, end); returns their Σ|v|² afterwards.
double removeMean(DsmcState& s, std::size_t first) {
    const auto count = static_cast<double>(s.size() - first);
    double mean[3] = {0, 0, 0};
    for (std::size_t i = first; i < s.size(); ++i) {
        mean[0] += s.vx[i];
        mean[1] += s.vy[i];
        mean[2] += s.vz[i];
    }
    for (double& m : mean) m /= count;
    double sum2 = 0;
    for (std::size_t i = first; i < s.size(); ++i) {
        s.vx[i] -= mean[0];
        s.vy[i] -= mean[1];
        s.vz[i] -= mean[2];
        sum2 += s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i];
    }
    return sum2;
}
} // namespace

void DsmcModel::buildInitialState() {
    state_.clear();
    if (params_.initial == DsmcInitialState::Bkw) {
        addBkwPopulation(params_.countA);
    } else if (params_.initial == DsmcInitialState::Maxwellian) {
        addPopulation(params_.countA, 0.0, 0, kBeamOneStream);
    } else {
        addPopulation(params_.countA, params_.driftA, 0, kBeamOneStream);
        addPopulation(params_.countB, params_.driftB, 1, kBeamTwoStream);
    }
}

dsmc::Velocity DsmcModel::drawnVelocity(const DsmcParams& p, std::uint64_t seed, long long k,
                                        std::uint32_t stream) {
    const double sigma = std::sqrt(kBoltzmann * p.temperature / p.mass());
    const auto id = static_cast<std::uint32_t>(k);
    const auto [gx, gy] = gaussianPair(randomWords(seed, RngPurpose::InitialVelocity, id, 2 * stream));
    const auto [gz, unused] =
        gaussianPair(randomWords(seed, RngPurpose::InitialVelocity, id, 2 * stream + 1));
    (void)unused;
    return {sigma * gx, sigma * gy, p.planar() ? 0.0 : sigma * gz};
}

dsmc::Velocity DsmcModel::drawnBkwVelocity(const DsmcParams& p, std::uint64_t seed, long long k) {
    const double scale = std::sqrt(0.6 * kBoltzmann * p.temperature / p.mass());
    const auto id = static_cast<std::uint32_t>(k);
    const auto [g1, g2] = gaussianPair(randomWords(seed, RngPurpose::InitialVelocity, id, 2 * kBkwStream));
    const auto [g3, g4] =
        gaussianPair(randomWords(seed, RngPurpose::InitialVelocity, id, 2 * kBkwStream + 1));
    const auto [g5, unused] =
        gaussianPair(randomWords(seed, RngPurpose::InitialVelocity, id, 2 * kBkwStream + 7));
    (void)unused;
    const double speed = scale * std::sqrt(g1 * g1 + g2 * g2 + g3 * g3 + g4 * g4 + g5 * g5);
    const auto [u1, u2] = uniformPair(randomWords(seed, RngPurpose::InitialVelocity, id, 2 * kBkwStream + 9));
    const double cosTheta = 2.0 * u1 - 1.0, sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * std::numbers::pi * u2;
    return {speed * sinTheta * std::cos(phi), speed * sinTheta * std::sin(phi), speed * cosTheta};
}

dsmc::Velocity DsmcModel::drawnInitialVelocity(const DsmcParams& p, std::uint64_t seed, long long i) {
    if (p.initial == DsmcInitialState::Bkw) return drawnBkwVelocity(p, seed, i);
    if (p.initial == DsmcInitialState::Maxwellian) return drawnVelocity(p, seed, i, kBeamOneStream);
    dsmc::Velocity v = i < p.countA ? drawnVelocity(p, seed, i, kBeamOneStream)
                                    : drawnVelocity(p, seed, i - p.countA, kBeamTwoStream);
    v.x += i < p.countA ? p.driftA : p.driftB;
    return v;
}

void DsmcModel::addPopulation(long long count, double drift, std::uint8_t origin, std::uint32_t stream) {
    if (count <= 0) return;
    // Gaussian thermal velocities, then moment matching: each population's sample mean is removed and its
    // sample temperature set to exactly the parameter, so the mean velocity of the cell is exactly the
    // mean drift and its temperature exactly the analytic value (the write-up's 17.83 K), not that ± noise.
    // (The write-up samples with Birdsall's sum of three uniforms, whose variance gives 1/8 of the requested
    // temperature; we sample the Maxwellian it intends.)
    const std::size_t first = state_.size();
    const double sigma = std::sqrt(kBoltzmann * params_.temperature / params_.mass());
    for (long long k = 0; k < count; ++k) state_.append(drawnVelocity(params_, seed_, k, stream), origin);
    const double sum2 = removeMean(state_, first);
    const auto components = static_cast<double>(params_.velocityComponents);
    const double scale = count > 1 && sum2 > 0
                             ? std::sqrt(components * static_cast<double>(count) * sigma * sigma / sum2)
                             : 0.0;
    for (std::size_t i = first; i < state_.size(); ++i) {
        state_.vx[i] = scale * state_.vx[i] + drift;
        state_.vy[i] *= scale;
        state_.vz[i] *= scale;
    }
}

void DsmcModel::addBkwPopulation(long long count) {
    // BKW at K₀ = 0.6 (docs/dsmc.md#bkw-solution): speed = χ₅ variate × √(0.6 kT/m), direction uniform on the
    // sphere. Only the mean is removed; the moments are normalised by the sampled ⟨c²⟩, which DSMC conserves.
    const std::size_t first = state_.size();
    for (long long k = 0; k < count; ++k) state_.append(drawnBkwVelocity(params_, seed_, k), 0);
    removeMean(state_, first);
}

} // namespace pl
