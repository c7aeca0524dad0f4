// The integrator sweep on the harmonic pair, run through GasModel's own integrators; costs and orders
// from the integrator table.
#include "MethodSweep.h"

#include "GasKernels.h"
#include "GasModel.h"
#include "common/sweep/CellOutcome.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace pl::gas {

namespace {
constexpr double kDiameter = 0.1, kOverlap = 0.02;
constexpr double kHorizonOverQuarterPeriod = 0.8;
} // namespace

double fitOrder(const std::vector<double>& dts, const std::vector<double>& errors, double noiseFloor) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t k = 0; k < dts.size(); ++k) {
        if (!(errors[k] > noiseFloor) || !std::isfinite(errors[k])) continue;
        const double x = std::log(dts[k]), y = std::log(errors[k]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        ++n;
    }
    if (n < 2) return std::numeric_limits<double>::quiet_NaN();
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

SweepResult sweepHarmonicPair(const std::vector<std::string>& integrators, const std::vector<int>& stepsList,
                              double stiffness) {
    const double omega = contactOmega(stiffness, 1.0, 1.0);
    const double horizon = kHorizonOverQuarterPeriod * 0.5 * std::numbers::pi / omega;
    const double gap = kDiameter - kOverlap * std::cos(omega * horizon); // r(T)
    SweepResult result;
    for (const auto& name : integrators) {
        std::vector<double> dts, errors;
        for (int steps : stepsList) {
            if (steps < 1) throw std::invalid_argument("steps per horizon must be positive");
            GasModel model;
            const double dt = horizon / steps;
            model.setParams({{"count_a", 2.0},
                             {"integrator", name},
                             {"dt", dt},
                             {"stiffness", stiffness},
                             {"diameter_a", kDiameter},
                             {"mass_a", 1.0}});
            const double x0 = 0.5 * (kDiameter - kOverlap);
            model.placeParticles({{-x0, 0.0, 0.0, 0.0, 0}, {x0, 0.0, 0.0, 0.0, 0}});
            const double e0 = model.totalEnergy();
            SweepPoint p;
            p.integrator = name;
            p.dt = dt;
            const auto start = std::chrono::steady_clock::now();
            for (int s = 0; s < steps; ++s) {
                model.step();
                p.energyError = std::max(p.energyError, std::abs(model.totalEnergy() - e0) / e0);
            }
            p.secondsPerTime =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / horizon;
            p.forcesPerTime = gasIntegrator(name).forcesPerStep() / dt;
            const GasState& s = model.state();
            for (std::size_t i = 0; i < s.size(); ++i) {
                const double exact = (s.id[i] == 0 ? -0.5 : 0.5) * gap; // the pair stays on the x axis
                p.trajectoryError = std::max({p.trajectoryError, std::abs(s.x[i] - exact), std::abs(s.y[i])});
            }
            dts.push_back(dt);
            errors.push_back(p.trajectoryError);
            result.points.push_back(p);
        }
        result.orders.push_back({name, fitOrder(dts, errors), gasIntegrator(name).order});
    }
    return result;
}

namespace {

std::unique_ptr<GasModel> startFrom(const GasReference& reference, const std::string& integrator, double dt) {
    auto model = std::make_unique<GasModel>();
    Preset preset = reference.preset;
    preset.params["integrator"] = integrator;
    preset.params["dt"] = dt;
    preset.params["wall_mode"] = std::string("reflecting"); // thermal walls draw random numbers per step
    model->reset(preset);
    model->placeParticles(reference.start);
    return model;
}

// Positions by disk: ids are the start order (placeParticles numbers them so); the model sorts in space.
void positionsByDisk(const GasModel& model, std::vector<double>& x, std::vector<double>& y) {
    const GasState& s = model.state();
    x.assign(s.size(), 0.0);
    y.assign(s.size(), 0.0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        x[s.id[i]] = s.x[i];
        y[s.id[i]] = s.y[i];
    }
}

} // namespace

GasReference captureGas(const GasModel& source) {
    GasReference reference;
    reference.preset = source.toPreset();
    const GasState& s = source.state();
    for (std::size_t i = 0; i < s.size(); ++i)
        reference.start.push_back({s.x[i], s.y[i], s.vx[i], s.vy[i], s.species[i]});
    return reference;
}

GasReference gasReference(const GasModel& source, double horizon, double referenceDt) {
    GasReference reference = captureGas(source);
    runReference(reference, horizon, referenceDt);
    return reference;
}

void runReference(GasReference& reference, double horizon, double referenceDt) {
    if (!(horizon > 0) || !(referenceDt > 0) || referenceDt > horizon)
        throw std::invalid_argument("the reference needs 0 < dt ≤ horizon");
    if (reference.start.empty()) throw std::invalid_argument("the gas has no disks to follow");
    reference.horizon = horizon;
    reference.referenceDt = referenceDt;
    auto model = startFrom(reference, gasIntegrator(GasIntegrator::ForestRuth).name, referenceDt);
    const auto steps = std::llround(horizon / referenceDt);
    for (long long k = 0; k < steps; ++k) model->step();
    if (model->failure())
        throw std::runtime_error("the reference run failed: " + model->failure()->message());
    positionsByDisk(*model, reference.x, reference.y);
}

SweepResult sweepFromReference(const GasReference& reference, const std::vector<std::string>& integrators,
                               const std::vector<int>& stepsList) {
    if (reference.x.empty()) throw std::invalid_argument("the reference run has not been made");
    SweepResult result;
    for (const auto& name : integrators) {
        std::vector<double> dts, errors;
        for (int steps : stepsList) {
            if (steps < 1) throw std::invalid_argument("steps per horizon must be positive");
            result.points.push_back(sweepFromState(reference, name, reference.horizon / steps));
            dts.push_back(result.points.back().dt);
            errors.push_back(result.points.back().trajectoryError);
        }
        result.orders.push_back({name, fitOrder(dts, errors), gasIntegrator(name).order});
    }
    return result;
}

SweepPoint sweepFromState(const GasReference& reference, const std::string& integrator, double dt) {
    SweepPoint p;
    p.integrator = integrator;
    p.dt = dt;
    p.forcesPerTime = gasIntegrator(integrator).forcesPerStep() / dt; // throws for an unknown name
    auto model = startFrom(reference, integrator, dt);
    const double e0 = model->totalEnergy();
    const auto steps = std::max<long long>(1, std::llround(reference.horizon / dt));
    double seconds = 0; // the steps only, not the energy checks between them
    for (long long k = 0; k < steps; ++k) {
        seconds += methods::secondsOf([&] { model->step(); });
        if (model->failure()) {
            p.failure = model->failure()->message();
            break;
        }
        p.energyError = std::max(p.energyError, std::abs(model->totalEnergy() - e0) / std::abs(e0));
    }
    p.secondsPerTime = seconds / (static_cast<double>(steps) * dt);
    // A horizon of a few steps ends before the model's periodic health check: judge the energy here.
    if (p.failure.empty() && !(p.energyError <= 1.0))
        p.failure = "the energy changed by more than 100 % within the horizon: unstable at this dt";
    if (!p.failure.empty()) {
        p.trajectoryError = p.energyError = std::numeric_limits<double>::quiet_NaN();
        return p;
    }
    std::vector<double> x, y;
    positionsByDisk(*model, x, y);
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
        sum += (x[i] - reference.x[i]) * (x[i] - reference.x[i]) +
               (y[i] - reference.y[i]) * (y[i] - reference.y[i]);
    p.trajectoryError = std::sqrt(sum / static_cast<double>(x.size()));
    return p;
}

} // namespace pl::gas
