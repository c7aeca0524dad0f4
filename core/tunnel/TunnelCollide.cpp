// Indexing and collisions (Bird 1994 §11.1): a counting sort puts the molecules in cell order, then
// the No-Time-Counter scheme collides pairs within each cell, V_c the open part of the cell's volume
// where a body cuts it. Cells are independent, so they collide on several threads with random numbers
// keyed by (cell, step): the same result at any thread count.
#include "TunnelModel.h"

#include "common/Parallel.h"
#include "common/StopRequest.h"

#include <algorithm>
#include <cmath>
#include <omp.h>

namespace pl {

namespace {
// Sub-sampling points per cell side for the open fraction: 16² points resolve it to ~0.4 % of a cell.
constexpr int kOpenSamples = 16;
// Cells opened less than this collide as if this open: a sliver's few molecules would otherwise see
// an unbounded density.
constexpr double kMinOpenFraction = 0.05;
constexpr std::uint32_t kGone = 0xffffffffu;
} // namespace

std::vector<double> TunnelModel::openFractions(const TunnelParams& p,
                                               const std::vector<Obstacle>& obstacles) {
    const auto nx = static_cast<std::size_t>(p.cellsX), ny = static_cast<std::size_t>(p.cellsY);
    std::vector<double> open(nx * ny, 1.0);
    const double dx = p.cellWidth(), dy = p.cellHeight();
    // Each cell under a body's bounding box, with the bodies whose boxes reach it: a cell's samples are
    // tested against those alone, so many bodies cost their cells, not bodies² × cells.
    std::vector<std::pair<std::size_t, std::uint32_t>> reach; // (cell, body), sorted by cell then body
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
        const Obstacle& o = obstacles[k];
        const double hx = o.shape == Obstacle::Shape::Disc ? o.radius : o.halfWidth;
        const double hy = o.shape == Obstacle::Shape::Disc ? o.radius : o.halfHeight;
        const auto lo = [](double a, double d, std::size_t n) {
            return static_cast<std::size_t>(std::clamp(std::floor(a / d), 0.0, double(n - 1)));
        };
        const std::size_t i0 = lo(o.x - hx, dx, nx), i1 = lo(o.x + hx, dx, nx);
        const std::size_t j0 = lo(o.y - hy, dy, ny), j1 = lo(o.y + hy, dy, ny);
        for (std::size_t j = j0; j <= j1; ++j)
            for (std::size_t i = i0; i <= i1; ++i)
                reach.emplace_back(j * nx + i, static_cast<std::uint32_t>(k));
    }
    std::sort(reach.begin(), reach.end());
    for (std::size_t first = 0; first < reach.size();) {
        const std::size_t cell = reach[first].first;
        std::size_t last = first;
        while (last < reach.size() && reach[last].first == cell) ++last;
        const double i = double(cell % nx), j = double(cell / nx);
        int covered = 0;
        for (int b = 0; b < kOpenSamples; ++b)
            for (int a = 0; a < kOpenSamples; ++a) {
                const double x = (i + (a + 0.5) / kOpenSamples) * dx;
                const double y = (j + (b + 0.5) / kOpenSamples) * dy;
                bool inside = false;
                for (std::size_t r = first; r < last && !inside; ++r)
                    inside = obstacles[reach[r].second].contains(x, y, 0.0);
                covered += inside;
            }
        open[cell] = 1.0 - double(covered) / double(kOpenSamples * kOpenSamples);
        first = last;
    }
    return open;
}

void TunnelModel::sortIntoCells(bool reorder) {
    // Molecules that left (cell kGone) are replaced by the last one: O(removed), deterministic.
    for (std::size_t i = 0; i < state_.size();)
        if (state_.cell[i] == kGone)
            state_.removeSwap(i);
        else
            ++i;
    // A stable counting sort of the indices by cell, in parallel: each thread counts its contiguous
    // range, the prefix sums give each (cell, range) its slots, and each thread scatters its range.
    // The result is the one stable order whatever the number of threads.
    const std::size_t cells = openFraction_.size();
    const std::size_t n = state_.size();
    const std::uint32_t* cell = state_.cell.data();
    const bool parallel = static_cast<long long>(n) >= kParallelMinParticles;
    const int parts = parallel ? std::max(1, omp_get_max_threads()) : 1;
    partCounts_.assign(static_cast<std::size_t>(parts) * cells, 0);
    cellStart_.assign(cells + 1, 0);
    if (stepStart_.keeping) { // the step start's order goes aside whole; an undo swaps it back
        stepStart_.order.swap(order_);
        stepStart_.sorted = true;
    }
    order_.resize(n);
    // A stop request between the count and the scatter skips the scatter (each a pass over the
    // molecules); an exception may not leave the parallel region, so the step is left after it.
    bool abandon = false;
#pragma omp parallel num_threads(parts) if (parallel)
    {
        const auto team = static_cast<std::size_t>(omp_get_num_threads());
        const auto t = static_cast<std::size_t>(omp_get_thread_num());
        const std::size_t lo = n * t / team, hi = n * (t + 1) / team;
        std::uint32_t* slot = partCounts_.data() + t * cells;
        for (std::size_t i = lo; i < hi; ++i) ++slot[cell[i]];
#pragma omp barrier
#pragma omp single
        {
            std::uint32_t running = 0;
            for (std::size_t c = 0; c < cells; ++c) {
                cellStart_[c] = running;
                for (std::size_t r = 0; r < team; ++r) {
                    const std::uint32_t count = partCounts_[r * cells + c];
                    partCounts_[r * cells + c] = running;
                    running += count;
                }
            }
            cellStart_[cells] = running;
            abandon = abandoningStep();
        }
        if (!abandon)
            for (std::size_t i = lo; i < hi; ++i) order_[slot[cell[i]]++] = static_cast<std::uint32_t>(i);
    }
    if (abandon) throw StepAbandoned();
    if (!reorder) return;
    // Now and then the arrays themselves follow the cells, so a cell's molecules share cache lines
    // (each molecule moves less than a cell per step, so the order decays slowly).
    scratch_.resize(n);
    for (std::vector<double>* column : {&state_.x, &state_.y, &state_.vx, &state_.vy, &state_.vz}) {
        leaveIfAbandoning(); // a step's sort in the middle: the undo swaps the whole arrays back
        const std::vector<double>& source = *column;
#pragma omp parallel for schedule(static) if (parallel)
        for (std::size_t k = 0; k < n; ++k) scratch_[k] = source[order_[k]];
        column->swap(scratch_);
    }
    for (std::size_t c = 0; c < cells; ++c)
        std::fill(state_.cell.begin() + cellStart_[c], state_.cell.begin() + cellStart_[c + 1],
                  static_cast<std::uint32_t>(c));
    for (std::size_t k = 0; k < n; ++k) order_[k] = static_cast<std::uint32_t>(k);
}

