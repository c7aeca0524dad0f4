// The methods lab's CLI subcommands: each runs its study in core, writes the CSV and prints a summary.
#include "MethodsCommands.h"

#include "Commands.h"
#include "catalog/ModelCatalog.h"
#include "common/sweep/SweepGrid.h"
#include "comparison/GasVsDsmc.h"
#include "dsmc/DsmcSweep.h"
#include "fluid/FluidSweep.h"
#include "gas/GasModel.h"
#include "gas/StabilityMap.h"

#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

namespace pl::cli {

namespace {

// A CSV field: quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + '"';
}

} // namespace

int stabilityMap(const StabilityOptions& options) {
    const std::vector<double> columns =
        options.omegaDt.empty() ? methods::logSpaced(0.05, 5.0, 25) : options.omegaDt;
    gas::StabilitySetup setup;
    setup.steps = options.steps;
    setup.tolerance = options.tolerance;
    std::ostringstream csv;
    csv.precision(10);
    csv << "integrator,dt,stiffness,omega_dt,outcome,energy_error,steps,seconds,detail\n";
    for (const auto& name : options.integrators) {
        try {
            gasIntegrator(name);
        } catch (const std::exception& e) {
            std::cerr << "particlelab-cli: " << e.what() << "\n";
            return kBadInput;
        }
        for (double k : options.stiffness) {
            std::vector<gas::StabilityCell> row;
            const double omega = gas::cagedOmega(k);
            for (double wdt : columns) {
                row.push_back(gas::runStabilityCell(name, wdt / omega, k, setup));
                const gas::StabilityCell& c = row.back();
                csv << name << ',' << c.dt << ',' << c.stiffness << ',' << c.omegaDt << ','
                    << methods::outcomeName(c.status.outcome) << ',' << c.energyError << ',' << c.status.steps
                    << ',' << c.status.seconds << ',' << csvField(c.status.detail) << '\n';
            }
            std::cerr << name << ", k = " << k << ": stable up to ω dt = " << gas::measuredLimit(row)
                      << " (linear theory " << gasIntegrator(name).stabilityLimit << ")\n";
        }
    }
    return writeOrPrint(options.out, csv.str());
}

int fluidSweep(const FluidSweepOptions& options) {
    fluid::FluidSweepSetup setup;
    setup.duration = options.duration;
    setup.tolerance = options.tolerance;
    std::ostringstream csv;
    csv.precision(10);
    csv << "dt,iterations,outcome,density_error_mean,density_error_max,max_speed,seconds_per_time,steps,"
           "detail\n";
    const Preset base = fluid::smallDamBreak();
    for (double dt : options.dt)
        for (int iterations : options.iterations) {
            const fluid::FluidCell c = fluid::runFluidCell(base, dt, iterations, setup);
            csv << c.dt << ',' << c.iterations << ',' << methods::outcomeName(c.status.outcome) << ','
                << c.densityErrorMean << ',' << c.densityErrorMax << ',' << c.maxSpeed << ','
                << c.secondsPerTime << ',' << c.status.steps << ',' << csvField(c.status.detail) << '\n';
            std::cerr << "dt " << dt << ", " << iterations
                      << " iterations: " << methods::outcomeName(c.status.outcome) << ", mean density error "
                      << c.densityErrorMean << "\n";
        }
    return writeOrPrint(options.out, csv.str());
}

int dsmcSweep(const DsmcSweepOptions& options) {
    const Preset base = loadPreset("dsmc-bkw");
    std::ostringstream csv;
    csv.precision(10);
    csv << "particles,nu_dt,dt,outcome,moment_error,seconds,steps,detail\n";
    for (long long n : options.particles)
        for (double nuDt : options.nuDt) {
            const dsmc::DsmcCell c = dsmc::runDsmcCell(base, n, nuDt);
            csv << c.particles << ',' << c.nuDt << ',' << c.dt << ','
                << methods::outcomeName(c.status.outcome) << ',' << c.momentError << ',' << c.seconds << ','
                << c.status.steps << ',' << csvField(c.status.detail) << '\n';
            std::cerr << n << " particles, ν dt " << nuDt << ": moment error " << c.momentError << ", "
                      << c.seconds << " s\n";
        }
    return writeOrPrint(options.out, csv.str());
}

int relaxMdDsmc(const RelaxOptions& options) {
    methods::TwoBeamSetup setup;
    setup.particles = options.particles;
    setup.collisionsPerParticle = options.collisions;
    setup.seed = options.seed;
    methods::GasVsDsmcResult r;
    try {
        r = methods::compareRelaxations(methods::relaxWithMd(setup), methods::relaxWithDsmc(setup));
    } catch (const std::exception& e) {
        std::cerr << "particlelab-cli: " << e.what() << "\n";
        return kBadInput;
    }
    std::ostringstream csv;
    csv.precision(10);
    csv << "method,collisions_per_particle,kurtosis_vx,seconds\n";
    for (const methods::RelaxationRun* run : {&r.md, &r.dsmc})
        for (const auto& s : run->curve)
            csv << run->method << ',' << s.collisionsPerParticle << ',' << s.kurtosisVx << ',' << s.seconds
                << '\n';
    std::cerr << "MD: " << r.md.seconds << " s, " << r.md.particleSteps
              << " particle-steps; DSMC: " << r.dsmc.seconds << " s; cost ratio " << r.costRatio
              << "; final v_x KS distance " << r.ksDistance << " (p = " << r.ksPValue << ")\n";
    return writeOrPrint(options.out, csv.str());
}

} // namespace pl::cli
