// TunnelModelGL: the step as GPU dispatches, and the hand-over of particles and samples to the CPU.
#include "TunnelModelGL.h"

#include "TunnelGpu.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>

namespace pl::gl {

namespace {

// Buffers hold twice the particles of an upload (and at least this many steps of inflow) before the
// host must look at the count.
constexpr std::size_t kMinCapacity = 4096;
constexpr double kInflowStepsOfCapacity = 64.0;

std::array<std::uint32_t, 3> groupsOf(std::size_t items, unsigned localSize) {
    const auto groups = static_cast<std::uint32_t>(groupsFor(items, localSize));
    const std::uint32_t x = std::min<std::uint32_t>(groups, 65535u);
    return {x, x == 0 ? 1u : (groups + x - 1) / x, 1u};
}

// A 64-bit two's-complement fixed-point sum of the ring, in m/s.
double wideValue(std::uint32_t low, std::uint32_t high) {
    const auto bits = static_cast<std::int64_t>((std::uint64_t{high} << 32) | low);
    return static_cast<double>(bits) / kImpulseQuantum;
}

} // namespace

TunnelModelGL::TunnelModelGL(std::shared_ptr<GlContext> context) : GpuHandOver(std::move(context)) {
    gpu_ = std::make_unique<TunnelGpu>();
    reset();
}

TunnelModelGL::TunnelModelGL(std::shared_ptr<GlContext> context, const Preset& preset)
    : GpuHandOver(std::move(context)) {
    gpu_ = std::make_unique<TunnelGpu>();
    reset(preset);
}

TunnelModelGL::~TunnelModelGL() {
    context_->makeCurrent(); // buffers and programs are deleted in their context
}

int TunnelModelGL::dispatchesLastStep() const {
    return gpu_->dispatches;
}

void TunnelModelGL::finishPendingWork() const {
    context_->makeCurrent();
    glFinish();
}

std::array<double, 4> TunnelModelGL::expectedInflow(double h) const {
    // TunnelModel::admitInflow's number per step through each inflow side (left, right, bottom, top):
    // the half-range flux (Bird 1994 eq. 4.22) × the side's length × h / F_N.
    const TunnelParams& p = params_;
    const TunnelBoundary sides[4] = {p.left, p.right, p.bottom, p.top};
    const double inwardX[4] = {1, -1, 0, 0};
    const double sigma = std::sqrt(kBoltzmann * p.streamTemperature / p.mass());
    const double mostProbable = std::numbers::sqrt2 * sigma;
    std::array<double, 4> expected{};
    for (int side = 0; side < 4; ++side) {
        if (sides[side] != TunnelBoundary::Inflow || (side == 0 && p.pistonOn)) continue;
        const double s = p.streamSpeed * inwardX[side] / mostProbable;
        const double length = side < 2 ? p.boxHeight : p.boxWidth;
        expected[side] = tunnel::halfRangeFlux(p.streamDensity, sigma, s) * length * h / p.fn;
    }
    return expected;
}

std::array<unsigned, 4> TunnelModelGL::inflowCounts(double h) {
    // The fraction carried to the next step in the CPU model's inflowRemainder_ (a side that admits
    // nothing keeps its remainder, as there).
    const std::array<double, 4> expected = expectedInflow(h);
    std::array<unsigned, 4> counts{};
    for (std::size_t side = 0; side < 4; ++side) {
        const double wanted = expected[side] + inflowRemainder_[side];
        counts[side] = static_cast<unsigned>(wanted);
        inflowRemainder_[side] = wanted - static_cast<double>(counts[side]);
    }
    return counts;
}

void TunnelModelGL::upload() {
    TunnelGpu& g = *gpu_;
    g.pendingSampled.clear();
    g.pendingSampledSteps = 0;
    const std::size_t n = state_.size();
    g.cells = static_cast<std::size_t>(params_.cellsX * params_.cellsY);
    const std::array<double, 4> inflow = expectedInflow(params_.dt);
    const double inflowPerStep = inflow[0] + inflow[1] + inflow[2] + inflow[3];
    g.capacity =
        std::max({kMinCapacity, 2 * n, n + static_cast<std::size_t>(kInflowStepsOfCapacity * inflowPerStep),
                  g.roomWanted});
    std::vector<float> position(2 * n), velocity(2 * n), vz(n);
    for (std::size_t i = 0; i < n; ++i) {
        position[2 * i] = float(state_.x[i]), position[2 * i + 1] = float(state_.y[i]);
        velocity[2 * i] = float(state_.vx[i]), velocity[2 * i + 1] = float(state_.vy[i]);
        vz[i] = float(state_.vz[i]);
    }
    for (Buffer* b : {&g.sortedPosition, &g.sortedVelocity, &g.movedPosition, &g.movedVelocity, &g.movedCell})
        b->reserve(g.capacity * 8);
    for (Buffer* b : {&g.sortedVz, &g.movedVz}) b->reserve(g.capacity * 4);
    if (n > 0) {
        g.sortedPosition.upload(position.data(), position.size() * sizeof(float));
        g.sortedVelocity.upload(velocity.data(), velocity.size() * sizeof(float));
        g.sortedVz.upload(vz.data(), vz.size() * sizeof(float));
    }
    const auto groups = groupsOf(n, kTunnelParticleLocal);
    const std::uint32_t book[kBookWords] = {
        static_cast<std::uint32_t>(n), 0, groups[0], groups[1], groups[2], 0, 1, 1};
    g.book.reserve(sizeof book);
    g.book.upload(book, sizeof book);
    // A prefix sum over cells + 1 counts: the cell grid's scan on a row of unit cells.
    g.prefix.configure(0.0, 0.0, static_cast<double>(g.cells), 1.0, 1.0, g.cells, 1e-6);
    g.windowSums.reserve(g.cells * kSumsPerCell * sizeof(double));
    g.windowSums.fillZero(g.cells * kSumsPerCell * sizeof(double));
    g.ringStride = kRingHeader + 4 * obstacles_.size();
    g.ring.reserve(kRingSlots * g.ringStride * sizeof(std::uint32_t));
    g.ring.fillZero(kRingSlots * g.ringStride * sizeof(std::uint32_t));
    uploadCellArrays();
    g.countBound = g.knownCount = n;
    g.countKnown = true;
}

void TunnelModelGL::uploadCellArrays() {
    TunnelGpu& g = *gpu_;
    std::vector<double> remainders = remainder_, sigma = cellSigmaCrMax_, open = openFraction_;
    remainders.resize(g.cells, 0.0);
    sigma.resize(g.cells, initialSigmaCrMax());
    open.resize(g.cells, 1.0);
    g.remainders.uploadVector(toFloats(remainders));
    g.cellSigmaCrMax.uploadVector(toFloats(sigma));
    g.openFractions.uploadVector(toFloats(open));
}

void TunnelModelGL::download() const {
    TunnelGpu& g = *gpu_;
    flushSamples();
    std::uint32_t book[kBookWords];
    g.book.download(book, sizeof book);
    const std::size_t n = book[0];
    const auto position = g.sortedPosition.downloadVector<float>(2 * n);
    const auto velocity = g.sortedVelocity.downloadVector<float>(2 * n);
    const auto vz = g.sortedVz.downloadVector<float>(n);
    const auto starts = g.prefix.starts().downloadVector<std::uint32_t>(g.cells + 1);
    state_.clear();
    for (std::size_t i = 0; i < n; ++i)
        state_.append(position[2 * i], position[2 * i + 1], {velocity[2 * i], velocity[2 * i + 1], vz[i]});
    // The GPU's sorted buffers are in cell order: the cells' ranges are the scan's starts.
    for (std::size_t c = 0; c < g.cells; ++c)
        std::fill(state_.cell.begin() + starts[c], state_.cell.begin() + starts[c + 1],
                  static_cast<std::uint32_t>(c));
    adoptDeviceCells(starts, g.remainders.downloadVector<float>(g.cells),
                     g.cellSigmaCrMax.downloadVector<float>(g.cells));
    g.knownCount = n;
    g.countKnown = true;
}

void TunnelModelGL::flushSamples() const {
    TunnelGpu& g = *gpu_;
    if (g.pendingSampled.empty()) return;
    if (!gpuCurrent()) { // a reset or a restored state replaced what these steps sampled
        g.pendingSampled.clear();
        g.pendingSampledSteps = 0;
        return;
    }
    context_->makeCurrent();
    const std::size_t steps = g.pendingSampled.size(), bodies = obstacles_.size();
    const auto ring = g.ring.downloadVector<std::uint32_t>(steps * g.ringStride);
    TunnelSampler& sampler = samplerForHandOver();
    const double m = params_.mass();
    bool sumsAdded = false;
    for (std::size_t k = 0; k < steps; ++k) {
        const std::uint32_t* slot = ring.data() + k * g.ringStride;
        for (std::size_t b = 0; b < bodies; ++b) {
            const std::uint32_t* w = slot + kRingHeader + 4 * b;
            const double dvx = wideValue(w[0], w[1]), dvy = wideValue(w[2], w[3]);
            if (dvx != 0.0 || dvy != 0.0) sampler.addSurfaceImpulse(b, m * dvx, m * dvy);
        }
        // The window's sums open it at its first sampled step, as addState() would.
        if (g.pendingSampled[k] && !sumsAdded) {
            const auto sums = g.windowSums.downloadVector<double>(g.cells * kSumsPerCell);
            std::vector<TunnelSampler::CellSums> cells(g.cells);
            for (std::size_t c = 0; c < g.cells; ++c) {
                const double* s = sums.data() + c * kSumsPerCell;
                cells[c] = {s[0], s[1], s[2], s[3], s[4], s[5], s[6]};
            }
            sampler.addCellSums(cells, g.pendingSampledSteps);
            g.windowSums.fillZero(g.cells * kSumsPerCell * sizeof(double));
            sumsAdded = true;
        }
        sampler.endStep(bodies, params_.dt);
    }
    adoptDeviceCollisions(ring[(steps - 1) * g.ringStride]);
    g.ring.fillZero(steps * g.ringStride * sizeof(std::uint32_t));
    g.pendingSampled.clear();
    g.pendingSampledSteps = 0;
}

std::size_t TunnelModelGL::particleCount() const {
    TunnelGpu& g = *gpu_;
    if (!gpuCurrent()) return state_.size(); // the CPU's edit is the latest state
    if (!g.countKnown) {
        context_->makeCurrent();
        std::uint32_t count = 0;
        g.book.download(&count, sizeof count);
        g.knownCount = count;
        g.countKnown = true;
    }
    return g.knownCount;
}

void TunnelModelGL::ensureCapacity(std::size_t entering) {
    TunnelGpu& g = *gpu_;
    if (g.countBound + entering <= g.capacity) return;
    g.countKnown = false;
    g.countBound = particleCount(); // removals since the last look
    if (g.countBound + entering <= g.capacity) return;
    // More room: through the CPU copy, which the upload sizes anew (rare: the count doubled).
    g.roomWanted = g.countBound + entering;
    pullState();
    stateEdited();
    pushState();
}

} // namespace pl::gl
