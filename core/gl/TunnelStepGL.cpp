// TunnelModelGL's step in the CPU model's order (TunnelModel::step: bodies and piston on the CPU, then
// move, inflow, sort, collide and sample as dispatches), and the readers that take the GPU's samples
// over first.
#include "TunnelModelGL.h"

#include "GpuObstacles.h"
#include "TunnelGpu.h"
#include "tunnel/TunnelSeries.h"

#include <cmath>
#include <limits>

namespace pl::gl {

namespace {

// Cut cells collide as if at least this open (TunnelCollide.cpp's kMinOpenFraction).
constexpr float kMinOpenFraction = 0.05f;

void dispatchIndirect(const Buffer& book, GLintptr offset) {
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, book.id());
    glDispatchComputeIndirect(offset);
}

// The next pass reads what this one wrote, some of it as its dispatch size.
void storageAndCommandBarrier() {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

} // namespace

void TunnelModelGL::bindAll() const {
    TunnelGpu& g = *gpu_;
    g.sortedPosition.bind(0);
    g.sortedVelocity.bind(1);
    g.sortedVz.bind(2);
    g.movedPosition.bind(3);
    g.movedVelocity.bind(4);
    g.movedVz.bind(5);
    g.movedCell.bind(6);
    g.prefix.counts().bind(7);
    g.prefix.starts().bind(8);
    g.book.bind(9);
    g.ring.bind(10);
    g.remainders.bind(11);
    g.windowSums.bind(12);
    g.openFractions.bind(13);
    g.cellSigmaCrMax.bind(14);
}

void TunnelModelGL::setCommonUniforms(ComputeProgram& p, double h) const {
    const TunnelGpu& g = *gpu_;
    const TunnelParams& q = params_;
    const double m = q.mass();
    p.set("seedWords", unsigned(seed_), unsigned(seed_ >> 32));
    p.set("stepIndex", unsigned(stepCount()));
    p.set("dt", float(h));
    p.set("domain", 0.0f, 0.0f, float(q.boxWidth), float(q.boxHeight));
    p.set("cellDims", int(q.cellsX), int(q.cellsY));
    p.set("cellInverse", float(1.0 / q.cellWidth()), float(1.0 / q.cellHeight()));
    p.set("ringBase", unsigned(g.pendingSampled.size() * g.ringStride));
    p.set("obstacleCount", unsigned(obstacles_.size()));
    p.set("sides[0]", int(q.left));
    p.set("sides[1]", int(q.right));
    p.set("sides[2]", int(q.bottom));
    p.set("sides[3]", int(q.top));
    p.set("wallSigma", float(std::sqrt(kBoltzmann * q.wallTemperature / m)));
    p.set("wallSpeeds", float(q.bottomWallSpeed), float(q.topWallSpeed));
    p.set("bodySigma", float(std::sqrt(kBoltzmann * q.bodyTemperature / m)));
    p.set("bodiesDiffuse", q.surface == TunnelSurface::Diffuse ? 1 : 0);
    p.set("pistonOn", q.pistonOn ? 1 : 0);
    p.set("pistonStart", float(pistonX_ - pistonVelocity_ * h)); // the piston at τ = 0, as fly() has it
    p.set("pistonVelocity", float(pistonVelocity_));
    p.set("surfacePurpose", unsigned(RngPurpose::TunnelSurface));
}

void TunnelModelGL::advance(double h) {
    TunnelGpu& g = *gpu_;
    context_->makeCurrent();
    pushState();
    // Bodies and piston on the CPU (a handful), as TunnelModel::step. Moving bodies or a piston the
    // user drives restart the window: the steps before it are handed over first.
    const bool bodiesWereMoving = obstacleDrive_.moving();
    if (bodiesWereMoving || (params_.pistonOn && pistonDrive_.moving() && !pistonExperiment_)) flushSamples();
    advanceBodies(h);
    if (bodiesWereMoving) g.openFractions.uploadVector(toFloats(openFraction_));
    std::vector<Obstacle> frames = obstacles_; // centres at the step's start: flights meet them moving
    for (Obstacle& o : frames) o.x -= o.vx * h, o.y -= o.vy * h;
    uploadObstacles(g.obstacles, frames);
    const std::array<unsigned, 4> entering = inflowCounts(h);
    const unsigned enteringTotal = entering[0] + entering[1] + entering[2] + entering[3];
    ensureCapacity(enteringTotal);
    const bool sampled = stepCount() >= sampleFrom_;
    bindAll();

    // Move: flight, sides, bodies, piston; removal and the count into cells.
    g.move.use();
    setCommonUniforms(g.move, h);
    dispatchIndirect(g.book, kMoveGroupsOffset);
    storageBarrier();
    // Inflow: appended after the moved particles, counted into cells the same way.
    g.inflow.use();
    setCommonUniforms(g.inflow, h);
    g.inflow.set("inflowEnd[0]", entering[0]);
    g.inflow.set("inflowEnd[1]", entering[0] + entering[1]);
    g.inflow.set("inflowEnd[2]", entering[0] + entering[1] + entering[2]);
    g.inflow.set("inflowEnd[3]", enteringTotal);
    const double m = params_.mass();
    g.inflow.set("streamSigma", float(std::sqrt(kBoltzmann * params_.streamTemperature / m)));
    g.inflow.set("streamVelocity", float(params_.streamSpeed), 0.0f);
    g.inflow.set("inflowPurpose", unsigned(RngPurpose::TunnelInflow));
    g.inflow.dispatch(std::max(enteringTotal, 1u), kTunnelParticleLocal); // invocation 0 sizes the scatter
    storageAndCommandBarrier();
    // Sort: the cell counts' prefix sum (removed particles have none), then the scatter into cell order.
    g.prefix.scan();
    bindAll();
    g.scatter.use();
    g.scatter.set("cellCount", unsigned(g.cells));
    dispatchIndirect(g.book, kScatterGroupsOffset);
    storageAndCommandBarrier();
    // Collide and sample, one invocation per cell.
    g.collide.use();
    setCommonUniforms(g.collide, h);
    g.collide.set("cellCount", unsigned(g.cells));
    g.collide.set("candidateFactor", float(params_.fn * h / (params_.cellWidth() * params_.cellHeight())));
    g.collide.set("sigmaPrefactor", float(collisions_.prefactor));
    g.collide.set("sigmaExponent", float(2.0 - 2.0 * collisions_.omega));
    g.collide.set("collisionPurpose", unsigned(RngPurpose::TunnelCollision));
    g.collide.set("sampleStep", sampled ? 1 : 0);
    g.collide.set("minOpenFraction", kMinOpenFraction);
    g.collide.dispatch(g.cells, kTunnelCellLocal);
    storageBarrier();
    g.dispatches = 4 + g.prefix.scanDispatches();

    g.pendingSampled.push_back(sampled);
    g.pendingSampledSteps += sampled ? 1 : 0;
    g.countBound += enteringTotal;
    g.countKnown = false;
}

void TunnelModelGL::afterStep() {
    TunnelGpu& g = *gpu_;
    steppedOnGpu();
    if (g.pendingSampled.size() == kRingSlots) flushSamples();
    // TunnelModel::step's limit, checked when the bound on the count passes it.
    if (static_cast<double>(g.countBound) > TunnelParams::maxParticles()) {
        g.countKnown = false;
        g.countBound = particleCount();
        if (static_cast<double>(g.countBound) > TunnelParams::maxParticles()) {
            pullState();
            failTooManyMolecules(g.countBound);
        }
    }
}

SceneView TunnelModelGL::sceneViewSharingGpu() const {
    if (!drawsFromGpu()) return sceneView();
    SceneView view = sceneFrame();
    if (!view.drawParticles) return view;
    TunnelGpu& g = *gpu_;
    const std::size_t n = particleCount();
    context_->makeCurrent();
    waitUntilCommandsComplete(); // another context reads these buffers next
    GpuParticles p;
    p.positions = g.sortedPosition.id();
    p.velocities = g.sortedVelocity.id(); // (v_x, v_y): the colour is the in-plane speed
    p.radius = {0.0f, 0.0f};
    p.inverseColourMax = float(1.0 / view.colourMax);
    p.count = n;
    view.gpu = p;
    return view;
}

} // namespace pl::gl
