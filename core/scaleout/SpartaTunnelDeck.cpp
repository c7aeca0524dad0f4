// The SPARTA deck of the wind tunnel: the same 2D box, grid, gas, free stream, sides and bodies, with
// SPARTA's grid fields and body forces written where the CLI's --fields and --surface can be set
// against them (bench/compare_sparta_tunnel.sh; docs/scale-out.md).
#include "ExactNumber.h"
#include "SpartaDeck.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string_view>

namespace pl::scaleout {

namespace {

const char* kSpecies = "gas";
const char* kSpeciesFile = "gas.species";
const char* kCollisionFile = "gas.vss";
const char* kStream = "stream"; // the free-stream mixture: inflow and the initial gas
const char* kRest = "rest";     // the same gas at rest, for initial = rest

struct Point {
    double x, y;
};

// One letter of SPARTA's boundary command per side: inflow sides are outflow faces that fix emit/face
// feeds, diffuse sides are surfaces ("s") with their own surf_collide.
char boundaryLetter(TunnelBoundary side) {
    switch (side) {
    case TunnelBoundary::Inflow:
    case TunnelBoundary::Outflow:
        return 'o';
    case TunnelBoundary::Specular:
        return 'r';
    case TunnelBoundary::Diffuse:
        return 's';
    case TunnelBoundary::Periodic:
        return 'p';
    }
    return 'o';
}

std::string boundaryPair(TunnelBoundary low, TunnelBoundary high) {
    const char a = boundaryLetter(low), b = boundaryLetter(high);
    return a == b ? std::string(1, a) : std::string{a, b};
}

// The outline of a body in clockwise order: SPARTA's outward normal of a segment p1 → p2 is
// ẑ × (p2 − p1) (read_surf), which points out of a body traversed clockwise.
std::vector<Point> outline(const Obstacle& body, const TunnelParams& params) {
    std::vector<Point> points;
    if (body.shape == Obstacle::Shape::Box) {
        const double w = body.halfWidth, h = body.halfHeight;
        points = {{body.x - w, body.y - h},
                  {body.x - w, body.y + h},
                  {body.x + w, body.y + h},
                  {body.x + w, body.y - h}};
        return points;
    }
    const int sides = discPolygonSides(body.radius, params);
    for (int k = 0; k < sides; ++k) {
        const double angle = -2.0 * std::numbers::pi * k / sides;
        points.push_back({body.x + body.radius * std::cos(angle), body.y + body.radius * std::sin(angle)});
    }
    return points;
}

// read_surf's file: a skipped title line, the counts, then Points and Lines (format A: id p1 p2).
// Each body is one closed loop, so the set is watertight as read_surf requires.
std::string surfaceFile(const std::vector<std::vector<Point>>& bodies) {
    std::size_t total = 0;
    for (const auto& b : bodies) total += b.size();
    std::ostringstream out;
    out.precision(17);
    out << "ParticleLab tunnel bodies as closed clockwise polygons\n\n"
        << total << " points\n"
        << total << " lines\n\nPoints\n\n";
    std::size_t id = 1;
    for (const auto& b : bodies)
        for (const auto& p : b) out << id++ << ' ' << Exact{p.x} << ' ' << Exact{p.y} << '\n';
    out << "\nLines\n\n";
    std::size_t first = 1, line = 1;
    for (const auto& b : bodies) {
        for (std::size_t k = 0; k < b.size(); ++k)
            out << line++ << ' ' << first + k << ' ' << first + (k + 1) % b.size() << '\n';
        first += b.size();
    }
    return out.str();
}

bool reachesOutside(const std::vector<std::vector<Point>>& bodies, const SamplingGrid& box) {
    for (const auto& b : bodies)
        for (const auto& p : b)
            if (p.x < box.left || p.x > box.right || p.y < box.bottom || p.y > box.top) return true;
    return false;
}

std::vector<std::string> mappingNotes(const TunnelModel& tunnel, const VssParameters& vss, bool clipped) {
    const TunnelParams& p = tunnel.parameters();
    std::ostringstream cross;
    cross.precision(10);
    cross << "exact: the cross-section, " << crossSectionName(tunnel.collisionModel().kind)
          << ", as collide vss with d_ref = " << vss.diameter << " m, omega = " << vss.omega
          << ", T_ref = " << vss.tref << " K, alpha = 1";
    std::vector<std::string> notes{
        "exact: the box, the " + std::to_string(p.cellsX) + " x " + std::to_string(p.cellsY) +
            " grid, F_N (per m of depth: SPARTA's 2D cells have unit depth), dt, the free stream through "
            "fix emit/face (Bird 1994 eq. 4.22, as ours), NTC with carried remainders",
        cross.str(),
        "exact: the sides (inflow and outflow as o, specular as r, diffuse as s with surf_collide diffuse "
        "at wall_temperature and the wall speed as translate, periodic as p)",
        "exact: bodies at rest where they are, " + nameOf(p.surface) +
            " surfaces; discs as inscribed polygons of at least 64 sides (area short by 2 pi^2/(3 N^2))" +
            (clipped ? ", clipped to the box (read_surf clip)" : ""),
        "differs: random numbers; SPARTA draws its own initial gas (" + nameOf(p.initial) +
            ") instead of taking our particles; SPARTA estimates its own first (sigma c_r)_max per cell; "
            "SPARTA splits the cells a body cuts and collides in each part; molecules carry no internal "
            "energy in either code",
        "outputs: stats every row with the force on the bodies averaged since the last row [N/m]; " +
            std::string(kSpartaGrid) + " with the grid fields averaged from step " +
            std::to_string(p.sampleStart) + " to the end"};
    return notes;
}

} // namespace

int discPolygonSides(double radius, const TunnelParams& params) {
    const double segment = 0.25 * std::min(params.cellWidth(), params.cellHeight());
    const double wanted = std::ceil(2.0 * std::numbers::pi * radius / segment);
    return static_cast<int>(std::clamp(wanted, 64.0, 4096.0));
}

Deck spartaDeck(const TunnelModel& tunnel, const SpartaExportOptions& options) {
    if (options.steps < 1 || options.every < 1) throw ExportError("steps and every must be >= 1");
    const TunnelParams& p = tunnel.parameters();
    if (p.pistonOn)
        throw ExportError("piston_on has no SPARTA counterpart: SPARTA's box boundaries do not move (its "
                          "surf_collide piston is a pressure condition); use --set piston_on=false");
    if (options.steps <= p.sampleStart)
        throw ExportError("the run of " + std::to_string(options.steps) +
                          " steps ends before the fields window opens at sample_start = " +
                          std::to_string(p.sampleStart) + "; use more --steps or a smaller sample_start");
    // SPARTA prints a stats row at the end of the run, and the force averages exist only every `every`.
    if (!tunnel.obstacles().empty() && options.steps % options.every != 0)
        throw ExportError("the force on the bodies is written every " + std::to_string(options.every) +
                          " steps, so the run's " + std::to_string(options.steps) +
                          " steps must be a multiple of it; choose --steps and --every to fit");
    const SamplingGrid& box = tunnel.sampler().grid();
    std::vector<std::vector<Point>> bodies;
    for (const auto& body : tunnel.obstacles()) bodies.push_back(outline(body, p));
    const bool clipped = reachesOutside(bodies, box);
    const VssParameters vss = vssParameters(p, tunnel.collisionModel());
    const long long window = options.steps - p.sampleStart;

    Deck deck;
    deck.notes = mappingNotes(tunnel, vss, clipped);
    deck.command = std::string("spa_serial -in ") + kSpartaInput + "   (or mpirun -np N spa_mpi -in " +
                   kSpartaInput + ")";
    std::ostringstream in;
    in << "# ParticleLab wind tunnel (" << tunnel.obstacles().size() << " bodies, " << p.massAmu
       << " u) as a 2D SPARTA deck. Run: " << deck.command << "\n";
    for (const auto& note : deck.notes) in << "# " << note << "\n";
    // SPARTA's seed is a positive integer below 2^31.
    in << "seed            " << tunnel.toPreset().seed % 2147483646 + 1 << "\n"
       << "units           si\n"
       << "dimension       2\n"
       << "boundary        " << boundaryPair(p.left, p.right) << ' ' << boundaryPair(p.bottom, p.top)
       << " p\n"
       << "create_box      " << Exact{box.left} << ' ' << Exact{box.right} << ' ' << Exact{box.bottom} << ' '
       << Exact{box.top} << " -0.5 0.5\n"
       << "create_grid     " << p.cellsX << ' ' << p.cellsY << " 1\n"
       << "global          nrho " << Exact{p.streamDensity} << " fnum " << Exact{p.fn} << "\n"
       << "species         " << kSpeciesFile << ' ' << kSpecies << "\n"
       << "mixture         " << kStream << ' ' << kSpecies << " vstream " << Exact{p.streamSpeed}
       << " 0 0 temp " << Exact{p.streamTemperature} << "\n"
       << "collide         vss " << kStream << ' ' << kCollisionFile << "\n"
       << "collide_modify  remain yes\n";

    // Diffuse sides: one wall model per side, moving along x at its wall speed (Couette).
    const std::pair<const char*, TunnelBoundary> sides[] = {
        {"xlo", p.left}, {"xhi", p.right}, {"ylo", p.bottom}, {"yhi", p.top}};
    for (const auto& [face, side] : sides) {
        if (side != TunnelBoundary::Diffuse) continue;
        const std::string_view name(face);
        const double speed = name == "ylo" ? p.bottomWallSpeed : name == "yhi" ? p.topWallSpeed : 0.0;
        in << "surf_collide    wall_" << face << " diffuse " << Exact{p.wallTemperature} << " 1.0";
        if (speed != 0.0) in << " translate " << Exact{speed} << " 0 0";
        in << "\nbound_modify    " << face << " collide wall_" << face << "\n";
    }
    if (!bodies.empty()) {
        in << "read_surf       " << kSpartaBodies << (clipped ? " clip" : "") << "\n";
        if (p.surface == TunnelSurface::Diffuse)
            in << "surf_collide    body diffuse " << Exact{p.bodyTemperature} << " 1.0\n";
        else
            in << "surf_collide    body specular\n";
        in << "surf_modify     all collide body\n";
    }
    if (p.initial == TunnelInitial::Stream) {
        in << "create_particles " << kStream << " n 0\n";
    } else if (p.initial == TunnelInitial::Rest) {
        in << "mixture         " << kStream << " copy " << kRest << "\n"
           << "mixture         " << kRest << " vstream 0 0 0\n"
           << "create_particles " << kRest << " n 0\n";
    }
    std::string inflow;
    for (const auto& [face, side] : sides)
        if (side == TunnelBoundary::Inflow) inflow += std::string(" ") + face;
    if (!inflow.empty()) in << "fix             inflow emit/face " << kStream << inflow << "\n";
    in << "timestep        " << Exact{p.dt} << "\n"
       << "# grid fields: count, n, velocity and mean squares (T_x = m/k (<vx^2> - u^2) etc.), averaged over "
          "the window\n"
       << "compute         cells grid all " << kStream << " n nrho u v w usq vsq wsq\n"
       << "fix             fields ave/grid all 1 " << window << ' ' << options.steps << " c_cells[*]\n"
       << "dump            fields grid all " << options.steps << ' ' << kSpartaGrid
       << " id xlo ylo xhi yhi vol f_fields[*]\n"
       << "dump_modify     fields format float %.10g\n";
    std::string forceColumns;
    if (!bodies.empty()) {
        in << "# drag and lift per unit depth: the force on all bodies, averaged over each stats interval\n"
           << "compute         surfaceForce surf all " << kStream << " fx fy\n"
           << "fix             surfaceForce ave/surf all 1 " << options.every << ' ' << options.every
           << " c_surfaceForce[*]\n"
           << "compute         force reduce sum f_surfaceForce[1] f_surfaceForce[2]\n";
        forceColumns = " c_force[1] c_force[2]";
    }
    in << "stats           " << options.every << "\n"
       << "stats_style     step elapsed cpu np nattempt ncoll nscoll" << forceColumns << "\n"
       << "stats_modify    format float %.10g\n"
       << "run             " << options.steps << "\n";

    std::ostringstream species;
    species.precision(17);
    species << "# ParticleLab's tunnel molecules: mass only, no internal energy\n"
            << "# ID molwt mass rotdof rotrelax vibdof vibrelax vibtemp specwt charge\n"
            << kSpecies << ' ' << p.massAmu << ' ' << p.mass() << " 0 0 0 0 0 1 0\n";
    std::ostringstream collisions;
    collisions << "# ID diam omega tref alpha (collide vss)\n"
               << kSpecies << ' ' << Exact{vss.diameter} << ' ' << Exact{vss.omega} << ' ' << Exact{vss.tref}
               << ' ' << Exact{vss.alpha} << "\n";

    deck.files.push_back({kSpartaInput, in.str()});
    deck.files.push_back({kSpeciesFile, species.str()});
    deck.files.push_back({kCollisionFile, collisions.str()});
    if (!bodies.empty()) deck.files.push_back({kSpartaBodies, surfaceFile(bodies)});
    deck.files.push_back({kExperimentFile, serializePreset(tunnel.toPreset(), TunnelParams::describe())});
    deck.files.push_back(
        {"README", "A ParticleLab wind tunnel as a 2D SPARTA deck. SPARTA is not packaged by Debian: "
                   "build it from https://github.com/sparta/sparta (cd src && make serial) and run\n  " +
                       deck.command + "\nin this folder. " + kSpartaGrid +
                       " holds the grid fields, log.sparta the force on the bodies per stats row.\n"});
    return deck;
}

} // namespace pl::scaleout