void TunnelModel::collide(double h) {
    const std::size_t cells = openFraction_.size();
    const double m = params_.mass();
    const double cellVolume = params_.cellWidth() * params_.cellHeight(); // × 1 m of depth
    const std::uint64_t base = tunnel::stepBase(stepCount());
    const std::uint64_t seed = seed_;
    const double fn = params_.fn;
    long long accepted = 0;
    const bool parallel = static_cast<long long>(state_.size()) >= kParallelMinParticles;
    double* vx = state_.vx.data();
    double* vy = state_.vy.data();
    double* vz = state_.vz.data();
    const std::uint32_t* order = order_.data();
    // σ c_r = A c_r^(2 − 2ω) from c_r² (no square root): (c_r²)^(1 − ω), with the exact fast paths.
    const CollisionModel model = collisions_;
    const double halfExponent = 1.0 - model.omega;
    const auto sigmaCrOf = [model, halfExponent](double cr2) {
        switch (model.kind) {
        case CollisionModel::Kind::HardSphere:
            return model.prefactor * std::sqrt(cr2);
        case CollisionModel::Kind::Maxwell:
            return model.prefactor;
        case CollisionModel::Kind::InverseRoot:
            return model.prefactor * std::sqrt(std::sqrt(cr2));
        case CollisionModel::Kind::Vhs:
            break;
        }
        return model.prefactor * std::pow(cr2, halfExponent);
    };
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : accepted) if (parallel)
    for (std::size_t c = 0; c < cells; ++c) {
        if (abandoningStep()) continue; // the step is undone: skip the rest (common/StopRequest.h)
        const std::uint32_t first = cellStart_[c];
        const std::uint32_t count = cellStart_[c + 1] - first;
        if (count < 2 || openFraction_[c] <= 0.0) continue;
        const double volume = cellVolume * std::max(openFraction_[c], kMinOpenFraction);
        double& sigmaCrMax = cellSigmaCrMax_[c];
        // NTC candidates (Bird 1994 eq. 11.3): ½ N (N − 1) F_N (σ c_r)_max Δt / V_c, the fraction carried.
        const double wanted = 0.5 * count * (count - 1.0) * fn * sigmaCrMax * h / volume + remainder_[c];
        const auto candidates = static_cast<long long>(wanted);
        remainder_[c] = wanted - static_cast<double>(candidates);
        for (long long k = 0; k < candidates; ++k) {
            const Philox4x32 w =
                randomWords(seed, RngPurpose::TunnelCollision, static_cast<std::uint32_t>(c),
                            base + (std::uint64_t{1} << 31) + 2 * static_cast<std::uint64_t>(k));
            // A random distinct pair of the cell.
            const std::uint32_t i = dsmc::randomIndex(w[0], count);
            std::uint32_t j = dsmc::randomIndex(w[1], count - 1);
            if (j >= i) ++j;
            const std::uint32_t a = order[first + i], b = order[first + j];
            dsmc::Velocity va{vx[a], vy[a], vz[a]}, vb{vx[b], vy[b], vz[b]};
            const double rx = va.x - vb.x, ry = va.y - vb.y, rz = va.z - vb.z;
            const double sigmaCr = sigmaCrOf(rx * rx + ry * ry + rz * rz);
            // Bird raises (σ c_r)_max as soon as a pair exceeds it; that pair is then accepted.
            if (sigmaCr > sigmaCrMax) sigmaCrMax = sigmaCr;
            if (unitOpen32(w[2]) * sigmaCrMax >= sigmaCr) continue;
            const Philox4x32 angles =
                randomWords(seed, RngPurpose::TunnelCollision, static_cast<std::uint32_t>(c),
                            base + (std::uint64_t{1} << 31) + 2 * static_cast<std::uint64_t>(k) + 1);
            dsmc::scatterIsotropic(va, vb, m, m, unitOpen(angles[0], angles[1]),
                                   unitOpen(angles[2], angles[3]));
            vx[a] = va.x, vy[a] = va.y, vz[a] = va.z;
            vx[b] = vb.x, vy[b] = vb.y, vz[b] = vb.z;
            ++accepted;
        }
    }
    collisionsThisStep_ = accepted;
    sigmaCrMax_ = cells > 0 ? *std::max_element(cellSigmaCrMax_.begin(), cellSigmaCrMax_.end()) : 0.0;
}

} // namespace pl
