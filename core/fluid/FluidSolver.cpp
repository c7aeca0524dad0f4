// The passes of one PBF step (Macklin & Müller 2013, Algorithm 1). Every loop writes only particle i and
// reads its neighbours' values from the previous pass (Jacobi), so results do not depend on the thread
// count and each loop maps onto one GPU dispatch.
#include "FluidLambdaPass.h"
#include "FluidModel.h"

#include "common/Parallel.h"
#include "common/StopRequest.h"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {
using fluid::BlockPair;

long long loopCount(const FluidState& state) {
    return static_cast<long long>(state.size());
}
} // namespace

// Lines 1–4: v ← v + Δt f_ext; x* ← x + Δt v, kept inside the walls and out of obstacles.
void FluidModel::applyExternalForcesAndPredict() {
    const std::size_t count = state_.size();
    px_.resize(count);
    py_.resize(count);
    nextX_.resize(count);
    nextY_.resize(count);
    lambda_.resize(count);
    constraint_.resize(count);
    const double dt = params_.dt;
    const double gx = params_.accelerationX();
    const double gy = params_.accelerationY();
    const fluid::Box box = confinementBox();
    const fluid::WallJitter jitter = wallJitter();
    const double margin = params_.particleRadius;
    const long long n = loopCount(state_);
    double *x = state_.x.data(), *y = state_.y.data(), *vx = state_.vx.data(), *vy = state_.vy.data();
    double *px = px_.data(), *py = py_.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        vx[i] += dt * gx;
        vy[i] += dt * gy;
        px[i] = x[i] + dt * vx[i];
        py[i] = y[i] + dt * vy[i];
        fluid::confine(box, obstacles_, margin, jitter, static_cast<std::uint32_t>(i), px[i], py[i]);
    }
}

// Lines 5–7: neighbours within the search radius (1.05 h in the write-up) of the predicted positions, found
// once and kept through the iterations; the corrections move particles by a fraction of h.
// The iterations then run in solver numbers (FluidNeighbours.h): px_, py_ and every per-particle array of
// the λ and Δx passes are in cell order until leaveSolverNumbers().
void FluidModel::findNeighbours() {
    neighbours_.buildLanePairs(px_.data(), py_.data(), state_.size(), params_.neighbourRadius(),
                               params_.boxWidth, params_.boxHeight);
    std::copy_n(neighbours_.sortedX(), state_.size(), px_.begin());
    std::copy_n(neighbours_.sortedY(), state_.size(), py_.begin());
}

// The corrected positions back in particle numbers, for the velocity update and what follows.
void FluidModel::leaveSolverNumbers() {
    const long long n = loopCount(state_);
    const std::uint32_t* rank = neighbours_.rank();
    const auto toParticleNumbers = [&](std::vector<double>& values) {
        const double* from = values.data();
        double* to = nextX_.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
        for (long long i = 0; i < n; ++i) to[i] = from[rank[i]];
        values.swap(nextX_);
    };
    toParticleNumbers(px_);
    toParticleNumbers(py_);
    if (params_.releaseLimit > 0) {
        toParticleNumbers(velocityX_);
        toParticleNumbers(velocityY_);
    }
}

