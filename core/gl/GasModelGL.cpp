// GasModelGL: the integrator table's passes as GPU dispatches, and the CPU ↔ GPU state hand-over.
#include "GasModelGL.h"

#include "GlProgram.h"
#include "GpuCellGrid.h"
#include "GpuObstacles.h"
#include "common/Statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace pl::gl {

namespace {

constexpr unsigned kDriftLocal = 256, kForceLocal = 128, kReduceLocal = 256;
// gas_drift_small.comp sorts in one work group of 1024 with 2048 cell counts in shared memory; beyond
// 16 disks per invocation the three-dispatch path is faster anyway.
constexpr std::size_t kSmallSortCells = 2048, kSmallSortThreads = 1024, kSmallSortMaxDisks = 16384;
constexpr std::size_t kSumsPerGroup = 9; // gas_observe.comp's kSums
constexpr unsigned kFineBins = 4096;     // KS distance from a histogram this fine (see observe())
constexpr double kFineSigmas = 10.0;     // fine bins span 0 … 10 √(kT/m)
constexpr double kParticlesPerCell = 2.0;
constexpr std::int64_t kHealthInterval = 64; // as the CPU model's energy check
// gas_forces.comp: invocations per disk, doubled up to 8 until the pass has this many, so that a small
// gas spreads over the GPU's multiprocessors (H200: 132) instead of a few work groups. On the H200
// (bench/results/h200-gas-lanes-*.jsonl) 8 lanes took the 4096-disk step from 23.3 to 17.8 µs, 16 384
// disks were fastest with 8, 65 536 with 2, and 262 144 with 1 or 2; more than 8 gained nothing.
constexpr std::size_t kForceInvocationsWanted = 131072;
constexpr unsigned kMaxAutomaticForceLanes = 8, kMaxForceLanes = 32; // the shader's work group is 128

} // namespace

struct GasGpu {
    ComputeProgram drift{"gas/gas_drift.comp"}, driftSmall{"gas/gas_drift_small.comp"},
        forces{"gas/gas_forces.comp"}, observe{"gas/gas_observe.comp"}, histogram{"gas/gas_histogram.comp"};
    GpuCellGrid grid;
    Buffer pos[2], vel[2], tag[2], acc, slots, status, impulseSums, energy, sums, bins, obstacles;
    int current = 0;          // which of the ping-pong pairs holds the cell-ordered state
    double pendingKick = 0.0; // true velocity = vel + pendingKick · acc (the force pass does not kick)
    std::size_t count = 0;
    int dispatches = 0;
    bool profiling = false;
    std::vector<std::pair<std::string, GLuint>> marks;     // this step's timestamps
    std::vector<std::pair<std::string, double>> passTimes; // accumulated per pass [ns]

    // Timestamp after the work issued so far, labelled with the pass it ends.
    void mark(const char* pass) {
        if (!profiling) return;
        GLuint query = 0;
        glGenQueries(1, &query);
        glQueryCounter(query, GL_TIMESTAMP);
        marks.emplace_back(pass, query);
    }
    void collectMarks() {
        for (std::size_t k = 1; k < marks.size(); ++k) {
            GLuint64 before = 0, after = 0;
            glGetQueryObjectui64v(marks[k - 1].second, GL_QUERY_RESULT, &before);
            glGetQueryObjectui64v(marks[k].second, GL_QUERY_RESULT, &after);
            auto it = std::find_if(passTimes.begin(), passTimes.end(),
                                   [&](auto& p) { return p.first == marks[k].first; });
            if (it == passTimes.end()) it = passTimes.insert(passTimes.end(), {marks[k].first, 0.0});
            it->second += static_cast<double>(after - before);
        }
        for (auto& m : marks) glDeleteQueries(1, &m.second);
        marks.clear();
    }

    void bindState() {
        pos[current].bind(0);
        vel[current].bind(1);
        acc.bind(2);
        tag[current].bind(3);
    }
};

