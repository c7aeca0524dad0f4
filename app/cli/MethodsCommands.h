// The methods lab's subcommands: stability maps of the gas and the fluid, and MD against DSMC. Each
// writes CSV (standard output without --out) and a summary on stderr, and returns the exit code.
#pragma once

#include "gas/GasIntegratorTable.h"

#include <string>
#include <vector>

namespace pl::cli {

struct StabilityOptions {
    std::vector<std::string> integrators = gasIntegratorNamesByOrder();
    std::vector<double> omegaDt;                  // ω dt of the columns (default 0.05 … 5, log-spaced)
    std::vector<double> stiffness{1e2, 1e3, 1e4}; // k of the rows [M/T²]
    long long steps = 4000;
    double tolerance = 0.01;
    std::string out;
};

struct FluidSweepOptions {
    std::vector<double> dt{0.0025, 0.005, 0.01, 0.02, 0.04};
    std::vector<int> iterations{1, 2, 3, 5, 8};
    double duration = 1.0;
    double tolerance = 0.01;
    std::string out;
};

struct DsmcSweepOptions {
    std::vector<long long> particles{1000, 4000, 16000, 64000};
    std::vector<double> nuDt{0.03, 0.1, 0.3, 1.0};
    std::string out;
};

struct RelaxOptions {
    long long particles = 1024;
    double collisions = 10;
    unsigned long long seed = 1;
    std::string out;
};

int stabilityMap(const StabilityOptions& options);
int fluidSweep(const FluidSweepOptions& options);
int dsmcSweep(const DsmcSweepOptions& options);
int relaxMdDsmc(const RelaxOptions& options);

} // namespace pl::cli
