// The free stream: what enters through each inflow side per step (the exact half-range flux, Bird 1994
// eq. 4.22, with the flux-weighted shifted Maxwellian for the normal velocity, §12.5), and the gas a
// reset or the spawn tool puts into a rectangle (the free-stream number density of each cell's open
// area).
#include "TunnelModel.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace pl {

namespace {

// Draws of a position inside a cut cell before it is given up (the open part is then a sliver).
constexpr int kPlacementTries = 64;

bool insideAnyBody(const std::vector<Obstacle>& obstacles, double x, double y) {
    for (const Obstacle& o : obstacles)
        if (o.contains(x, y, 0.0)) return true;
    return false;
}

// The whole molecules of a cell whose expected number is `expected`, the fraction carried to the next
// cell so the total matches n A / F_N to within one molecule.
long long wholeMolecules(double expected, double& carry) {
    const double wanted = expected + carry;
    const auto whole = static_cast<long long>(wanted);
    carry = wanted - static_cast<double>(whole);
    return whole;
}

// The cells that [x0, x1] × [y0, y1] overlaps and the overlap's area in each, in cell order.
template <class Visit>
void forCellsOf(const TunnelParams& p, double x0, double y0, double x1, double y1, Visit visit) {
    const double dx = p.cellWidth(), dy = p.cellHeight();
    const auto first = [](double a, double d, long long n) {
        return std::clamp(static_cast<long long>(std::floor(a / d)), 0LL, n - 1);
    };
    const long long i0 = first(x0, dx, p.cellsX), i1 = first(x1, dx, p.cellsX);
    const long long j0 = first(y0, dy, p.cellsY), j1 = first(y1, dy, p.cellsY);
    for (long long j = j0; j <= j1; ++j)
        for (long long i = i0; i <= i1; ++i) {
            const double left = std::max(x0, i * dx), right = std::min(x1, (i + 1) * dx);
            const double bottom = std::max(y0, j * dy), top = std::min(y1, (j + 1) * dy);
            if (right <= left || top <= bottom) continue;
            visit(static_cast<std::size_t>(j * p.cellsX + i), left, bottom, right, top);
        }
}

} // namespace

std::size_t TunnelModel::initialFillCount(const TunnelParams& p, const std::vector<Obstacle>& obstacles) {
    if (p.initial == TunnelInitial::Empty) return 0;
    const std::vector<double> open = openFractions(p, obstacles);
    double carry = 0.0;
    long long total = 0;
    forCellsOf(p, 0.0, 0.0, p.boxWidth, p.boxHeight,
               [&](std::size_t c, double left, double bottom, double right, double top) {
                   total += wholeMolecules(p.streamDensity * (right - left) * (top - bottom) * open[c] / p.fn,
                                           carry);
               });
    return static_cast<std::size_t>(total);
}

dsmc::Velocity TunnelModel::freeStreamVelocity(tunnel::CounterRng& rng, bool drifting) const {
    const double sigma = std::sqrt(kBoltzmann * params_.streamTemperature / params_.mass());
    const double drift = drifting ? params_.streamSpeed : 0.0;
    const double vx = drift + sigma * rng.normal();
    const double vy = sigma * rng.normal();
    return {vx, vy, sigma * rng.normal()};
}

TunnelModel::Filled TunnelModel::fillRectangle(double x0, double y0, double x1, double y1, bool drifting,
                                               std::uint64_t call) {
    Filled filled;
    double carry = 0.0;
    forCellsOf(params_, x0, y0, x1, y1,
               [&](std::size_t c, double left, double bottom, double right, double top) {
                   const double expected = params_.streamDensity * (right - left) * (top - bottom) *
                                           openFraction_[c] / params_.fn;
                   const long long count = wholeMolecules(expected, carry);
                   tunnel::CounterRng rng(seed_, RngPurpose::TunnelFill, static_cast<std::uint32_t>(c),
                                          tunnel::stepBase(static_cast<std::int64_t>(call)));
                   for (long long k = 0; k < count; ++k) {
                       bool placed = false;
                       for (int tries = 0; tries < kPlacementTries && !placed; ++tries) {
                           const double x = left + (right - left) * rng.uniform();
                           const double y = bottom + (top - bottom) * rng.uniform();
                           if (insideAnyBody(obstacles_, x, y)) continue;
                           state_.append(x, y, freeStreamVelocity(rng, drifting));
                           state_.cell.back() = static_cast<std::uint32_t>(c);
                           placed = true;
                       }
                       placed ? ++filled.added : ++filled.refused;
                   }
               });
    return filled;
}