GasModelGL::GasModelGL(std::shared_ptr<GlContext> context) : GpuHandOver(std::move(context)) {
    createBuffers();
    reset();
}

GasModelGL::GasModelGL(std::shared_ptr<GlContext> context, const Preset& preset)
    : GpuHandOver(std::move(context)) {
    createBuffers();
    reset(preset);
}

void GasModelGL::createBuffers() {
    gpu_ = std::make_unique<GasGpu>();
    gpu_->status.reserve(4 * sizeof(std::uint32_t));
    gpu_->status.fillZero(16);
}

GasModelGL::~GasModelGL() {
    context_->makeCurrent(); // buffers and programs are deleted in their context
}

bool GasModelGL::stepsOnGpu() const {
    return gasIntegrator(activeIntegrator()).onlyKicksAndDrifts() &&
           params_.forceMethod != GasForceMethod::AllPairs;
}

int GasModelGL::dispatchesLastStep() const {
    return gpu_->dispatches;
}

void GasModelGL::setProfiling(bool on) {
    gpu_->profiling = on;
    gpu_->passTimes.clear();
}

std::vector<std::pair<std::string, double>> GasModelGL::profile() const {
    return gpu_->passTimes;
}

SceneView GasModelGL::sceneViewSharingGpu() const {
    const GasGpu& g = *gpu_;
    if (!drawsFromGpu()) return sceneView();
    context_->makeCurrent();
    waitUntilCommandsComplete(); // another context reads these buffers next
    SceneView view = sceneFrame();
    GpuParticles p;
    p.positions = g.pos[g.current].id();
    p.velocities = g.vel[g.current].id();
    p.accelerations = g.acc.id();
    p.tags = g.tag[g.current].id();
    p.pendingKick = float(g.pendingKick);
    p.radius = {float(0.5 * params_.a.diameter), float(0.5 * params_.b.diameter)};
    p.inverseColourMax = float(1.0 / view.colourMax);
    p.count = g.count;
    view.gpu = p;
    return view;
}

const GpuCellGrid& GasModelGL::cellGrid() const {
    return gpu_->grid;
}

void GasModelGL::finishPendingWork() const {
    context_->makeCurrent();
    glFinish();
}

void GasModelGL::upload() {
    GasGpu& g = *gpu_;
    const std::size_t n = state_.size();
    g.count = n;
    std::vector<float> pos(2 * n), vel(2 * n);
    std::vector<std::uint32_t> tags(n);
    for (std::size_t i = 0; i < n; ++i) {
        pos[2 * i] = static_cast<float>(state_.x[i]), pos[2 * i + 1] = static_cast<float>(state_.y[i]);
        vel[2 * i] = static_cast<float>(state_.vx[i]), vel[2 * i + 1] = static_cast<float>(state_.vy[i]);
        tags[i] = state_.id[i] << 1 | state_.species[i];
    }
    g.current = 0;
    g.pos[0].uploadVector(pos);
    g.vel[0].uploadVector(vel);
    g.tag[0].uploadVector(tags);
    for (Buffer* b : {&g.pos[1], &g.vel[1], &g.acc, &g.slots, &g.energy}) b->reserve(n * 8);
    g.tag[1].reserve(n * 4);
    g.acc.fillZero(g.acc.capacity());
    const std::size_t groups = std::max<std::size_t>(1, groupsFor(n, kDriftLocal));
    g.impulseSums.reserve(groups * sizeof(float));
    g.impulseSums.fillZero(g.impulseSums.capacity());
    g.sums.reserve(groupsFor(n, kReduceLocal) * kSumsPerGroup * sizeof(float) + 16);
    g.grid.configure(params_.left(), params_.bottom(), 0.5 * params_.boxWidth - params_.left(),
                     params_.boxHeight, params_.maxDiameter(), n, kParticlesPerCell);
    // Contacts and impulses of the CPU window carry over.
    double impulse = 0.0;
    std::uint32_t began = 0;
    for (std::size_t i = 0; i < n; ++i) impulse += state_.wallImpulse[i], began += state_.contactsBegun[i];
    const std::uint32_t status[4] = {0, began, 0, 0};
    g.status.upload(status, sizeof status);
    const float firstImpulse = static_cast<float>(impulse);
    if (n > 0) g.impulseSums.upload(&firstImpulse, sizeof firstImpulse);
    g.pendingKick = 0.0;
    drift(0.0, 0.0, 0.0); // a drift of length zero only sorts into cell order
    forces(false, 0.0);
}

