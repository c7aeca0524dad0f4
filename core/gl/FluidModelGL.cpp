// FluidModelGL: Algorithm 1 as dispatches, and the CPU ↔ GPU hand-over of the particles.
#include "FluidModelGL.h"

#include "GlProgram.h"
#include "GpuCellGrid.h"
#include "GpuObstacles.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pl::gl {

namespace {

constexpr unsigned kStreamLocal = 256, kPairLocal = 128;
constexpr std::int64_t kHealthInterval = 64;
// Cells of half the search radius (1.05 h / 2) searched 2 cells out: a dense fluid puts about one particle
// in each, and the 5×5 stencil holds ~25 candidates for ~14 neighbours (3×3 cells of side 1.05 h: ~36;
// cells sized for two particles each, as for the sparse gas: ~110). The search runs once a step
// (fluid_neighbours.comp); the pair passes walk its list.
constexpr int kCellReach = 2;
constexpr double kParticlesPerCell = 0.1;
// Neighbours each particle's list holds (fluid_neighbours.comp): ~14 within 1.05 h in a fluid at rest.
// A particle with more walks its cells instead, and the list grows at the next health check to a
// quarter above the most seen, up to the largest, past which the few such particles keep walking cells.
constexpr unsigned kFirstNeighbourCapacity = 32, kLargestNeighbourCapacity = 96;

} // namespace

struct FluidGpu {
    ComputeProgram predict{"fluid/fluid_predict.comp"}, neighbours{"fluid/fluid_neighbours.comp"},
        lambda{"fluid/fluid_lambda.comp"}, correct{"fluid/fluid_correct.comp"},
        velocity{"fluid/fluid_velocity.comp"}, vorticity{"fluid/fluid_vorticity.comp"},
        xsph{"fluid/fluid_xsph.comp"}, surfaceForces{"fluid/fluid_surface_forces.comp"};
    GpuCellGrid grid;
    // Cell-ordered state: positions x, velocities v (ping-pong across the sort), predictions p and
    // their Jacobi partner, λ, ω and a velocity scratch buffer; the step's neighbours of each particle.
    Buffer x[2], v[2], p, pNext, lambdaBuffer, omega, vScratch, slots, status, errorSums, obstacles;
    Buffer neighbourCounts, neighbourList;
    // The bounded release (FluidSolver.cpp): b_i of the starting positions; the new compression's solve.
    Buffer oldCompression, newSolve[2];
    int current = 0;
    std::size_t count = 0;
    unsigned neighbourCapacity = kFirstNeighbourCapacity; // entries per particle in neighbourList
    std::size_t errorGroups = 0;                          // λ groups per iteration in errorSums
    bool errorsCurrent = true; // errorMean_ and errorMax_ hold the last GPU step's errors
    int dispatches = 0;
};

FluidModelGL::FluidModelGL(std::shared_ptr<GlContext> context) : GpuHandOver(std::move(context)) {
    createBuffers();
    reset();
}

FluidModelGL::FluidModelGL(std::shared_ptr<GlContext> context, const Preset& preset)
    : GpuHandOver(std::move(context)) {
    createBuffers();
    reset(preset);
}

void FluidModelGL::createBuffers() {
    gpu_ = std::make_unique<FluidGpu>();
    gpu_->status.reserve(16);
    gpu_->status.fillZero(16);
}

FluidModelGL::~FluidModelGL() {
    context_->makeCurrent(); // buffers and programs are deleted in their context
}

int FluidModelGL::dispatchesLastStep() const {
    return gpu_->dispatches;
}

unsigned FluidModelGL::neighbourListLength() const {
    return gpu_->neighbourCapacity;
}

void FluidModelGL::finishPendingWork() const {
    context_->makeCurrent();
    glFinish();
}

SceneView FluidModelGL::sceneViewSharingGpu() const {
    const FluidGpu& g = *gpu_;
    if (!drawsFromGpu()) return sceneView();
    context_->makeCurrent();
    waitUntilCommandsComplete(); // another context reads these buffers next
    SceneView view = sceneFrame();
    GpuParticles p;
    p.positions = g.x[g.current].id();
    p.velocities = g.v[g.current].id();
    p.radius = {float(params_.particleRadius), float(params_.particleRadius)};
    p.inverseColourMax = float(1.0 / params_.colourSpeedMax);
    p.count = g.count;
    view.gpu = p;
    return view;
}

