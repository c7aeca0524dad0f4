// One cell of the gas stability map, run through GasModel's own integrators and health checks.
#include "StabilityMap.h"

#include "GasKernels.h"
#include "GasModel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pl::gas {

namespace {
// The mass ratio 10¹² keeps the cage still without walls: pushed apart by the preload, the heavy disks
// move 2·10⁻⁵ of it in 4000 steps at ω dt = 2 (walls would hold them, but their bouncing feeds energy
// into the oscillator near the limit).
constexpr double kDiameter = 0.1, kMass = 1e-6, kHeavyMass = 1e6;
constexpr double kPreload = 0.2 * kDiameter; // overlap of each spring at rest
constexpr double kAmplitude = 0.1 * kPreload;
} // namespace

double cagedOmega(double stiffness) {
    return std::sqrt(2.0 * stiffness); // two springs k·m in parallel on the light disk of mass m
}

StabilityCell runStabilityCell(const std::string& integrator, double dt, double stiffness,
                               const StabilitySetup& setup) {
    StabilityCell cell;
    cell.integrator = integrator;
    cell.dt = dt;
    cell.stiffness = stiffness;
    cell.omegaDt = cagedOmega(stiffness) * dt;
    cell.status = methods::runIsolated([&](methods::CellStatus& status) {
        // The heavy disks overlap the light one by kPreload each; the walls are far.
        GasModel model;
        model.setParams({{"count_a", 1.0},
                         {"count_b", 2.0},
                         {"integrator", integrator},
                         {"dt", dt},
                         {"stiffness", stiffness * kMass}, // ω = √(2k), as a unit-mass pair's
                         {"diameter_a", kDiameter},
                         {"diameter_b", kDiameter},
                         {"mass_a", kMass},
                         {"mass_b", kHeavyMass},
                         {"box_width", 10.0 * kDiameter},
                         {"box_height", 2.0 * kDiameter},
                         {"blowup_energy_factor", 1e12}}); // the cell judges growth itself, below
        const double heavyX = kDiameter - kPreload;
        model.placeParticles(
            {{kAmplitude, 0.0, 0.0, 0.0, 0}, {-heavyX, 0.0, 0.0, 0.0, 1}, {heavyX, 0.0, 0.0, 0.0, 1}});
        // The springs' preload holds k m δ₀² of energy that never moves; errors are relative to the
        // oscillation's k m A².
        const double resting = stiffness * kMass * kPreload * kPreload;
        const double e0 = model.totalEnergy() - resting;
        status.outcome = methods::CellOutcome::Stable;
        for (long long s = 0; s < setup.steps; ++s) {
            model.step();
            status.steps = s + 1;
            if (const auto failure = model.failure()) {
                status.outcome = methods::CellOutcome::Unstable;
                status.detail = failure->what;
                return;
            }
            const double error = std::abs(model.totalEnergy() - resting - e0) / e0;
            if (!std::isfinite(error) || error > setup.blowUpFactor) {
                status.outcome = methods::CellOutcome::Unstable;
                status.detail = "the oscillation's energy grew more than " +
                                std::to_string(static_cast<long long>(setup.blowUpFactor)) + "×";
                return;
            }
            cell.energyError = std::max(cell.energyError, error);
        }
        if (cell.energyError > setup.tolerance) status.outcome = methods::CellOutcome::Inaccurate;
    });
    return cell;
}

double measuredLimit(const std::vector<StabilityCell>& row) {
    std::vector<const StabilityCell*> sorted;
    for (const auto& c : row) sorted.push_back(&c);
    std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->omegaDt < b->omegaDt; });
    double lastRan = std::numeric_limits<double>::quiet_NaN();
    for (const StabilityCell* c : sorted) {
        if (c->status.outcome == methods::CellOutcome::Unstable) return lastRan;
        if (c->status.outcome != methods::CellOutcome::Rejected) lastRan = c->omegaDt;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

} // namespace pl::gas
