// The five time-stepping schemes, built from drift stages (kick, drift, boundaries fused in one pass)
// and force stages (forces, then a kick, in one pass). Each scheme ends with forces at the new
// positions, so the next step starts from cached forces.
#include "MdModel.h"
#include "common/Parallel.h"

#include <cmath>

namespace pl {

namespace {
// Forest & Ruth (1990) / Yoshida (1990) 4th-order symplectic composition: θ = 1 / (2 − 2^{1/3}).
const double kForestRuthTheta = 1.0 / (2.0 - std::cbrt(2.0));
} // namespace

void MdModel::driftStage(double kickBefore, double h, double kickAfter) {
    MdState& s = state_;
    const md::Boundaries walls = boundaries(h);
    const auto n = static_cast<long long>(s.size());
    const bool track = neighbours_.valid() && params_.forceMethod != "all-pairs";
    const double* builtX = neighbours_.builtX();
    const double* builtY = neighbours_.builtY();
    double* px = s.x.data();
    double* py = s.y.data();
    double* pvx = s.vx.data();
    double* pvy = s.vy.data();
    const double* pax = s.ax.data();
    const double* pay = s.ay.data();
    double* impulses = s.wallImpulse.data();
    const std::uint8_t* species = s.species.data();
    const std::uint32_t* ids = s.id.data();
    bool escaped = false;
    double worst = 0.0;
    // firstprivate: each thread reads its own copy of the loop's constants instead of the master's stack,
    // whose cache lines the master keeps writing (false sharing measured at a third of the loop's time).
#pragma omp parallel for schedule(static) reduction(||                                                       \
                                                    : escaped) reduction(max                                 \
                                                                         : worst)                            \
    firstprivate(walls, kickBefore, h, kickAfter, track, builtX, builtY, px, py, pvx, pvy, pax, pay,         \
                 impulses, species, ids) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        double vx = pvx[i] + kickBefore * pax[i];
        double vy = pvy[i] + kickBefore * pay[i];
        double x = px[i] + h * vx;
        double y = py[i] + h * vy;
        double impulse = 0.0;
        if (!walls.apply(x, y, vx, vy, species[i], ids[i], impulse)) escaped = true;
        if (impulse != 0.0) impulses[i] += impulse;
        px[i] = x;
        py[i] = y;
        pvx[i] = vx + kickAfter * pax[i];
        pvy[i] = vy + kickAfter * pay[i];
        if (track)
            worst = std::max(worst, (x - builtX[i]) * (x - builtX[i]) + (y - builtY[i]) * (y - builtY[i]));
    }
    escaped_ = escaped_ || escaped;
    maxDisplacement2_ = track ? worst : -1.0;
    ++driftIndex_;
}

void MdModel::boundaryStage(double h) {
    MdState& s = state_;
    const md::Boundaries walls = boundaries(h);
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

// Velocity Verlet (kick–drift–kick, Strang splitting): 2nd order, symplectic, time-reversible.
void MdModel::stepVelocityVerlet(double h) {
    driftStage(0.5 * h, h, 0.0);
    computeForces(Contacts::Count, 0.5 * h);
}

// Symplectic Euler: v_{n+1} = v_n + h a(x_n); x_{n+1} = x_n + h v_{n+1}. 1st order, symplectic.
void MdModel::stepSymplecticEuler(double h) {
    driftStage(h, h, 0.0);
    computeForces(Contacts::Count);
}

// Explicit Euler: x_{n+1} = x_n + h v_n; v_{n+1} = v_n + h a(x_n). Energy grows by (1 + ω²h²) per step.
void MdModel::stepExplicitEuler(double h) {
    driftStage(0.0, h, h); // the kick after the drift still uses a(x_n)
    computeForces(Contacts::Count);
}

// Forest–Ruth in velocity form: kicks θ/2, (1−θ)/2, (1−θ)/2, θ/2 around drifts θ, 1−2θ, θ.
void MdModel::stepForestRuth(double h) {
    const double t = kForestRuthTheta;
    driftStage(0.5 * t * h, t * h, 0.0);
    computeForces(Contacts::Ignore);
    driftStage(0.5 * (1.0 - t) * h, (1.0 - 2.0 * t) * h, 0.0);
    computeForces(Contacts::Ignore);
    driftStage(0.5 * (1.0 - t) * h, t * h, 0.0);
    computeForces(Contacts::Count, 0.5 * t * h);
}

// Classical RK4 on (x, v); walls reflect the final state (exact for free flight at the wall).
void MdModel::stepRungeKutta4(double h) {
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