void FluidModelGL::upload() {
    FluidGpu& g = *gpu_;
    const std::size_t n = state_.size();
    g.count = n;
    std::vector<float> x(2 * n), v(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        x[2 * i] = float(state_.x[i]), x[2 * i + 1] = float(state_.y[i]);
        v[2 * i] = float(state_.vx[i]), v[2 * i + 1] = float(state_.vy[i]);
    }
    g.current = 0;
    g.x[0].uploadVector(x);
    g.v[0].uploadVector(v);
    for (Buffer* b :
         {&g.x[1], &g.v[1], &g.p, &g.pNext, &g.vScratch, &g.slots, &g.newSolve[0], &g.newSolve[1]})
        b->reserve(n * 8);
    for (Buffer* b : {&g.lambdaBuffer, &g.omega, &g.neighbourCounts, &g.oldCompression}) b->reserve(n * 4);
    g.neighbourList.reserve(std::size_t(g.neighbourCapacity) * n * 4);
    // Cells of at least half the search radius: the 5 × 5 cells around a particle hold its neighbours.
    g.grid.configure(0.0, 0.0, params_.boxWidth, params_.boxHeight, params_.neighbourRadius() / kCellReach, n,
                     kParticlesPerCell);
}

void FluidModelGL::download() const {
    FluidGpu& g = *gpu_;
    const auto x = g.x[g.current].downloadVector<float>(2 * g.count);
    const auto v = g.v[g.current].downloadVector<float>(2 * g.count);
    state_.clear();
    for (std::size_t i = 0; i < g.count; ++i) state_.append(x[2 * i], x[2 * i + 1], v[2 * i], v[2 * i + 1]);
    if (!g.errorsCurrent) {
        const auto iterations = static_cast<std::size_t>(params_.iterations);
        const auto sums = g.errorSums.downloadVector<float>(2 * iterations * g.errorGroups);
        errorMean_.assign(iterations, 0.0);
        errorMax_.assign(iterations, 0.0);
        for (std::size_t k = 0; k < iterations; ++k) {
            double sum = 0.0, largest = 0.0;
            for (std::size_t gi = 0; gi < g.errorGroups; ++gi) {
                sum += sums[2 * (k * g.errorGroups + gi)];
                largest = std::max<double>(largest, sums[2 * (k * g.errorGroups + gi) + 1]);
            }
            errorMean_[k] = g.count > 0 ? sum / double(g.count) : 0.0;
            errorMax_[k] = largest;
        }
        g.errorsCurrent = true;
    }
}

void FluidModelGL::setCommonUniforms(ComputeProgram& p) const {
    const FluidGpu& g = *gpu_;
    const fluid::Box box = confinementBox();
    const fluid::WallJitter jitter = wallJitter();
    p.set("count", unsigned(g.count));
    p.set("kernelH", float(kernels_.h));
    p.set("kernelH2", float(kernels_.h2));
    p.set("poly6", float(kernels_.poly6));
    p.set("spikyGrad", float(kernels_.spikyGrad));
    p.set("selfWeight", float(kernels_.selfWeight()));
    p.set("scorrK", float(scorr_.k));
    p.set("scorrInverseReference", float(scorr_.inverseReference));
    p.set("scorrN", scorr_.n);
    p.set("confinement", float(box.left), float(box.bottom), float(box.right), float(box.top));
    p.set("margin", float(params_.particleRadius));
    p.set("obstacleCount", unsigned(obstacles_.size()));
    p.set("seedWords", unsigned(jitter.seed), unsigned(jitter.seed >> 32));
    p.set("stepWords", unsigned(jitter.step), unsigned(jitter.step >> 32));
    p.set("jitterAmount", float(jitter.amount));
    p.set("inverseRest", float(1.0 / restDensity_));
    g.grid.setUniforms(p);
    p.set("cellReach", kCellReach);
    p.set("neighbourCapacity", g.neighbourCapacity);
}