// The bounded release. The soft solver (ε = 1, 5 iterations) holds a pool up by compressing it: 1.35 % on
// average in the fluid-obstacle pool at rest, 5.8 % at its floor. Unloaded (gravity switched off), that
// compression would be released as velocity, v = (x* − x)/Δt, and the floor, which only pushes, would
// launch the pool at the ceiling (docs/fluid.md#stored-compression). As rigid-body solvers keep the
// correction of old position error out of the velocity (the split impulses of Bullet and Box2D), the
// correction is split here into the share that removes the compression arising during the step (an impact,
// the step's load), solved on C_i − b_i with b_i = max(C_i(x), 0) measured at the step's start, and the rest,
// which removes b_i: the positions take both, the velocity the rest only up to release_limit |g| Δt per
// step, enough to carry the load a resting pool's compression carries. The neighbour rows of x* serve for x.
void FluidModel::measureOldCompression() {
    const long long n = loopCount(state_);
    startX_.resize(state_.size());
    startY_.resize(state_.size());
    oldCompression_.resize(state_.size());
    const std::uint32_t* order = neighbours_.order();
    const double *x = state_.x.data(), *y = state_.y.data();
    double *sx = startX_.data(), *sy = startY_.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long k = 0; k < n; ++k) { // solver numbers
        sx[k] = x[order[k]];
        sy[k] = y[order[k]];
    }
    startX_.swap(px_);
    startY_.swap(py_);
    computeLambdas(kNotProfiled); // C_i(x) into constraint_
    startX_.swap(px_);
    startY_.swap(py_);
    double* b = oldCompression_.data();
    const double* c = constraint_.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long k = 0; k < n; ++k) b[k] = std::max(c[k], 0.0);
}

// The iterations on the step's new compression, from x*; x* is restored for the full solve.
void FluidModel::solveNewCompression() {
    measureOldCompression();
    predictedX_.assign(px_.begin(), px_.end());
    predictedY_.assign(py_.begin(), py_.end());
    for (long long k = 0; k < params_.iterations; ++k) {
        leaveIfAbandoning();
        computeLambdas(kNotProfiled, true);
        applyPositionCorrections();
    }
    px_.swap(predictedX_);
    py_.swap(predictedY_);
    velocityX_.swap(predictedX_); // the new compression's solve
    velocityY_.swap(predictedY_);
}

// x_v = x_new + (x_full − x_new) shortened to at most release_limit |g| Δt²: the positions the velocity
// update reads; the full solve's x* stays the position.
void FluidModel::limitRelease() {
    const long long n = loopCount(state_);
    const double limit = params_.releaseLimit * std::hypot(params_.accelerationX(), params_.accelerationY()) *
                         params_.dt * params_.dt; // [L]
    const double *px = px_.data(), *py = py_.data();
    double *vx = velocityX_.data(), *vy = velocityY_.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long k = 0; k < n; ++k) {
        const double ox = px[k] - vx[k], oy = py[k] - vy[k];
        const double length = std::sqrt(ox * ox + oy * oy);
        const double scale = length > limit ? limit / length : 1.0;
        vx[k] += ox * scale;
        vy[k] += oy * scale;
    }
}

// Lines 9–11: ρ_i = Σ_j W(x_i − x_j) (eq. 2), C_i = ρ_i/ρ₀ − 1 (eq. 1),
// λ_i = −C_i / (Σ_k |∇_k C_i|² + ε) (eq. 11) with ∇_i C_i = Σ_j ∇W_ij / ρ₀ and ∇_j C_i = −∇W_ij / ρ₀ (eq. 8).
// The pair terms the correction pass needs at these same positions are kept: ∇W_ij per neighbour slot,
// G_i = Σ_j ∇W_ij and S_i = Σ_j s_corr,ij ∇W_ij, so that pass costs one multiply-add per pair.
// Two particles per step of the loop, each summing over its own row in row order (FluidKernels.h, Lanes), or
// two slots of both rows per AVX instruction (FluidLambdaPass.h).
void FluidModel::computeLambdas(std::size_t iteration, bool newOnly) {
    const long long n = loopCount(state_);
    pairGradX_.resize(neighbours_.laneSlots());
    pairGradY_.resize(neighbours_.laneSlots());
    gradSumX_.resize(state_.size());
    gradSumY_.resize(state_.size());
    scorrSumX_.resize(state_.size());
    scorrSumY_.resize(state_.size());
    const fluid::LambdaArrays arrays{px_.data(),
                                     py_.data(),
                                     neighbours_.blockStart(),
                                     neighbours_.laneEntries(),
                                     lambda_.data(),
                                     constraint_.data(),
                                     pairGradX_.data(),
                                     pairGradY_.data(),
                                     gradSumX_.data(),
                                     gradSumY_.data(),
                                     scorrSumX_.data(),
                                     scorrSumY_.data(),
                                     n,
                                     newOnly ? oldCompression_.data() : nullptr};
    const fluid::LambdaConstants constants{fluid::LaneKernels(kernels_, scorr_), kernels_.selfWeight(),
                                           1.0 / restDensity_, params_.epsilon, params_.compressionOnly};
    const fluid::LambdaBlocksFunction blocks = fluid::lambdaBlocks(); // AVX where the CPU has it
#pragma omp parallel if (n >= kParallelMinParticles)
    {
        const auto [first, end] = neighbours_.threadBlocks(); // equal shares of the slots
        blocks(arrays, constants, first, end);
    }
    if (iteration == kNotProfiled) return;
    const double* constraint = constraint_.data();
    // Serial sums in particle order: the same bits for any thread count.
    const std::uint32_t* rank = neighbours_.rank();
    double sum = 0, largest = 0;
    for (long long i = 0; i < n; ++i) {
        const double compression = std::max(constraint[rank[i]], 0.0);
        sum += compression;
        largest = std::max(largest, compression);
    }
    errorMean_[iteration] = n > 0 ? sum / static_cast<double>(n) : 0.0;
    errorMax_[iteration] = largest;
}