void GasModelGL::download() const {
    GasGpu& g = *gpu_;
    const std::size_t n = g.count;
    const auto pos = g.pos[g.current].downloadVector<float>(2 * n);
    const auto vel = g.vel[g.current].downloadVector<float>(2 * n);
    const auto acc = g.acc.downloadVector<float>(2 * n);
    const auto tags = g.tag[g.current].downloadVector<std::uint32_t>(n);
    const auto impulses = g.impulseSums.downloadVector<float>(groupsFor(n, kDriftLocal));
    std::uint32_t status[4];
    g.status.download(status, sizeof status);
    GasState& s = state_;
    s.resize(n);
    const double k = g.pendingKick;
    for (std::size_t i = 0; i < n; ++i) {
        s.x[i] = pos[2 * i], s.y[i] = pos[2 * i + 1];
        s.ax[i] = acc[2 * i], s.ay[i] = acc[2 * i + 1];
        s.vx[i] = vel[2 * i] + k * acc[2 * i], s.vy[i] = vel[2 * i + 1] + k * acc[2 * i + 1];
        s.species[i] = static_cast<std::uint8_t>(tags[i] & 1u);
        s.id[i] = tags[i] >> 1;
        s.wallImpulse[i] = 0.0;
        s.contactsBegun[i] = 0;
    }
    // The windows' totals ride on the first disk until observe() empties them.
    if (n > 0) {
        double impulse = 0.0;
        for (float v : impulses) impulse += v;
        s.wallImpulse[0] = impulse;
        s.contactsBegun[0] = status[1];
    }
    stateChangedOnDevice();
}

void GasModelGL::drift(double kickBefore, double h, double kickAfter) {
    GasGpu& g = *gpu_;
    const bool small = g.grid.cells() + 1 <= kSmallSortCells && g.count <= kSmallSortMaxDisks;
    ComputeProgram& p = small ? g.driftSmall : g.drift;
    const gas::Boundaries b = boundaries(h);
    p.use();
    p.set("box", float(b.left), float(b.right), float(b.bottom), float(b.top));
    p.set("pistonVelocity", float(b.pistonVelocity));
    p.set("driftH", float(h));
    p.set("thermalWalls", b.thermal ? 1 : 0);
    p.set("thermalRight", b.thermalRight ? 1 : 0);
    p.set("wallKT", float(b.wallKT));
    p.set("speciesMass", float(b.mass[0]), float(b.mass[1]));
    p.set("speciesRadius", float(b.radius[0]), float(b.radius[1]));
    p.set("seedWords", unsigned(b.seed), unsigned(b.seed >> 32));
    p.set("drawWords", unsigned(b.drawIndex), unsigned(b.drawIndex >> 32));
    p.set("obstacleCount", unsigned(obstacles_.size()));
    p.set("count", unsigned(g.count));
    p.set("kickBefore", float(g.pendingKick + kickBefore));
    p.set("kickAfter", float(kickAfter));
    g.grid.setUniforms(p);
    auto bindAll = [&] {
        g.bindState();
        g.pos[1 - g.current].bind(4);
        g.vel[1 - g.current].bind(5);
        g.tag[1 - g.current].bind(6);
        g.grid.counts().bind(7);
        g.grid.starts().bind(8);
        g.slots.bind(9);
        g.status.bind(10);
        g.impulseSums.bind(11);
    };
    bindAll();
    if (small) { // count, scan and scatter in one dispatch
        p.dispatch(kSmallSortThreads, kSmallSortThreads);
        storageBarrier();
        g.mark("drift + sort (one group)");
        g.current = 1 - g.current;
        g.pendingKick = 0.0;
        ++g.dispatches;
        driftDone();
        return;
    }
    p.set("scatterPass", 0);
    p.dispatch(g.count, kDriftLocal);
    storageBarrier();
    g.mark("drift: count");
    g.grid.scan(); // binds its own buffers
    g.mark("cell scan");
    p.use();
    bindAll();
    p.set("scatterPass", 1);
    p.dispatch(g.count, kDriftLocal);
    storageBarrier();
    g.mark("drift: scatter");
    g.current = 1 - g.current;
    g.pendingKick = 0.0;
    g.dispatches += 2 + g.grid.scanDispatches();
    driftDone();
}

