// One cell of the DSMC sweep, run through DsmcModel against its own BKW columns.
#include "DsmcSweep.h"

#include "DsmcModel.h"

#include <cmath>
#include <stdexcept>

namespace pl::dsmc {

DsmcCell runDsmcCell(const Preset& base, long long particles, double nuDt, const DsmcSweepSetup& setup) {
    DsmcCell cell;
    cell.particles = particles;
    cell.nuDt = nuDt;
    cell.status = methods::runIsolated([&](methods::CellStatus& status) {
        DsmcModel model;
        model.reset(base);
        const DsmcParams& p = model.parameters();
        if (p.initial != DsmcInitialState::Bkw || p.crossSection != DsmcCrossSection::Maxwell)
            throw std::invalid_argument(
                "the DSMC sweep measures against BKW: it needs Maxwell molecules from "
                "the BKW start (the dsmc-bkw preset)");
        if (particles < 2) throw std::invalid_argument("a DSMC cell needs at least 2 particles");
        if (!(nuDt > 0)) throw std::invalid_argument("ν dt must be positive");
        Preset preset = base;
        const double density = model.numberDensity();
        preset.params["count_a"] = static_cast<double>(particles);
        preset.params["fn"] = density * p.cellVolume / static_cast<double>(particles);
        preset.params["run_steps"] = 0.0;
        const double nu = density * model.collisionModel().prefactor; // n σ c_r, Maxwell molecules
        cell.dt = nuDt / nu;
        preset.params["dt"] = cell.dt;
        model.reset(preset);
        const auto steps = std::max<long long>(1, std::llround(setup.collisionTimes / nuDt));
        double sum = 0;
        status.outcome = methods::CellOutcome::Stable;
        for (long long s = 0; s < steps; ++s) {
            cell.seconds += methods::secondsOf([&] { model.step(); });
            status.steps = s + 1;
            if (const auto failure = model.failure()) {
                status.outcome = methods::CellOutcome::Unstable;
                status.detail = failure->what;
                return;
            }
            const DsmcObservables o = model.observe();
            sum += 0.5 * ((o.m4 - o.m4Bkw) * (o.m4 - o.m4Bkw) + (o.m6 - o.m6Bkw) * (o.m6 - o.m6Bkw));
        }
        cell.momentError = std::sqrt(sum / static_cast<double>(steps));
    });
    return cell;
}

} // namespace pl::dsmc
