// Running LAMMPS on an exported deck from here: `mpirun -np N lmp` as a child process whose thermo rows
// report progress and which the caller may cancel (particlelab-cli run-lammps, the app's Simulation →
// Run on LAMMPS…).
#pragma once

#include <functional>
#include <string>

namespace pl::scaleout {

// The first of lmp and mpirun that is not an executable on PATH; empty when both are.
std::string missingLammpsProgram();

struct LammpsRunResult {
    int status = 0;         // LAMMPS's exit status (128 + signal when killed); 0: it ran to its end
    bool cancelled = false; // ended because cancelled() said so
    std::string lastOutput; // its last lines of output, for the message when it failed
};

// Runs `mpirun -np ranks lmp -in in.lammps -log log.lammps` in dir (LammpsDeck.h's names). onStep
// receives the step of every thermo row LAMMPS prints; cancelled is asked about ten times a second and,
// once true, ends the run. Both may be empty; both are called on the calling thread.
LammpsRunResult runLammps(const std::string& dir, int ranks, const std::function<void(long long)>& onStep,
                          const std::function<bool()>& cancelled);

} // namespace pl::scaleout
