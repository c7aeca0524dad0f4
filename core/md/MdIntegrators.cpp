// The five time-stepping schemes, built from kick (v += h a) and drift (x += h v, then boundaries).
// Each ends with forces evaluated at the new positions, so the next step starts from cached forces.
#include "MdModel.h"
#include "common/Parallel.h"

#include <cmath>

namespace pl {

namespace {
// Forest & Ruth (1990) / Yoshida (1990) 4th-order symplectic composition: θ = 1 / (2 − 2^{1/3}).
const double kForestRuthTheta = 1.0 / (2.0 - std::cbrt(2.0));
} // namespace

void MdModel::kick(double h) {
    const auto n = static_cast<long long>(state_.size());
    double* vx = state_.vx.data();
    double* vy = state_.vy.data();
    const double* ax = state_.ax.data();
    const double* ay = state_.ay.data();
#pragma omp parallel for simd schedule(static) if(n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        vx[i] += h * ax[i];
        vy[i] += h * ay[i];
    }
}

void MdModel::drift(double h) {
    const auto n = static_cast<long long>(state_.size());
    double* x = state_.x.data();
    double* y = state_.y.data();
    const double* vx = state_.vx.data();
    const double* vy = state_.vy.data();
#pragma omp parallel for simd schedule(static) if(n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        x[i] += h * vx[i];
        y[i] += h * vy[i];
    }
    applyBoundaries(h);
    ++driftIndex_;
}

// Velocity Verlet (kick–drift–kick, Strang splitting): 2nd order, symplectic, time-reversible.
void MdModel::stepVelocityVerlet(double h) {
    kick(0.5 * h);
    drift(h);
    computeForces(true);
    kick(0.5 * h);
}

// Symplectic Euler: v_{n+1} = v_n + h a(x_n); x_{n+1} = x_n + h v_{n+1}. 1st order, symplectic.
void MdModel::stepSymplecticEuler(double h) {
    kick(h);
    drift(h);
    computeForces(true);
}

// Explicit Euler: x_{n+1} = x_n + h v_n; v_{n+1} = v_n + h a(x_n). Energy grows by (1 + ω²h²) per step.
void MdModel::stepExplicitEuler(double h) {
    drift(h);
    kick(h); // a still holds a(x_n)
    computeForces(true);
}

// Forest–Ruth in velocity form: kicks θ/2, (1−θ)/2, (1−θ)/2, θ/2 around drifts θ, 1−2θ, θ.
void MdModel::stepForestRuth(double h) {
    const double t = kForestRuthTheta;
    kick(0.5 * t * h);
    drift(t * h);
    computeForces(false);
    kick(0.5 * (1.0 - t) * h);
    drift((1.0 - 2.0 * t) * h);
    computeForces(false);
    kick(0.5 * (1.0 - t) * h);
    drift(t * h);
    computeForces(true);
    kick(0.5 * t * h);
}

// Classical RK4 on (x, v); walls reflect the final state (exact for free flight at the wall).
void MdModel::stepRungeKutta4(double h) {
    const std::size_t n = state_.size();
    for (auto* v : {&stageX_, &stageY_, &stageVX_, &stageVY_, &sumVX_, &sumVY_, &sumAX_, &sumAY_}) v->resize(n);
    auto& s = state_;
    const auto count = static_cast<long long>(n);
    // Stage k1 from the cached a(x_n); x0, v0 saved in stage*.
#pragma omp parallel for schedule(static) if(count >= kParallelMinParticles)
    for (long long i = 0; i < count; ++i) {
        stageX_[i] = s.x[i], stageY_[i] = s.y[i], stageVX_[i] = s.vx[i], stageVY_[i] = s.vy[i];
        sumVX_[i] = s.vx[i], sumVY_[i] = s.vy[i], sumAX_[i] = s.ax[i], sumAY_[i] = s.ay[i];
    }
    // Stages 2–4: state at x0 + c h k_{prev}, weights 2, 2, 1.
    const double c[3] = {0.5, 0.5, 1.0};
    const double w[3] = {2.0, 2.0, 1.0};
    for (int stage = 0; stage < 3; ++stage) {
        const double ch = c[stage] * h;
#pragma omp parallel for schedule(static) if(count >= kParallelMinParticles)
        for (long long i = 0; i < count; ++i) {
            const double vxPrev = s.vx[i], vyPrev = s.vy[i];
            s.x[i] = stageX_[i] + ch * vxPrev;
            s.y[i] = stageY_[i] + ch * vyPrev;
            s.vx[i] = stageVX_[i] + ch * s.ax[i];
            s.vy[i] = stageVY_[i] + ch * s.ay[i];
        }
        computeForces(false);
#pragma omp parallel for schedule(static) if(count >= kParallelMinParticles)
        for (long long i = 0; i < count; ++i) {
            sumVX_[i] += w[stage] * s.vx[i], sumVY_[i] += w[stage] * s.vy[i];
            sumAX_[i] += w[stage] * s.ax[i], sumAY_[i] += w[stage] * s.ay[i];
        }
    }
#pragma omp parallel for schedule(static) if(count >= kParallelMinParticles)
    for (long long i = 0; i < count; ++i) {
        s.x[i] = stageX_[i] + h / 6.0 * sumVX_[i];
        s.y[i] = stageY_[i] + h / 6.0 * sumVY_[i];
        s.vx[i] = stageVX_[i] + h / 6.0 * sumAX_[i];
        s.vy[i] = stageVY_[i] + h / 6.0 * sumAY_[i];
    }
    applyBoundaries(h);
    computeForces(true);
}

} // namespace pl