// Lines 13–16: Δx_i = (1/ρ₀) Σ_j (λ_i + λ_j + s_corr) ∇W_ij (eq. 14) = (λ_i G_i + Σ_j λ_j ∇W_ij + S_i)/ρ₀,
// then collision response; the new positions go to a second buffer so every particle sees its
// neighbours' positions of this iteration. A padded slot holds ∇W = 0 and adds nothing.
void FluidModel::applyPositionCorrections() {
    const long long n = loopCount(state_);
    const double *px = px_.data(), *py = py_.data(), *lambda = lambda_.data();
    const double *pgx = pairGradX_.data(), *pgy = pairGradY_.data();
    const double *sumGx = gradSumX_.data(), *sumGy = gradSumY_.data(), *sumSx = scorrSumX_.data(),
                 *sumSy = scorrSumY_.data();
    double *nx = nextX_.data(), *ny = nextY_.data();
    const std::uint32_t *blockStart = neighbours_.blockStart(), *lanes = neighbours_.laneEntries(),
                        *order = neighbours_.order();
    const Lanes inverseRest = Lanes::all(1.0 / restDensity_);
    const fluid::Box box = confinementBox();
    const fluid::WallJitter jitter = wallJitter();
    const double margin = params_.particleRadius;
#pragma omp parallel if (n >= kParallelMinParticles)
    for (auto [b, end] = neighbours_.threadBlocks(); b < end; ++b) { // equal shares of the slots
        const BlockPair pair(b, n);
        const Lanes li = pair.gather(lambda);
        Lanes sx = li * pair.gather(sumGx) + pair.gather(sumSx);
        Lanes sy = li * pair.gather(sumGy) + pair.gather(sumSy);
        for (std::size_t e = 2 * std::size_t{blockStart[b]}; e < 2 * std::size_t{blockStart[b + 1]}; e += 2) {
            const Lanes l = Lanes::gather(lambda, lanes[e], lanes[e + 1]);
            sx += l * Lanes::load(pgx + e);
            sy += l * Lanes::load(pgy + e);
        }
        pair.scatter(pair.gather(px) + sx * inverseRest, nx);
        pair.scatter(pair.gather(py) + sy * inverseRest, ny);
        // The wall jitter is keyed by the particle number.
        fluid::confine(box, obstacles_, margin, jitter, order[pair.first], nx[pair.first], ny[pair.first]);
        if (pair.second != pair.first)
            fluid::confine(box, obstacles_, margin, jitter, order[pair.second], nx[pair.second],
                           ny[pair.second]);
    }
    px_.swap(nextX_);
    py_.swap(nextY_);
}

