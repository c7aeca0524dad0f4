// One cell of the fluid sweep, run through FluidModel's own solver and divergence check.
#include "FluidSweep.h"

#include "FluidModel.h"

#include <algorithm>
#include <cmath>

namespace pl::fluid {

Preset smallDamBreak() {
    Preset p;
    p.model = "fluid";
    p.name = "small-dam-break";
    p.description =
        "A 5 × 10 column released against the left wall (the dam break at a quarter of its size).";
    p.params = {{"h", 0.8},
                {"epsilon", 1.0},
                {"kernel", "2d"},
                {"self_density", true},
                {"rest_density_source", "spawn-lattice"},
                {"spawn_spacing", 0.5},
                {"particle_radius", 0.2},
                {"max_particles", 3000.0},
                {"drain", false},
                {"fill_x0", 0.0},
                {"fill_y0", 0.0},
                {"fill_x1", 5.0},
                {"fill_y1", 10.0},
                {"box_width", 20.0},
                {"box_height", 15.0}};
    return p;
}

FluidCell runFluidCell(const Preset& base, double dt, int iterations, const FluidSweepSetup& setup) {
    FluidCell cell;
    cell.dt = dt;
    cell.iterations = iterations;
    cell.status = methods::runIsolated([&](methods::CellStatus& status) {
        Preset preset = base;
        preset.params["dt"] = dt;
        preset.params["iterations"] = static_cast<double>(iterations);
        preset.params["run_steps"] = 0.0;
        FluidModel model;
        model.reset(preset);
        const FluidParams& p = model.parameters();
        const double g = p.gravityOn ? p.gravityMagnitude() : 0.0;
        // Energy bound: falling the whole box height releases g H per unit mass; a fluid whose mean kinetic
        // energy exceeds that has made energy, not released it.
        const double kineticLimit = setup.explosionFactor * std::max(g * p.boxHeight, 1.0);
        const auto steps = std::max<long long>(1, std::llround(setup.duration / dt));
        double errorSum = 0;
        status.outcome = methods::CellOutcome::Stable;
        for (long long s = 0; s < steps; ++s) {
            cell.stepSeconds += methods::secondsOf([&] { model.step(); });
            status.steps = s + 1;
            if (const auto failure = model.failure()) {
                status.outcome = methods::CellOutcome::Exploded;
                status.detail = failure->what;
                return;
            }
            const std::vector<double> mean = model.iterationErrorMean(), max = model.iterationErrorMax();
            if (!mean.empty()) errorSum += mean.back();
            if (!max.empty()) cell.densityErrorMax = std::max(cell.densityErrorMax, max.back());
            const FluidState& state = model.state();
            double kinetic = 0;
            for (std::size_t i = 0; i < state.size(); ++i) {
                const double v2 = state.vx[i] * state.vx[i] + state.vy[i] * state.vy[i];
                kinetic += 0.5 * v2;
                cell.maxSpeed = std::max(cell.maxSpeed, std::sqrt(v2));
            }
            kinetic /= static_cast<double>(std::max<std::size_t>(state.size(), 1));
            // The first projections of a block that starts off its rest density move particles by a fixed
            // distance, so at a small dt they start fast; a fluid is exploded when it stays that hot.
            const bool settled = 2 * s >= steps;
            if (!std::isfinite(kinetic) || (settled && kinetic > kineticLimit)) {
                status.outcome = methods::CellOutcome::Exploded;
                status.detail =
                    "mean kinetic energy " + std::to_string(kinetic) +
                    " per unit mass after half the run, more than the fall through the box releases";
                return;
            }
        }
        cell.densityErrorMean = errorSum / static_cast<double>(steps);
        if (cell.densityErrorMean > setup.tolerance) status.outcome = methods::CellOutcome::OverCompressed;
    });
    cell.secondsPerTime = cell.stepSeconds / std::max(static_cast<double>(cell.status.steps) * dt, dt);
    return cell;
}

} // namespace pl::fluid
