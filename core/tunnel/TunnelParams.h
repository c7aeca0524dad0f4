// Parameters of the rarefied-gas wind tunnel (SI units: m, s, kg, K): a 2D domain on a uniform grid of
// collision cells, per unit depth (a cell's volume is dx · dy · 1 m), with three velocity components.
// One table drives presets, the CLI and the parameter panel.
#pragma once

#include "common/MemoryBudget.h"

#include "common/ParamSpec.h"
#include "dsmc/DsmcParams.h" // DsmcCrossSection, kBoltzmann, kAtomicMass

#include <string>
#include <vector>

namespace pl {

// What a side of the domain does to a particle that reaches it (docs/wind-tunnel.md#boundaries).
enum class TunnelBoundary {
    Inflow,   // a Maxwellian free stream enters (exact half-range flux); particles leaving are removed
    Outflow,  // vacuum: particles leaving are removed, nothing enters
    Specular, // mirror reflection
    Diffuse,  // full accommodation to wall_temperature, moving along the side at its wall speed
    Periodic, // leaves here, enters at the opposite side (both opposite sides must be periodic)
};
// How a body's surface reflects: diffuse at body_temperature, or specular (in the body's frame).
enum class TunnelSurface { Diffuse, Specular };
// How the domain starts: empty, filled with the free stream, or filled with the free-stream gas at rest.
enum class TunnelInitial { Empty, Stream, Rest };
// What the viewport shows: the particles, or one sampled field as a colour map.
enum class TunnelView { Particles, Density, Speed, Temperature, Mach };
const ChoiceTable<TunnelBoundary>& choiceTable(TunnelBoundary);
const ChoiceTable<TunnelSurface>& choiceTable(TunnelSurface);
const ChoiceTable<TunnelInitial>& choiceTable(TunnelInitial);
const ChoiceTable<TunnelView>& choiceTable(TunnelView);

struct TunnelParams {
    // Domain and method
    double boxWidth = 0.2, boxHeight = 0.12; // [m]
    long long cellsX = 100, cellsY = 60;     // collision and sampling cells
    double fn = 5e14;                        // real molecules per simulated particle (per m of depth)
    double dt = 2e-7;                        // [s]
    long long runSteps = 0;                  // the run stops here; 0 runs on

    // Gas (argon by default; the cross-section models and their parameters are the DSMC cell's, common to
    // both scenes: dsmc/MolecularParams.h)
    double massAmu = 39.948;
    DsmcCrossSection crossSection = DsmcCrossSection::Vhs;
    double diameter = 3.595e-10;     // hard-sphere diameter [m]
    double vhsDiameter = 4.17e-10;   // VHS d_ref (argon, Bird 1994 App. A) [m]
    double vhsTref = 273.0;          // [K]
    double vhsOmega = 0.81;          // argon
    double maxwellSigmaCr = 1.5e-17; // [m³/s]

    // Free stream: what Inflow sides admit, and what Stream / Rest fill the domain with
    double streamDensity = 1e21;      // number density [m⁻³]
    double streamSpeed = 2634.0;      // along +x [m/s]
    double streamTemperature = 200.0; // [K]
    TunnelInitial initial = TunnelInitial::Stream;

    // Sides
    TunnelBoundary left = TunnelBoundary::Inflow, right = TunnelBoundary::Outflow;
    // A side along the stream is an inflow side too (its free stream enters with s_n = 0): an outflow
    // there drains the gas near it, a vacuum parallel to the flow.
    TunnelBoundary bottom = TunnelBoundary::Specular, top = TunnelBoundary::Inflow;
    double wallTemperature = 300.0;                   // diffuse sides [K]
    double bottomWallSpeed = 0.0, topWallSpeed = 0.0; // tangential (+x) speed of the bottom / top side [m/s]

    // Bodies (the preset's obstacles: discs and boxes) and the piston (a specular wall moving along x)
    TunnelSurface surface = TunnelSurface::Diffuse;
    double bodyTemperature = 500.0; // diffuse bodies [K]
    double toolSpeed = 50.0;        // the fastest a dragged body or the piston moves [m/s]
    bool pistonOn = false;          // the left side is a piston at x = piston position
    double pistonSpeed = 0.0;       // the piston's drive speed [m/s]; > 0 at start drives it from t = 0

    // Sampling and view
    long long sampleStart = 200; // steps after a reset or an edit before the fields window opens
    // Steps the fields and mean forces average over, the most recent (between half and all of them) for a
    // flow that changes; 0: every step since the window opened, for a steady flow. Typical 100 for the
    // shock tube; 0 … 1e9.
    long long sampleWindow = 0;
    TunnelView view = TunnelView::Particles;

    double mass() const;          // [kg]
    static double maxParticles(); // molecules a run may hold
    static double maxCells();     // cells_x × cells_y a run may have
    // maxParticles(), or fewer where the memory this machine can give the run now ends first
    // (common/MemoryBudget.h).
    double moleculeLimit() const;
    double cellWidth() const { return boxWidth / double(cellsX); }
    double cellHeight() const { return boxHeight / double(cellsY); }
    // Cross-field checks (periodic sides in pairs, the piston with a left side that is not periodic, the
    // free-stream fill within moleculeLimit()); throws ParamError naming the key.
    void validate() const;
    // The most memory the state can come to hold, which the base checks after validate() (ModelBase.h).
    MemoryNeed memoryNeed() const;

    static const std::vector<ParamField<TunnelParams>>& fields();
    static const std::vector<ParamSpec>& describe();
};

} // namespace pl