void FluidModelGL::advance(double /*h*/) { // h = dt, as FluidModel::advance
    FluidGpu& g = *gpu_;
    context_->makeCurrent();
    // Spawning is the only way past the cap: drain before the particles go up.
    if (!gpuCurrent()) drainOverCap();
    pushState();
    g.dispatches = 0;
    const std::size_t n = g.count;
    advanceBodies(); // on the CPU: a handful of bodies
    uploadObstacles(g.obstacles, obstacles_);
    const double gx = params_.accelerationX(), gy = params_.accelerationY();

    // Lines 1–7: predict, then sort by the cell of the prediction (neighbours come from the cells).
    ComputeProgram& predict = g.predict;
    predict.use();
    setCommonUniforms(predict);
    predict.set("dt", float(params_.dt));
    predict.set("gravity", float(gx), float(gy));
    auto bindPredict = [&] {
        g.x[g.current].bind(0);
        g.v[g.current].bind(1);
        g.x[1 - g.current].bind(4);
        g.v[1 - g.current].bind(5);
        g.p.bind(6);
        g.grid.counts().bind(7);
        g.slots.bind(9);
        g.grid.starts().bind(11);
    };
    bindPredict();
    predict.set("scatterPass", 0);
    predict.dispatch(n, kStreamLocal);
    storageBarrier();
    g.grid.scan();
    predict.use();
    bindPredict();
    predict.set("scatterPass", 1);
    predict.dispatch(n, kStreamLocal);
    storageBarrier();
    g.current = 1 - g.current;
    g.dispatches += 2 + g.grid.scanDispatches();

    // Lines 5–7: each particle's neighbours, read by every pair pass below (the bindings stay).
    g.grid.starts().bind(8);
    g.neighbourCounts.bind(12);
    g.neighbourList.bind(13);
    ComputeProgram& neighbours = g.neighbours;
    neighbours.use();
    setCommonUniforms(neighbours);
    const double searchRadius = params_.neighbourRadius();
    neighbours.set("searchRadius2", float(searchRadius * searchRadius));
    g.p.bind(0);
    g.status.bind(10);
    neighbours.dispatch(n, kPairLocal);
    storageBarrier();
    ++g.dispatches;

    // Lines 8–19: K Jacobi iterations of λ and Δx. The slot past the step's iterations in errorSums takes
    // the errors of the passes the profile does not show (the bounded release's).
    const auto iterations = static_cast<std::size_t>(params_.iterations);
    g.errorGroups = groupsFor(n, kPairLocal);
    g.errorSums.reserve(std::max<std::size_t>(1, (iterations + 1) * g.errorGroups) * 8);
    g.oldCompression.bind(3);
    auto lambdaPass = [&](const Buffer& positions, std::size_t errorSlot, int oldCompressionMode) {
        g.lambda.use();
        setCommonUniforms(g.lambda);
        g.lambda.set("epsilon", float(params_.epsilon));
        g.lambda.set("errorOffset", unsigned(errorSlot * g.errorGroups));
        g.lambda.set("oldCompressionMode", oldCompressionMode);
        g.lambda.set("compressionOnly", int(params_.compressionOnly));
        positions.bind(0);
        g.lambdaBuffer.bind(1);
        g.errorSums.bind(2);
        g.lambda.dispatch(n, kPairLocal);
        storageBarrier();
        ++g.dispatches;
    };
    auto correctPass = [&](const Buffer& positions, const Buffer& corrected) {
        g.correct.use();
        setCommonUniforms(g.correct);
        positions.bind(0);
        g.lambdaBuffer.bind(1);
        corrected.bind(2);
        g.correct.dispatch(n, kPairLocal);
        storageBarrier();
        ++g.dispatches;
    };
    // The bounded release (FluidModel::solveNewCompression): b_i at x, then K iterations on C_i − b_i from
    // x*.
    const bool limited = params_.releaseLimit > 0;
    const Buffer* newSolve = &g.p;
    if (limited) {
        lambdaPass(g.x[g.current], iterations, 2);
        for (std::size_t k = 0; k < iterations; ++k) {
            lambdaPass(*newSolve, iterations, 1);
            correctPass(*newSolve, g.newSolve[k % 2]);
            newSolve = &g.newSolve[k % 2];
        }
    }
    for (std::size_t k = 0; k < iterations; ++k) {
        lambdaPass(g.p, k, 0);
        correctPass(g.p, g.pNext);
        std::swap(g.p, g.pNext);
    }

    // Lines 20–22: velocities from the displacement, vorticity confinement, XSPH.
    g.velocity.use();
    setCommonUniforms(g.velocity);
    g.velocity.set("inverseDt", float(1.0 / params_.dt));
    g.velocity.set("limited", int(limited));
    g.velocity.set("releaseLimit",
                   float(params_.releaseLimit * std::hypot(gx, gy) * params_.dt * params_.dt));
    g.x[g.current].bind(0);
    g.p.bind(1);
    newSolve->bind(3);
    g.v[g.current].bind(2);
    g.status.bind(10);
    g.velocity.dispatch(n, kStreamLocal);
    storageBarrier();
    ++g.dispatches;
    if (params_.vorticity > 0) {
        g.vorticity.use();
        setCommonUniforms(g.vorticity);
        g.vorticity.set("strength", float(params_.vorticity * params_.dt));
        g.p.bind(0);
        g.v[g.current].bind(1);
        g.omega.bind(2);
        g.vScratch.bind(3);
        for (int pass = 0; pass < 2; ++pass) {
            g.vorticity.set("pass_", pass);
            g.vorticity.dispatch(n, kPairLocal);
            storageBarrier();
        }
        std::swap(g.v[g.current], g.vScratch);
        g.dispatches += 2;
    }
    if (params_.cohesion > 0 || params_.adhesion > 0) { // FluidModel::applySurfaceForces
        g.surfaceForces.use();
        setCommonUniforms(g.surfaceForces);
        g.surfaceForces.set("cohesion", float(params_.cohesion));
        g.surfaceForces.set("adhesion", float(params_.adhesion));
        g.surfaceForces.set("world", float(params_.boxWidth), float(params_.boxHeight));
        g.surfaceForces.set("dt", float(params_.dt));
        g.p.bind(0);
        g.v[g.current].bind(1);
        g.surfaceForces.dispatch(n, kPairLocal);
        storageBarrier();
        ++g.dispatches;
    }
    if (params_.xsph > 0) {
        g.xsph.use();
        setCommonUniforms(g.xsph);
        g.xsph.set("viscosity", float(params_.xsph));
        g.p.bind(0);
        g.v[g.current].bind(1);
        g.vScratch.bind(3);
        g.xsph.dispatch(n, kPairLocal);
        storageBarrier();
        std::swap(g.v[g.current], g.vScratch);
        ++g.dispatches;
    }
    // Line 23: x ← x*, by exchanging the buffers.
    std::swap(g.x[g.current], g.p);
}