void GasModelGL::setForceLanesPerDisk(unsigned lanes) {
    if (lanes > kMaxForceLanes || (lanes & (lanes - 1)) != 0)
        throw std::invalid_argument("invocations per disk must be 0 (automatic) or a power of two up to " +
                                    std::to_string(kMaxForceLanes) + ", not " + std::to_string(lanes));
    forceLanes_ = lanes;
}

unsigned GasModelGL::forceLanesPerDisk() const {
    if (forceLanes_ != 0) return forceLanes_;
    if (contextInfo().software) return 1; // more invocations only add work for a few CPU cores
    unsigned lanes = 1;
    while (lanes < kMaxAutomaticForceLanes && gpu_->count * lanes < kForceInvocationsWanted) lanes *= 2;
    return lanes;
}

void GasModelGL::forces(bool countContacts, double kick, bool energies) {
    GasGpu& g = *gpu_;
    ComputeProgram& p = g.forces;
    p.use();
    const unsigned lanes = forceLanesPerDisk();
    p.set("count", unsigned(g.count));
    p.set("lanesPerDisk", lanes);
    p.set("stiffness", float(params_.stiffness));
    p.set("gravity", float(params_.appliedGravity()));
    p.set("speciesDiameter", float(params_.a.diameter), float(params_.b.diameter));
    p.set("speciesInverseMass", float(1.0 / params_.a.mass), float(1.0 / params_.b.mass));
    p.set("maxContact", float(params_.maxDiameter()));
    p.set("countContacts", countContacts ? 1 : 0);
    p.set("energies", energies ? 1 : 0);
    p.set("backtrackH", float(signedStep()));
    g.grid.setUniforms(p);
    g.bindState();
    g.grid.starts().bind(8);
    g.status.bind(10);
    g.energy.bind(12);
    p.dispatch(g.count * lanes, kForceLocal);
    storageBarrier();
    g.mark("forces");
    g.pendingKick = kick;
    ++g.dispatches;
}

void GasModelGL::advance(double h) {
    if (!stepsOnGpu()) { // the CPU model takes the step on its own state
        pullState();
        GasModel::advance(h);
        return;
    }
    context_->makeCurrent();
    advanceBodies(h);                             // on the CPU: a handful of bodies
    uploadObstacles(gpu_->obstacles, obstacles_); // they move between steps, never within one
    pushState();
    gpu_->dispatches = 0;
    gpu_->mark("start");
    beginDrifts();
    // The integrator table's passes, as the CPU model runs them (GasModel::runPasses). The force pass
    // leaves its kick pending; the next drift or a reader of the velocities applies it.
    for (const GasPass& pass : gasIntegrator(activeIntegrator()).passes) {
        if (pass.kind == GasPass::Kind::Drift)
            drift(stepFraction(pass.kickBefore, h), stepFraction(pass.drift, h),
                  stepFraction(pass.kickAfter, h));
        else if (pass.kind == GasPass::Kind::Forces)
            forces(pass.countContacts, stepFraction(pass.kickAfter, h));
        // no RungeKutta4 pass here: stepsOnGpu() is false for it
    }
    if (gpu_->profiling) gpu_->collectMarks();
}