std::string TunnelModel::spawnInRectangle(double x0, double y0, double x1, double y1) {
    pullState();
    const double left = std::max(std::min(x0, x1), params_.pistonOn ? pistonX_ : 0.0);
    const double right = std::min(std::max(x0, x1), params_.boxWidth);
    const double bottom = std::max(std::min(y0, y1), 0.0),
                 top = std::min(std::max(y0, y1), params_.boxHeight);
    std::ostringstream message;
    if (!(right > left && top > bottom)) {
        // A point (or a rectangle outside the gas): one molecule at the free-stream state.
        const double x = std::clamp(x0, left, params_.boxWidth), y = std::clamp(y0, 0.0, params_.boxHeight);
        if (insideAnyBody(obstacles_, x, y)) return "Nothing added: the point lies inside a body.";
        tunnel::CounterRng rng(seed_, RngPurpose::TunnelFill, 0xffffffffu,
                               tunnel::stepBase(static_cast<std::int64_t>(streamCounter_++)));
        state_.append(x, y, freeStreamVelocity(rng, true));
        message << "Added 1 molecule at the free-stream state.";
    } else {
        const Filled filled = fillRectangle(left, bottom, right, top, true, streamCounter_++);
        message << "Added " << filled.added
                << " molecules at the free-stream state (n = " << formatNumber(params_.streamDensity, 3)
                << " m⁻³, T = " << formatNumber(params_.streamTemperature, 4) << " K)";
        if (filled.refused > 0) message << "; " << filled.refused << " fell inside bodies and were refused";
        message << '.';
    }
    sortIntoCells();
    restartSampling();
    stateEdited();
    return message.str();
}

void TunnelModel::admitInflow(double h) {
    const TunnelParams& p = params_;
    const TunnelBoundary sides[4] = {p.left, p.right, p.bottom, p.top};
    const double inwardX[4] = {1, -1, 0, 0}, inwardY[4] = {0, 0, 1, -1};
    const double m = p.mass();
    const double sigma = std::sqrt(kBoltzmann * p.streamTemperature / m);
    const double mostProbable = std::numbers::sqrt2 * sigma; // √(2kT/m)
    const std::size_t bodies = obstacles_.size();
    std::vector<double>& impulse = impulseChunks_; // the move's sums are already handed over
    impulse.assign(2 * bodies, 0.0);
    for (int side = 0; side < 4; ++side) {
        if (sides[side] != TunnelBoundary::Inflow || (side == 0 && p.pistonOn)) continue;
        const bool alongX = side < 2;
        const double inwardSpeed = p.streamSpeed * inwardX[side]; // the stream is along +x
        const double s = inwardSpeed / mostProbable;
        const double length = alongX ? p.boxHeight : p.boxWidth;
        const double wanted =
            tunnel::halfRangeFlux(p.streamDensity, sigma, s) * length * h / p.fn + inflowRemainder_[side];
        const auto count = static_cast<long long>(wanted);
        inflowRemainder_[side] = wanted - static_cast<double>(count);
        for (long long k = 0; k < count; ++k) {
            const auto subject = static_cast<std::uint32_t>((std::uint64_t(side) << 28) | std::uint64_t(k));
            tunnel::CounterRng rng(seed_, RngPurpose::TunnelInflow, subject, tunnel::stepBase(stepCount()));
            const double normal = tunnel::inflowNormalSpeedRatio(s, rng) * mostProbable;
            const double along = rng.uniform();
            dsmc::Velocity v;
            double x, y;
            if (alongX) {
                v = {normal * inwardX[side], sigma * rng.normal(), sigma * rng.normal()};
                x = side == 0 ? 0.0 : p.boxWidth;
                y = along * p.boxHeight;
            } else {
                v = {p.streamSpeed + sigma * rng.normal(), normal * inwardY[side], sigma * rng.normal()};
                x = along * p.boxWidth;
                y = side == 2 ? 0.0 : p.boxHeight;
            }
            state_.append(x, y, v);
            // It crossed the side at a uniformly random moment of the step and flies the rest.
            fly(state_.size() - 1, h * (1.0 - rng.uniform()), h, rng, impulse.data());
        }
    }
    for (std::size_t b = 0; b < bodies; ++b)
        if (impulse[2 * b] != 0.0 || impulse[2 * b + 1] != 0.0)
            sampler_.addSurfaceImpulse(b, impulse[2 * b], impulse[2 * b + 1]);
}

} // namespace pl
