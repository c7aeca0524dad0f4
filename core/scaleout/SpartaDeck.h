// The homogeneous DSMC cell as a SPARTA deck: species and VSS collision files, the exact initial
// velocities as a particle file SPARTA reads, the cell's volume, F_N and dt, stats and velocity dumps.
#pragma once

#include "LammpsDeck.h"
#include "dsmc/DsmcModel.h"

namespace pl::scaleout {

// SPARTA's VSS parameters of one species (collide vss): σ c_r = π d² (2kT_ref/m_r)^(ω−½) c_r^(2−2ω) /
// Γ(5/2 − ω), isotropic scattering for α = 1 (VHS).
struct VssParameters {
    double diameter = 0; // d_ref [m]
    double omega = 0;
    double tref = 0; // [K]
    double alpha = 1;
};

// The VHS parameters that give exactly our σ c_r: hard spheres and VHS directly, the seed's power law
// (ω = 3/4) and Maxwell molecules (ω = 1) through the reference diameter at vhs_tref (docs/dsmc.md).
VssParameters vssParameters(const DsmcParams& params, const CollisionModel& model);

struct SpartaExportOptions {
    long long steps = 500;
    long long every = 1; // stats and velocity dumps
};

inline constexpr const char* kSpartaInput = "in.sparta";
inline constexpr const char* kSpartaParticles = "particles.sparta";
inline constexpr const char* kSpartaDump = "dump.sparta";

// Throws ExportError for velocities and scattering in the plane (velocity_components = 2).
Deck spartaDeck(const DsmcModel& cell, const SpartaExportOptions& options);

} // namespace pl::scaleout