void FluidModelGL::afterStep() {
    steppedOnGpu();
    gpu_->errorsCurrent = false;
    if (stepCount() % kHealthInterval == 0) checkGpuHealth();
}

void FluidModelGL::checkGpuHealth() {
    FluidGpu& g = *gpu_;
    std::uint32_t status[4];
    g.status.download(status, sizeof status);
    if (status[1] > g.neighbourCapacity && g.neighbourCapacity < kLargestNeighbourCapacity) {
        // Some particles had more neighbours than the list holds (they walked their cells): lengthen it.
        const unsigned wanted = (status[1] + status[1] / 4 + 7) / 8 * 8;
        g.neighbourCapacity = std::min(kLargestNeighbourCapacity, wanted);
        g.neighbourList.reserve(std::size_t(g.neighbourCapacity) * g.count * 4);
        const std::uint32_t cleared = 0;
        g.status.upload(&cleared, sizeof cleared, sizeof(std::uint32_t));
    }
    if (status[0] == 0) return;
    pullState();
    std::ostringstream hint;
    hint << "the solver diverged at dt = " << params_.dt << " with " << params_.iterations
         << " iterations and ε = " << params_.epsilon << ": use a smaller dt, more iterations or a larger ε";
    fail("a particle has a non-finite velocity", hint.str());
}

} // namespace pl::gl