void GasModelGL::afterStep() {
    if (!stepsOnGpu()) {
        GasModel::afterStep();
        stateEdited(); // the step changed the CPU copy
        return;
    }
    steppedOnGpu();
    if (stepCount() % kHealthInterval == 0) checkGpuHealth();
}

namespace {

// Group sums of gas_observe.comp, added up in double (float group sums: no drift with N).
GasSums reduce(GasGpu& g, const GasParams& params) {
    ComputeProgram& p = g.observe;
    p.use();
    p.set("count", unsigned(g.count));
    p.set("pendingKick", float(g.pendingKick));
    p.set("gravity", float(params.appliedGravity()));
    p.set("bottom", float(params.bottom()));
    p.set("speciesMass", float(params.a.mass), float(params.b.mass));
    g.bindState();
    g.energy.bind(12);
    g.sums.bind(13);
    p.dispatch(g.count, kReduceLocal);
    storageBarrier();
    const std::size_t groups = groupsFor(g.count, kReduceLocal);
    const auto partial = g.sums.downloadVector<float>(groups * kSumsPerGroup);
    double total[kSumsPerGroup] = {};
    for (std::size_t k = 0; k < groups; ++k)
        for (std::size_t q = 0; q < kSumsPerGroup; ++q) total[q] += partial[k * kSumsPerGroup + q];
    GasSums sums;
    sums.count = {std::llround(total[0]), std::llround(total[1])};
    sums.kinetic = {total[2], total[3]};
    sums.px = total[4], sums.py = total[5];
    sums.potential = total[6];
    sums.virial = total[7];
    return sums;
}

struct SpeedBins {
    std::vector<std::uint32_t> raw; // [species][plot + 1 overflow], then [species][fine]
    std::size_t plotBins;
    double plotMax[2], fineMax[2];
    std::uint32_t plot(int s, std::size_t b) const { return raw[s * (plotBins + 1) + b]; }
    std::uint32_t fine(int s, std::size_t b) const { return raw[2 * (plotBins + 1) + s * kFineBins + b]; }
};

SpeedBins speedBins(GasGpu& g, std::size_t plotBins, const double plotMax[2], const double fineMax[2]) {
    SpeedBins bins{{}, plotBins, {plotMax[0], plotMax[1]}, {fineMax[0], fineMax[1]}};
    const std::size_t entries = 2 * (plotBins + 1) + 2 * kFineBins;
    g.bins.reserve(entries * sizeof(std::uint32_t));
    g.bins.fillZero(entries * sizeof(std::uint32_t));
    ComputeProgram& p = g.histogram;
    p.use();
    p.set("count", unsigned(g.count));
    p.set("pendingKick", float(g.pendingKick));
    p.set("plotBins", unsigned(plotBins));
    p.set("fineBins", kFineBins);
    p.set("plotMax", float(plotMax[0]), float(plotMax[1]));
    p.set("fineMax", float(fineMax[0]), float(fineMax[1]));
    g.bindState();
    g.bins.bind(14);
    p.dispatch(g.count, kReduceLocal);
    storageBarrier();
    bins.raw = g.bins.downloadVector<std::uint32_t>(entries);
    return bins;
}

// KS distance to the 2D Maxwell–Boltzmann speed distribution, from the fine bins: the largest gap
// between the two CDFs at the bin edges. It can fall short of the exact statistic by at most the mass
// of one fine bin (about 0.0015 at 4096 bins over 10 σ).
double binnedKsDistance(const SpeedBins& bins, int s, double kT, double mass, long long count) {
    if (count < 2 || !(kT > 0)) return std::numeric_limits<double>::quiet_NaN();
    double cumulative = 0.0, worst = 0.0;
    const double width = bins.fineMax[s] / kFineBins;
    for (std::size_t b = 0; b < kFineBins; ++b) {
        worst = std::max(worst, std::abs(cumulative / double(count) - rayleighCdf(b * width, kT, mass)));
        cumulative += bins.fine(s, b);
    }
    return std::max(worst, std::abs(1.0 - rayleighCdf(bins.fineMax[s], kT, mass)));
}

} // namespace

