// The DSMC scenes as SPARTA decks: the homogeneous cell (species and VSS files, the exact initial
// velocities as a particle file, the cell's volume, F_N and dt, stats and velocity dumps) and the wind
// tunnel (a 2D box and grid, the free stream through fix emit/face, the sides, the bodies as polygons,
// the sampled grid fields and the force on the bodies).
#pragma once

#include "LammpsDeck.h"
#include "dsmc/DsmcModel.h"
#include "tunnel/TunnelModel.h"

namespace pl::scaleout {

// SPARTA's VSS parameters of one species (collide vss): σ c_r = π d² (2kT_ref/m_r)^(ω−½) c_r^(2−2ω) /
// Γ(5/2 − ω), isotropic scattering for α = 1 (VHS).
struct VssParameters {
    double diameter = 0; // d_ref [m]
    double omega = 0;
    double tref = 0; // [K]
    double alpha = 1;
};

// The VHS parameters that give exactly our σ c_r: hard spheres and VHS directly, the write-up's power law
// (ω = 3/4) and Maxwell molecules (ω = 1) through the reference diameter at vhs_tref (docs/dsmc.md).
VssParameters vssParameters(const DsmcParams& params, const CollisionModel& model);
VssParameters vssParameters(const TunnelParams& params, const CollisionModel& model);
// How a cross-section model reads as SPARTA's VHS, for a deck's notes: "hard spheres (VHS, omega = 1/2)".
std::string crossSectionName(CollisionModel::Kind kind);

struct SpartaExportOptions {
    long long steps = 500;
    long long every = 1; // stats and velocity dumps
};

inline constexpr const char* kSpartaInput = "in.sparta";
inline constexpr const char* kSpartaParticles = "particles.sparta";
inline constexpr const char* kSpartaDump = "dump.sparta";

// Throws ExportError for velocities and scattering in the plane (velocity_components = 2).
Deck spartaDeck(const DsmcModel& cell, const SpartaExportOptions& options);

// The tunnel deck's own files: the bodies as SPARTA line segments, and the grid fields averaged over the
// window from sample_start to the end of the run (dump grid: id xlo ylo xhi yhi vol, then per cell the
// particle count, n, u, v, w and the mean squares of vx, vy, vz).
inline constexpr const char* kSpartaBodies = "bodies.surf";
inline constexpr const char* kSpartaGrid = "grid.sparta";

// Sides of a disc's polygon: segments no longer than a quarter of the smaller cell side, at least 64.
int discPolygonSides(double radius, const TunnelParams& params);

// The tunnel's set-up (parameters and bodies, not its particles: SPARTA draws the initial gas from the
// same state) with every `every` steps a stats row of the force on the bodies averaged since the last
// row [N/m]. Bodies are exported at rest where they are. Throws ExportError for a piston (SPARTA's
// boundaries do not move), for a run that ends before the fields window opens, and, with bodies, for a
// run that is not a whole number of stats intervals (SPARTA's last row would find no force average).
Deck spartaDeck(const TunnelModel& tunnel, const SpartaExportOptions& options);

} // namespace pl::scaleout
