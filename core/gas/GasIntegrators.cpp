// The integrator table's stages executed on the CPU: drift passes (kick, drift, boundaries fused in one
// pass), force passes (forces, then a kick, in one pass) and RK4's own stepper. Each step ends with
// forces at the new positions, so the next step starts from cached forces.
#include "GasDrift.h"
#include "GasModel.h"
#include "common/Parallel.h"
#include "common/StopRequest.h"

#include <cmath>

namespace pl {

void GasModel::driftStage(double kickBefore, double h, double kickAfter) {
    GasState& s = state_;
    const gas::Boundaries walls = boundaries(h);
    const auto n = static_cast<long long>(s.size());
    const bool track = neighbours_.valid() && params_.forceMethod != GasForceMethod::AllPairs;
    const gas::DriftArrays arrays{s.x.data(),  s.y.data(),           s.vx.data(),          s.vy.data(),
                                  s.ax.data(), s.ay.data(),          s.wallImpulse.data(), s.species.data(),
                                  s.id.data(), neighbours_.builtX(), neighbours_.builtY()};
    const gas::DriftStep step{kickBefore, h, kickAfter, track};
    bool escaped = false;
    double worst = 0.0;
    // One block of disks per thread (gas::driftBlock copies the constants it reads: the master's stack
    // lines, which it keeps writing, were false sharing measured at a third of the loop's time).
#pragma omp parallel reduction(|| : escaped) reduction(max : worst) if (n >= kParallelMinParticles)
    gas::driftBlock(walls, step, arrays, gas::threadRange(static_cast<std::size_t>(n)), escaped, worst);
    escaped_ = escaped_ || escaped;
    maxDisplacement2_ = track ? worst : -1.0;
    ++driftIndex_;
}

void GasModel::boundaryStage(double h) {
    GasState& s = state_;
    const gas::Boundaries walls = boundaries(h);
    const auto n = static_cast<long long>(s.size());
    bool escaped = false;
#pragma omp parallel for schedule(static) reduction(||                                                       \
                                                    : escaped)                                               \
    firstprivate(walls) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        double impulse = 0.0;
        if (!walls.apply(s.x[i], s.y[i], s.vx[i], s.vy[i], s.species[i], s.id[i], impulse)) escaped = true;
        s.wallImpulse[i] += impulse;
    }
    escaped_ = escaped_ || escaped;
    maxDisplacement2_ = -1.0;
    ++driftIndex_;
}

// The integrator table's fused passes (GasIntegratorTable.h): one pass over the particles each, and a
// drift with the force pass after it in one parallel region. A stop request may end the step between
// passes (common/StopRequest.h): one pass over 67 M disks takes well under a second.
void GasModel::runPasses(const std::vector<GasPass>& passes, double h) {
    for (std::size_t p = 0; p < passes.size(); ++p) {
        leaveIfAbandoning();
        const GasPass& pass = passes[p];
        const GasPass* next = p + 1 < passes.size() ? &passes[p + 1] : nullptr;
        if (pass.kind == GasPass::Kind::Drift && next && next->kind == GasPass::Kind::Forces &&
            params_.forceMethod != GasForceMethod::AllPairs) {
            driftThenForces(stepFraction(pass.kickBefore, h), stepFraction(pass.drift, h),
                            stepFraction(pass.kickAfter, h),
                            next->countContacts ? Contacts::Count : Contacts::Ignore,
                            stepFraction(next->kickAfter, h));
            ++p;
            continue;
        }
        switch (pass.kind) {
        case GasPass::Kind::Drift:
            driftStage(stepFraction(pass.kickBefore, h), stepFraction(pass.drift, h),
                       stepFraction(pass.kickAfter, h));
            break;
        case GasPass::Kind::Forces:
            computeForces(pass.countContacts ? Contacts::Count : Contacts::Ignore,
                          stepFraction(pass.kickAfter, h));
            break;
        case GasPass::Kind::RungeKutta4:
            stepRungeKutta4(h);
            break;
        }
    }
}

// Classical RK4 on (x, v); walls reflect the final state (exact for free flight at the wall).
void GasModel::stepRungeKutta4(double h) {
    const std::size_t n = state_.size();
    for (auto* v : {&stageX_, &stageY_, &stageVX_, &stageVY_, &sumVX_, &sumVY_, &sumAX_, &sumAY_})
        v->resize(n);
    auto& s = state_;
    const auto count = static_cast<long long>(n);
    // Stage k1 from the cached a(x_n); x0, v0 saved in stage*.
#pragma omp parallel for schedule(static) if (count >= kParallelMinParticles)
    for (long long i = 0; i < count; ++i) {
        stageX_[i] = s.x[i], stageY_[i] = s.y[i], stageVX_[i] = s.vx[i], stageVY_[i] = s.vy[i];
        sumVX_[i] = s.vx[i], sumVY_[i] = s.vy[i], sumAX_[i] = s.ax[i], sumAY_[i] = s.ay[i];
    }
    // Stages 2–4: state at x0 + c h k_{prev}, weights 2, 2, 1.
    const double c[3] = {0.5, 0.5, 1.0};
    const double w[3] = {2.0, 2.0, 1.0};
    for (int stage = 0; stage < 3; ++stage) {
        const double ch = c[stage] * h;
#pragma omp parallel for schedule(static) if (count >= kParallelMinParticles)
        for (long long i = 0; i < count; ++i) {
            const double vxPrev = s.vx[i], vyPrev = s.vy[i];
            s.x[i] = stageX_[i] + ch * vxPrev;
            s.y[i] = stageY_[i] + ch * vyPrev;
            s.vx[i] = stageVX_[i] + ch * s.ax[i];
            s.vy[i] = stageVY_[i] + ch * s.ay[i];
        }
        maxDisplacement2_ = -1.0;
        computeForces(Contacts::Ignore);
#pragma omp parallel for schedule(static) if (count >= kParallelMinParticles)
        for (long long i = 0; i < count; ++i) {
            sumVX_[i] += w[stage] * s.vx[i], sumVY_[i] += w[stage] * s.vy[i];
            sumAX_[i] += w[stage] * s.ax[i], sumAY_[i] += w[stage] * s.ay[i];
        }
    }
#pragma omp parallel for schedule(static) if (count >= kParallelMinParticles)
    for (long long i = 0; i < count; ++i) {
        s.x[i] = stageX_[i] + h / 6.0 * sumVX_[i];
        s.y[i] = stageY_[i] + h / 6.0 * sumVY_[i];
        s.vx[i] = stageVX_[i] + h / 6.0 * sumAX_[i];
        s.vy[i] = stageVY_[i] + h / 6.0 * sumAY_[i];
    }
    boundaryStage(h);
    computeForces(Contacts::Count);
}

} // namespace pl