GasSums GasModelGL::gpuSums() {
    context_->makeCurrent();
    forces(false, gpu_->pendingKick, true); // the same accelerations again, now with energies
    return reduce(*gpu_, params_);
}

GasObservables GasModelGL::observe() {
    if (!gpuCurrent() || !stepsOnGpu()) return GasModel::observe();
    GasGpu& g = *gpu_;
    GasSums sums = gpuSums();
    std::uint32_t status[4];
    g.status.download(status, sizeof status);
    const auto impulses = g.impulseSums.downloadVector<float>(groupsFor(g.count, kDriftLocal));
    for (float v : impulses) sums.impulse += v;
    sums.contactsBegun = status[1];
    // The windows close: empty them here and in any copy the CPU state holds.
    status[1] = 0;
    g.status.upload(status, sizeof status);
    g.impulseSums.fillZero(g.impulseSums.capacity());
    std::fill(state_.wallImpulse.begin(), state_.wallImpulse.end(), 0.0);
    std::fill(state_.contactsBegun.begin(), state_.contactsBegun.end(), 0u);
    GasObservables o = summarise(sums);
    const double mass[2] = {params_.a.mass, params_.b.mass};
    double plotMax[2], fineMax[2];
    for (int s = 0; s < 2; ++s) {
        plotMax[s] = histogramRange(o.kTSpecies[s], mass[s]);
        fineMax[s] = o.kTSpecies[s] > 0 ? kFineSigmas * std::sqrt(o.kTSpecies[s] / mass[s]) : 1.0;
    }
    const SpeedBins bins = speedBins(g, 1, plotMax, fineMax);
    for (int s = 0; s < 2; ++s)
        o.ksDistance[s] = binnedKsDistance(bins, s, o.kTSpecies[s], mass[s], sums.count[s]);
    return o;
}

std::vector<NamedHistogram> GasModelGL::histograms() const {
    if (!gpuCurrent() || !stepsOnGpu()) return GasModel::histograms();
    GasGpu& g = *gpu_;
    context_->makeCurrent();
    const GasSums sums = reduce(g, params_);
    const double mass[2] = {params_.a.mass, params_.b.mass};
    double kT[2], plotMax[2], fineMax[2];
    for (int s = 0; s < 2; ++s) {
        kT[s] = sums.count[s] > 0 ? sums.kinetic[s] / double(sums.count[s]) : 0.0;
        plotMax[s] = histogramRange(kT[s], mass[s]);
        fineMax[s] = kT[s] > 0 ? kFineSigmas * std::sqrt(kT[s] / mass[s]) : 1.0;
    }
    const auto plotBins = static_cast<std::size_t>(params_.histogramBins);
    const SpeedBins bins = speedBins(g, plotBins, plotMax, fineMax);
    std::vector<NamedHistogram> list;
    for (int s = 0; s < 2; ++s) {
        if (sums.count[s] == 0) continue;
        Histogram counts(0.0, plotMax[s], plotBins);
        for (std::size_t b = 0; b < plotBins; ++b) counts.add(counts.binCentre(b), bins.plot(s, b));
        counts.add(2.0 * plotMax[s], bins.plot(s, plotBins)); // the overflow bin
        const double ks = binnedKsDistance(bins, s, kT[s], mass[s], sums.count[s]);
        list.push_back(describeSpeedHistogram(s, kT[s], ks, std::move(counts)));
    }
    return list;
}

double GasModelGL::totalEnergy() {
    if (!gpuCurrent() || !stepsOnGpu()) return GasModel::totalEnergy();
    const GasSums s = gpuSums();
    return s.kinetic[0] + s.kinetic[1] + s.potential;
}

void GasModelGL::checkGpuHealth() {
    std::uint32_t status[4];
    gpu_->status.download(status, sizeof status);
    if (status[0] != 0) reportEscape();
    checkHealth(true);         // reads totalEnergy(): GPU sums
    if (failed()) pullState(); // what the user inspects after a blow-up is the state it happened in
}

} // namespace pl::gl