// Lines 20–21: v ← (x* − x)/Δt; a particle touching an obstacle does not move into it faster than it moves.
// With the bounded release, x* there is limitRelease()'s x_v.
void FluidModel::updateVelocities() {
    const long long n = loopCount(state_);
    const double inverseDt = 1.0 / params_.dt;
    const double margin = params_.particleRadius;
    const bool limited = params_.releaseLimit > 0;
    const double *x = state_.x.data(), *y = state_.y.data(), *px = px_.data(), *py = py_.data();
    const double *ux = limited ? velocityX_.data() : px, *uy = limited ? velocityY_.data() : py;
    double *vx = state_.vx.data(), *vy = state_.vy.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        vx[i] = (ux[i] - x[i]) * inverseDt;
        vy[i] = (uy[i] - y[i]) * inverseDt;
        if (!obstacles_.empty()) fluid::obstacleVelocity(obstacles_, margin, px[i], py[i], vx[i], vy[i]);
    }
}

// Line 22, first half (eqs. 15–16) in 2D: the vorticity is a scalar, ω_i = Σ_j v_ij × ∇_j W_ij with
// v_ij = v_j − v_i; η = ∇|ω| (an SPH gradient, volumes 1/ρ₀), N = η/|η|, f = ε (N × ω ẑ) = ε ω (N_y, −N_x).
void FluidModel::applyVorticityConfinement() {
    const long long n = loopCount(state_);
    omega_.resize(state_.size());
    const double *px = px_.data(), *py = py_.data();
    double *vx = state_.vx.data(), *vy = state_.vy.data(), *omega = omega_.data();
    const std::uint32_t *lanes = neighbours_.laneEntries(), *counts = neighbours_.counts(),
                        *order = neighbours_.order(), *rank = neighbours_.rank();
    const fluid::Neighbours& list = neighbours_;
    const fluid::Kernels k = kernels_;
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        double w = 0;
        const std::uint32_t solver = rank[i];
        const std::uint32_t* row = lanes + list.rowStart(solver);
        for (std::uint32_t t = 0; t < counts[solver]; ++t) {
            const std::uint32_t j = order[row[2 * t]];
            const double dx = px[i] - px[j], dy = py[i] - py[j];
            const double f = k.gradFactor(dx * dx + dy * dy); // ∇_i W = f (dx, dy); ∇_j W = −∇_i W
            const double ux = vx[j] - vx[i], uy = vy[j] - vy[i];
            w -= ux * (f * dy) - uy * (f * dx);
        }
        omega[i] = w;
    }
    const double strength = params_.vorticity * params_.dt;
    const double inverseRest = 1.0 / restDensity_;
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        double ex = 0, ey = 0;
        const std::uint32_t solver = rank[i];
        const std::uint32_t* row = lanes + list.rowStart(solver);
        for (std::uint32_t t = 0; t < counts[solver]; ++t) {
            const std::uint32_t j = order[row[2 * t]];
            const double dx = px[i] - px[j], dy = py[i] - py[j];
            const double f = k.gradFactor(dx * dx + dy * dy) * (std::abs(omega[j]) - std::abs(omega[i]));
            ex += f * dx;
            ey += f * dy;
        }
        ex *= inverseRest;
        ey *= inverseRest;
        const double length = std::hypot(ex, ey);
        if (length < 1e-12) continue;
        vx[i] += strength * omega[i] * ey / length;
        vy[i] -= strength * omega[i] * ex / length;
    }
}

