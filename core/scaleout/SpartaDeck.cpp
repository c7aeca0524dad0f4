// The SPARTA deck of the DSMC cell. SPARTA's NTC with remainders and its VSS cross-section are the
// method of DsmcModel; what differs is said in the deck's header (docs/scale-out.md).
#include "SpartaDeck.h"

#include "ExactNumber.h"

#include <cmath>
#include <numbers>
#include <sstream>

namespace pl::scaleout {

namespace {

const char* kSpecies = "gas";
const char* kSpeciesFile = "gas.species";
const char* kCollisionFile = "gas.vss";

// Deterministic, even positions in the cube (an R3 low-discrepancy sequence): in one cell positions do
// not enter the collisions, SPARTA only needs them inside the box.
double fraction(std::size_t i, double alpha) {
    const double v = 0.5 + static_cast<double>(i) * alpha;
    return v - std::floor(v);
}

std::string particleFile(const DsmcModel& cell, double side) {
    const DsmcState& s = cell.state();
    constexpr double kR3[3] = {0.8191725133961645, 0.6710436067037893, 0.5497004779019703};
    std::ostringstream out;
    out.precision(17);
    out << "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n"
        << s.size() << "\nITEM: BOX BOUNDS pp pp pp\n0 " << side << "\n0 " << side << "\n0 " << side
        << "\nITEM: ATOMS id type x y z vx vy vz\n";
    for (std::size_t i = 0; i < s.size(); ++i)
        out << i + 1 << " 1 " << fraction(i, kR3[0]) * side << ' ' << fraction(i, kR3[1]) * side << ' '
            << fraction(i, kR3[2]) * side << ' ' << s.vx[i] << ' ' << s.vy[i] << ' ' << s.vz[i] << '\n';
    return out.str();
}

std::vector<std::string> mappingNotes(const DsmcModel& cell, const VssParameters& vss) {
    const DsmcParams& p = cell.parameters();
    std::ostringstream cross;
    cross.precision(10);
    cross << "exact: the cross-section, " << crossSectionName(cell.collisionModel().kind)
          << ", as collide vss with d_ref = " << vss.diameter << " m, omega = " << vss.omega
          << ", T_ref = " << vss.tref << " K, alpha = 1";
    return {
        "exact: the " + std::to_string(cell.state().size()) + " initial velocities (" + nameOf(p.initial) +
            " start), F_N, the cell volume, dt, NTC with carried remainders (collide_modify remain yes)",
        cross.str(),
        "differs: random numbers (SPARTA's own generator), SPARTA's first (sigma c_r)_max estimate instead "
        "of sigma_cr_max_init; the molecules carry no rotational or vibrational energy (rotdof = vibdof = "
        "0), "
        "as in ParticleLab",
        "one periodic cubic grid cell of the cell's volume: positions do not enter the collisions"};
}

} // namespace

namespace {

// One mapping for both scenes: their gases have the same cross-section parameters.
VssParameters vssFor(const CollisionModel& model, double hardSphereDiameter, double vhsDiameter, double tref,
                     double mass) {
    VssParameters vss;
    vss.omega = model.omega;
    vss.tref = tref;
    if (model.kind == CollisionModel::Kind::HardSphere) {
        vss.diameter = hardSphereDiameter;
    } else if (model.kind == CollisionModel::Kind::Vhs) {
        vss.diameter = vhsDiameter;
    } else {
        // A c_r^(2−2ω) = π d² (4kT_ref/m)^(ω−½) c_r^(2−2ω) / Γ(5/2−ω), solved for d (m_r = m/2).
        const double thermal = 4.0 * kBoltzmann * tref / mass;
        vss.diameter = std::sqrt(model.prefactor * std::tgamma(2.5 - model.omega) /
                                 (std::numbers::pi * std::pow(thermal, model.omega - 0.5)));
    }
    return vss;
}

} // namespace

std::string crossSectionName(CollisionModel::Kind kind) {
    switch (kind) {
    case CollisionModel::Kind::InverseRoot:
        return "inverse-root: sigma = 1e-18 c_r^-1/2 (VHS, omega = 3/4)";
    case CollisionModel::Kind::HardSphere:
        return "hard spheres (VHS, omega = 1/2)";
    case CollisionModel::Kind::Vhs:
        return "VHS";
    case CollisionModel::Kind::Maxwell:
        return "Maxwell molecules (VHS, omega = 1)";
    }
    return "";
}

VssParameters vssParameters(const DsmcParams& params, const CollisionModel& model) {
    return vssFor(model, params.diameter, params.vhsDiameter, params.vhsTref, params.mass());
}

VssParameters vssParameters(const TunnelParams& params, const CollisionModel& model) {
    return vssFor(model, params.diameter, params.vhsDiameter, params.vhsTref, params.mass());
}

Deck spartaDeck(const DsmcModel& cell, const SpartaExportOptions& options) {
    if (options.steps < 0 || options.every < 1) throw ExportError("steps must be >= 0 and every >= 1");
    const DsmcParams& p = cell.parameters();
    if (p.planar())
        throw ExportError("velocity_components = 2 (scattering in the plane) has no SPARTA counterpart: "
                          "SPARTA scatters in 3D even in 2D simulations; use --set velocity_components=3");
    const VssParameters vss = vssParameters(p, cell.collisionModel());
    const double side = std::cbrt(p.cellVolume);
    Deck deck;
    deck.notes = mappingNotes(cell, vss);
    deck.command = std::string("spa_serial -in ") + kSpartaInput + "   (or mpirun -np N spa_mpi -in " +
                   kSpartaInput + ")";

    std::ostringstream in;
    in.precision(17);
    in << "# ParticleLab DSMC cell (" << cell.state().size() << " particles, " << p.massAmu
       << " u) as a SPARTA deck. Run: " << deck.command << "\n";
    for (const auto& note : deck.notes) in << "# " << note << "\n";
    const double massOverK = p.mass() / kBoltzmann;
    // SPARTA's seed is a positive integer below 2^31.
    in << "seed            " << cell.toPreset().seed % 2147483646 + 1 << "\n"
       << "units           si\n"
       << "dimension       3\n"
       << "boundary        p p p\n"
       << "create_box      0 " << Exact{side} << " 0 " << Exact{side} << " 0 " << Exact{side} << "\n"
       << "create_grid     1 1 1\n"
       << "global          fnum " << Exact{p.fn} << "\n"
       << "species         " << kSpeciesFile << ' ' << kSpecies << "\n"
       << "mixture         cell " << kSpecies << "\n"
       << "collide         vss cell " << kCollisionFile << "\n"
       << "collide_modify  remain yes\n"
       << "read_particles  " << kSpartaParticles << " 0\n"
       << "timestep        " << Exact{p.dt} << "\n"
       << "# temperatures about the mean velocity, as ParticleLab's Tx, Ty, Tz and T\n"
       << "compute         u reduce ave vx vy vz\n"
       << "variable        vxx particle vx*vx\n"
       << "variable        vyy particle vy*vy\n"
       << "variable        vzz particle vz*vz\n"
       << "compute         sq reduce ave v_vxx v_vyy v_vzz\n"
       << "variable        Tx equal " << Exact{massOverK} << "*(c_sq[1]-c_u[1]^2)\n"
       << "variable        Ty equal " << Exact{massOverK} << "*(c_sq[2]-c_u[2]^2)\n"
       << "variable        Tz equal " << Exact{massOverK} << "*(c_sq[3]-c_u[3]^2)\n"
       << "variable        T equal (v_Tx+v_Ty+v_Tz)/3\n"
       << "stats           " << options.every << "\n"
       << "stats_style     step time np nattempt ncoll ncollave v_Tx v_Ty v_Tz v_T c_u[1] c_u[2] c_u[3]\n"
       << "stats_modify    format float %.17g\n"
       << "dump            velocities particle cell " << options.every << ' ' << kSpartaDump
       << " id vx vy vz\n"
       << "dump_modify     velocities format float %.17g\n"
       << "run             " << options.steps << "\n";

    std::ostringstream species;
    species.precision(17);
    species << "# ParticleLab's DSMC molecules: mass only, no internal energy\n"
            << "# ID molwt mass rotdof rotrelax vibdof vibrelax vibtemp specwt charge\n"
            << kSpecies << ' ' << p.massAmu << ' ' << p.mass() << " 0 0 0 0 0 1 0\n";
    std::ostringstream collisions;
    collisions.precision(17);
    collisions << "# ID diam omega tref alpha (collide vss)\n"
               << kSpecies << ' ' << vss.diameter << ' ' << vss.omega << ' ' << vss.tref << ' ' << vss.alpha
               << "\n";

    deck.files.push_back({kSpartaInput, in.str()});
    deck.files.push_back({kSpeciesFile, species.str()});
    deck.files.push_back({kCollisionFile, collisions.str()});
    deck.files.push_back({kSpartaParticles, particleFile(cell, side)});
    deck.files.push_back({kExperimentFile, serializePreset(cell.toPreset(), DsmcParams::describe())});
    deck.files.push_back(
        {"README", "A ParticleLab DSMC cell as a SPARTA deck. SPARTA is not packaged by Debian: "
                   "build it from https://github.com/sparta/sparta (cd src && make serial) and "
                   "run\n  " +
                       deck.command + "\nin this folder.\n"});
    return deck;
}

} // namespace pl::scaleout
