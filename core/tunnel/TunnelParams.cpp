// The wind tunnel's parameter table: units, ranges, tooltips, which values act at once, and the
// cross-field checks.
#include "TunnelParams.h"
#include "common/MemoryBudget.h"
#include "dsmc/MolecularParams.h"

#include <algorithm>
#include <cmath>

#include <string>
#include <tuple>

namespace pl {

namespace {
constexpr double kMaxCells = 1 << 22; // 4 M cells: the per-cell arrays stay below ~500 MB
// State, cell order and sort scratch (measured: 67–70 B a molecule from 0.05 M to 4.7 M molecules).
constexpr double kBytesPerMolecule = 72.0;
// NTC state, open fractions, the sampler's sums (measured: about 100 B a cell from 40 k to 640 k cells).
constexpr double kBytesPerCell = 128.0;
constexpr double kBytesPerOlderHalf = 56.0; // a moving window's older half: seven sums a cell

double bytesPerCell(const TunnelParams& p) {
    return kBytesPerCell + (p.sampleWindow > 0 ? kBytesPerOlderHalf : 0.0);
}
} // namespace

double TunnelParams::maxCells() {
    return kMaxCells;
}

double TunnelParams::maxParticles() {
    return 1 << 26; // 67 M molecules: 44 bytes each, 3 GB
}

double TunnelParams::moleculeLimit() const {
    const double cells = static_cast<double>(cellsX) * static_cast<double>(cellsY);
    const double room =
        (kUsableMemoryShare * availableMemoryBytes() - cells * bytesPerCell(*this)) / kBytesPerMolecule;
    return std::max(0.0, std::min(maxParticles(), std::floor(room)));
}

double TunnelParams::mass() const {
    return massAmu * kAtomicMass;
}

// The grid's cells; the molecules' memory is validate()'s molecule limit (moleculeLimit()).
MemoryNeed TunnelParams::memoryNeed() const {
    const double cells = static_cast<double>(cellsX) * static_cast<double>(cellsY);
    const double perCell = bytesPerCell(*this);
    return {cells * perCell, "cells_x", [perCell](double fitting) {
                return "use at most " + formatNumber(fitting / perCell, 3) + " cells ({cells_x} × {cells_y})";
            }};
}

void TunnelParams::validate() const {
    if (static_cast<double>(cellsX) * static_cast<double>(cellsY) > kMaxCells)
        throw ParamError("cells_x", "{cells_x} × {cells_y} = " + std::to_string(cellsX * cellsY) +
                                        " cells exceed the limit of " +
                                        std::to_string(static_cast<long long>(kMaxCells)));
    // The free stream filling the whole domain must fit (the count settles near it in a tunnel).
    const double fill = streamDensity * boxWidth * boxHeight / fn;
    const double limit = moleculeLimit();
    if (!(fill <= limit))
        throw ParamError(
            "fn",
            "the free stream fills the domain with " + formatNumber(fill, 3) + " molecules, more than " +
                (limit < maxParticles() ? "the " + formatNumber(limit, 3) + " this machine's memory holds now"
                                        : "the limit of " + formatNumber(limit, 3)) +
                "; raise {fn} to at least " +
                formatNumber(streamDensity * boxWidth * boxHeight / std::max(limit, 1.0), 3));
    // A periodic side hands its particles to the opposite side, which must then take them in.
    if ((left == TunnelBoundary::Periodic) != (right == TunnelBoundary::Periodic))
        throw ParamError(left == TunnelBoundary::Periodic ? "right" : "left",
                         "{left} and {right} must both be periodic or neither");
    if ((bottom == TunnelBoundary::Periodic) != (top == TunnelBoundary::Periodic))
        throw ParamError(bottom == TunnelBoundary::Periodic ? "top" : "bottom",
                         "{bottom} and {top} must both be periodic or neither");
    if (pistonOn && left == TunnelBoundary::Periodic)
        throw ParamError("piston_on", "the piston replaces the left side, which is periodic; make {left} "
                                      "and {right} non-periodic or switch {piston_on} off");
}

const std::vector<ParamField<TunnelParams>>& TunnelParams::fields() {
    using P = TunnelParams;
    static const std::vector<ParamField<P>> list = [] {
        const P d;
        std::vector<ParamField<P>> f;
        const std::string domain = "Domain and method", gas = "Gas", stream = "Free stream", sides = "Sides",
                          bodies = "Bodies and piston", sampling = "Sampling and view";
        f.push_back(bindReal(&P::boxWidth, makeSpec("box_width", "Width", "m", domain,
                                                    "Length of the domain along the stream (x).", 1e-9, 1e3,
                                                    0.01, d.boxWidth)));
        f.push_back(bindReal(&P::boxHeight, makeSpec("box_height", "Height", "m", domain,
                                                     "Height of the domain (y); the depth is 1 m.", 1e-9, 1e3,
                                                     0.01, d.boxHeight)));
        f.push_back(bindInteger(&P::cellsX, makeSpec("cells_x", "Cells along x", "", domain,
                                                     "Collision and sampling cells along x; Bird's "
                                                     "guideline is a cell width below λ/2.",
                                                     1, 1 << 16, 10, double(d.cellsX))));
        f.push_back(bindInteger(&P::cellsY, makeSpec("cells_y", "Cells along y", "", domain,
                                                     "Collision and sampling cells along y.", 1, 1 << 16, 10,
                                                     double(d.cellsY))));
        f.push_back(bindReal(&P::fn, makeSpec("fn", "Particle weight F_N", "", domain,
                                              "Real molecules (per m of depth) each simulated particle "
                                              "stands for; aim for ≥ 5 particles per free-stream cell.",
                                              1e-6, 1e30, 0, d.fn)));
        f.push_back(bindReal(&P::dt, makeSpec("dt", "Time step", "s", domain,
                                              "Keep it below a quarter of the mean collision time and "
                                              "the stream's cell transit time.",
                                              1e-15, 1e3, 0, d.dt, true)));
        f.push_back(bindInteger(&P::runSteps, makeSpec("run_steps", "Run length", "steps", domain,
                                                       "The run stops after this many steps; 0 runs on.", 0,
                                                       1e12, 100, double(d.runSteps), true)));
        // The molecule: the DSMC cell's table (MolecularParams.h), in one section; the defaults are argon.
        const MolecularParamsText molecule{.massGroup = gas, .collisionGroup = gas, .gas = "argon"};
        f.push_back(molecularMassField<P>(molecule));
        for (auto& field : crossSectionFields<P>(molecule)) f.push_back(std::move(field));
        f.push_back(bindReal(&P::streamDensity, makeSpec("stream_density", "Number density", "m⁻³", stream,
                                                         "Number density of the free stream.", 1e3, 1e32, 0,
                                                         d.streamDensity, true)));
        f.push_back(bindReal(&P::streamSpeed, makeSpec("stream_speed", "Stream speed", "m/s", stream,
                                                       "Velocity of the free stream along +x.", -1e6, 1e6, 10,
                                                       d.streamSpeed, true)));
        f.push_back(bindReal(&P::streamTemperature, makeSpec("stream_temperature", "Stream temperature", "K",
                                                             stream, "Temperature of the free stream.", 1e-3,
                                                             1e6, 10, d.streamTemperature, true)));
        f.push_back(bindChoice(&P::initial, makeChoice("initial", "Initial gas", stream,
                                                       "empty: vacuum; stream: the free stream everywhere; "
                                                       "rest: the free-stream gas at rest.")));
        for (auto [member, key, label] :
             {std::tuple{&P::left, "left", "Left side"}, std::tuple{&P::right, "right", "Right side"},
              std::tuple{&P::bottom, "bottom", "Bottom side"}, std::tuple{&P::top, "top", "Top side"}})
            f.push_back(bindChoice(member, makeChoice(key, label, sides,
                                                      "inflow: the free stream enters; outflow: vacuum; "
                                                      "specular: a mirror; diffuse: a wall at the wall "
                                                      "temperature; periodic: wraps to the opposite side.",
                                                      true)));
        f.push_back(bindReal(&P::wallTemperature, makeSpec("wall_temperature", "Wall temperature", "K", sides,
                                                           "Temperature of the diffuse sides.", 1e-3, 1e6, 10,
                                                           d.wallTemperature, true)));
        f.push_back(
            bindReal(&P::bottomWallSpeed, makeSpec("bottom_wall_speed", "Bottom wall speed", "m/s", sides,
                                                   "Speed along +x of a diffuse bottom side (Couette flow).",
                                                   -1e6, 1e6, 10, d.bottomWallSpeed, true)));
        f.push_back(bindReal(&P::topWallSpeed, makeSpec("top_wall_speed", "Top wall speed", "m/s", sides,
                                                        "Speed along +x of a diffuse top side.", -1e6, 1e6,
                                                        10, d.topWallSpeed, true)));
        f.push_back(bindChoice(&P::surface, makeChoice("surface", "Body surface", bodies,
                                                       "diffuse: molecules leave at the body temperature; "
                                                       "specular: they are mirrored.",
                                                       true)));
        f.push_back(bindReal(&P::bodyTemperature, makeSpec("body_temperature", "Body temperature", "K",
                                                           bodies, "Temperature of diffuse bodies.", 1e-3,
                                                           1e6, 10, d.bodyTemperature, true)));
        f.push_back(bindReal(&P::toolSpeed, makeSpec("tool_speed", "Tool speed", "m/s", bodies,
                                                     "Fastest a dragged body or the piston moves.", 1e-6, 1e5,
                                                     10, d.toolSpeed, true)));
        f.push_back(bindBool(&P::pistonOn, makeSpec("piston_on", "Piston", "", bodies,
                                                    "The left side becomes a specular piston that can be "
                                                    "driven to the right (a shock tube).",
                                                    0, 0, 0, d.pistonOn)));
        f.push_back(bindReal(&P::pistonSpeed, makeSpec("piston_speed", "Piston speed", "m/s", bodies,
                                                       "Speed of the driven piston; > 0 at the start drives "
                                                       "it into the gas from t = 0.",
                                                       0, 1e5, 10, d.pistonSpeed, true)));
        f.push_back(bindInteger(&P::sampleStart,
                                makeSpec("sample_start", "Sampling starts after", "steps", sampling,
                                         "Steps after a reset or an edit before the fields are averaged.", 0,
                                         1e9, 50, double(d.sampleStart), true)));
        f.push_back(bindInteger(
            &P::sampleWindow, makeSpec("sample_window", "Sampling window", "steps", sampling,
                                       "The fields and mean forces show the most recent steps only (between "
                                       "half and all of this many), so a moving shock shows where it is; 0: "
                                       "every step since sampling started, for a steady flow.",
                                       0, 1e9, 50, double(d.sampleWindow), true)));
        f.push_back(bindChoice(&P::view, makeChoice("view", "View", sampling,
                                                    "particles, or a sampled field as a colour map.", true)));
        return f;
    }();
    return list;
}

const ChoiceTable<TunnelBoundary>& choiceTable(TunnelBoundary) {
    static const ChoiceTable<TunnelBoundary> table{{TunnelBoundary::Inflow, "inflow"},
                                                   {TunnelBoundary::Outflow, "outflow"},
                                                   {TunnelBoundary::Specular, "specular"},
                                                   {TunnelBoundary::Diffuse, "diffuse"},
                                                   {TunnelBoundary::Periodic, "periodic"}};
    return table;
}

const ChoiceTable<TunnelSurface>& choiceTable(TunnelSurface) {
    static const ChoiceTable<TunnelSurface> table{{TunnelSurface::Diffuse, "diffuse"},
                                                  {TunnelSurface::Specular, "specular"}};
    return table;
}

const ChoiceTable<TunnelInitial>& choiceTable(TunnelInitial) {
    static const ChoiceTable<TunnelInitial> table{
        {TunnelInitial::Empty, "empty"}, {TunnelInitial::Stream, "stream"}, {TunnelInitial::Rest, "rest"}};
    return table;
}

const ChoiceTable<TunnelView>& choiceTable(TunnelView) {
    static const ChoiceTable<TunnelView> table{{TunnelView::Particles, "particles"},
                                               {TunnelView::Density, "density"},
                                               {TunnelView::Speed, "speed"},
                                               {TunnelView::Temperature, "temperature"},
                                               {TunnelView::Mach, "mach"}};
    return table;
}

const std::vector<ParamSpec>& TunnelParams::describe() {
    static const std::vector<ParamSpec> list = specsOf(fields());
    return list;
}

} // namespace pl