// Surface forces (Akinci, Akinci & Teschner 2013, "Versatile surface tension and adhesion for SPH fluids"):
// cohesion, eq. 1, a_i = −γ Σ_j C(r_ij) x̂_ij, and adhesion to the walls and obstacles, eq. 6, with their
// splines scaled to 1 at their peaks (FluidBoundaries.h, cohesionSpline and adhesionSpline). Neighbours
// beyond h/2 attract and closer ones repel, so the interior, surrounded evenly, feels nothing and the free
// surface is pulled in; the walls draw the fluid within h of them, so it wets them instead of balling up.
// Without them nothing but gravity holds a particle that the solver's noise lifts off the surface
// (docs/fluid.md#surface-forces). The neighbour pairs are the step's, at x*, as in the vorticity pass; each
// row is summed in its order, so any thread count gives the same bits.
void FluidModel::applySurfaceForces() {
    const long long n = loopCount(state_);
    const double *px = px_.data(), *py = py_.data();
    double *vx = state_.vx.data(), *vy = state_.vy.data();
    const std::uint32_t *lanes = neighbours_.laneEntries(), *counts = neighbours_.counts(),
                        *order = neighbours_.order(), *rank = neighbours_.rank();
    const fluid::Neighbours& list = neighbours_;
    const fluid::Adhesion adhesion{params_.boxWidth, params_.boxHeight, params_.h, params_.adhesion};
    const double cohesion = params_.cohesion, inverseH = 1.0 / params_.h, dt = params_.dt;
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        double ax = 0, ay = 0;
        const std::uint32_t solver = rank[i];
        const std::uint32_t* row = lanes + list.rowStart(solver);
        for (std::uint32_t t = 0; t < counts[solver]; ++t) {
            const std::uint32_t j = order[row[2 * t]];
            const double dx = px[i] - px[j], dy = py[i] - py[j];
            const double r = std::sqrt(dx * dx + dy * dy);
            if (!(r > 0)) continue; // the particle itself (or one on top of it: no direction)
            const double c = fluid::cohesionSpline(r * inverseH) / r;
            ax -= c * dx;
            ay -= c * dy;
        }
        ax *= cohesion;
        ay *= cohesion;
        if (adhesion.strength > 0) adhesion.add(obstacles_, px[i], py[i], ax, ay);
        vx[i] += dt * ax;
        vy[i] += dt * ay;
    }
}

// Line 22, second half (eq. 17): XSPH viscosity v_i ← v_i + c Σ_j (v_j − v_i) W_ij, two particles per step
// of the loop as in the λ pass; a padded slot has W = 0 and adds +0.
void FluidModel::applyXsphViscosity() {
    const long long n = loopCount(state_);
    nextVx_.resize(state_.size());
    nextVy_.resize(state_.size());
    const double *px = px_.data(), *py = py_.data(), *vx = state_.vx.data(), *vy = state_.vy.data();
    double *ox = nextVx_.data(), *oy = nextVy_.data();
    const std::uint32_t *blockStart = neighbours_.blockStart(), *lanes = neighbours_.laneEntries(),
                        *order = neighbours_.order();
    const fluid::LaneKernels k(kernels_, scorr_);
    const Lanes c = Lanes::all(params_.xsph), zero = Lanes::all(0.0);
    // After leaveSolverNumbers(): particle numbers, the rows' solver numbers translated through order.
#pragma omp parallel if (n >= kParallelMinParticles)
    for (auto [b, end] = neighbours_.threadBlocks(); b < end; ++b) { // equal shares of the slots
        const BlockPair pair(BlockPair(b, n), order);
        const Lanes xi = pair.gather(px), yi = pair.gather(py), ui = pair.gather(vx), wi = pair.gather(vy);
        Lanes sx = zero, sy = zero;
        for (std::size_t e = 2 * std::size_t{blockStart[b]}; e < 2 * std::size_t{blockStart[b + 1]}; e += 2) {
            const std::uint32_t j0 = order[lanes[e]], j1 = order[lanes[e + 1]];
            const Lanes dx = xi - Lanes::gather(px, j0, j1), dy = yi - Lanes::gather(py, j0, j1);
            const Lanes w = k.w(dx * dx + dy * dy);
            sx += (Lanes::gather(vx, j0, j1) - ui) * w;
            sy += (Lanes::gather(vy, j0, j1) - wi) * w;
        }
        pair.scatter(ui + c * sx, ox);
        pair.scatter(wi + c * sy, oy);
    }
    state_.vx.swap(nextVx_);
    state_.vy.swap(nextVy_);
}

// Line 23: x ← x*.
void FluidModel::commitPositions() {
    state_.x.swap(px_);
    state_.y.swap(py_);
}

} // namespace pl
