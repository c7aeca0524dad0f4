// The integrator sweep on the harmonic pair, run through MdModel's own integrators.
#include "MethodSweep.h"

#include "MdKernels.h"
#include "MdModel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace pl::md {

namespace {
constexpr double kDiameter = 0.1, kOverlap = 0.02;
constexpr double kHorizonOverQuarterPeriod = 0.8;
} // namespace

int forcesPerStep(const std::string& integrator) {
    if (integrator == "rk4") return 4;
    if (integrator == "forest-ruth") return 3;
    integratorFromName(integrator); // throws for an unknown name
    return 1;
}

int theoreticalOrder(const std::string& integrator) {
    if (integrator == "velocity-verlet") return 2;
    if (integrator == "rk4" || integrator == "forest-ruth") return 4;
    integratorFromName(integrator);
    return 1; // symplectic and explicit Euler
}

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
            MdModel model;
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
            p.forcesPerTime = forcesPerStep(name) / dt;
            const MdState& s = model.state();
            for (std::size_t i = 0; i < s.size(); ++i) {
                const double exact = (s.id[i] == 0 ? -0.5 : 0.5) * gap; // the pair stays on the x axis
                p.trajectoryError = std::max({p.trajectoryError, std::abs(s.x[i] - exact), std::abs(s.y[i])});
            }
            dts.push_back(dt);
            errors.push_back(p.trajectoryError);
            result.points.push_back(p);
        }
        result.orders.push_back({name, fitOrder(dts, errors), theoreticalOrder(name)});
    }
    return result;
}

} // namespace pl::md
