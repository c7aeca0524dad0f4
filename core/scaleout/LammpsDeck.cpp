// The LAMMPS deck of a gas: every choice below keeps LAMMPS's dynamics identical to velocity Verlet in
// GasModel, up to round-off, or is refused with the reason (docs/scale-out.md).
#include "LammpsDeck.h"

#include "ExactNumber.h"
#include "common/AtomicFile.h"

#include <filesystem>
#include <numbers>
#include <sstream>

namespace pl::scaleout {

namespace {

std::string number(double value) {
    std::ostringstream out;
    out << Exact{value};
    return out.str();
}

// Refusals first: a deck that would silently run another experiment is worse than none.
void checkExportable(const GasModel& gas) {
    const GasParams& p = gas.parameters();
    const std::string& verlet = gasIntegrator(GasIntegrator::VelocityVerlet).name;
    if (p.integrator != GasIntegrator::VelocityVerlet)
        throw ExportError(
            "integrator " + nameOf(p.integrator) +
            " has no LAMMPS counterpart: fix nve is velocity Verlet; use --set integrator=" + verlet);
    if (p.dt < 0)
        throw ExportError("dt = " + number(p.dt) +
                          " runs time backwards; LAMMPS steps forward only: export with dt > 0");
    if (p.wallMode == GasWallMode::Thermal)
        throw ExportError("thermal walls (wall_mode=thermal) are not exported: Debian's LAMMPS has no "
                          "diffuse wall (fix wall/reflect/stochastic is in the EXTRA-FIX package it lacks), "
                          "and a thermostat would heat the bulk instead of the walls; use --set "
                          "wall_mode=reflecting");
    if (!gas.obstacles().empty())
        throw ExportError(std::to_string(gas.obstacles().size()) +
                          " obstacle(s) are not exported: LAMMPS reflects only at planes (fix wall/reflect); "
                          "fix wall/region pushes with a soft potential instead of mirroring at the grown "
                          "obstacle, so the run would differ. Remove the obstacles to export");
}

std::vector<std::string> mappingNotes(const GasParams& p) {
    std::vector<std::string> notes{
        "exact: positions, velocities, both species' masses and diameters, the harmonic contact "
        "F = k (d_ij - r) as gran/hooke without damping or tangential spring, reflecting walls as fix "
        "wall/reflect, velocity Verlet as fix nve, dt" +
            std::string(p.appliedGravity() != 0 ? ", gravity as fix gravity" : ""),
        "potential and total energy: LAMMPS's granular pair styles report no energy; import computes them "
        "from the dumped positions with ParticleLab's formula",
        "not in LAMMPS's output: pressure_wall (fix wall/reflect counts no impulse) and collision_rate; "
        "import writes NaN"};
    if (p.pistonEnabled)
        notes.push_back("the piston at x = " + number(p.pistonX) +
                        " is the box's right edge, a reflecting wall at rest; moving it (Compress, Expand, "
                        "dragging) has no counterpart in the deck");
    return notes;
}

std::string dataFile(const GasModel& gas, int types) {
    const GasParams& p = gas.parameters();
    const GasState& s = gas.state();
    std::ostringstream out;
    out.precision(17);
    out << "ParticleLab gas state (atom_style sphere: id type diameter density x y z)\n\n"
        << s.size() << " atoms\n"
        << types << " atom types\n\n"
        << p.left() << ' ' << p.right() << " xlo xhi\n"
        << p.bottom() << ' ' << p.top() << " ylo yhi\n"
        << "-0.5 0.5 zlo zhi\n\nAtoms # sphere\n\n";
    // LAMMPS derives the mass from diameter and density; the input script then sets it exactly.
    double density[2];
    for (int t = 0; t < 2; ++t) {
        const double r = 0.5 * p.species(t).diameter;
        density[t] = p.species(t).mass / (4.0 / 3.0 * std::numbers::pi * r * r * r);
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
        const int t = s.species[i];
        out << s.id[i] + 1 << ' ' << t + 1 << ' ' << p.species(t).diameter << ' ' << density[t] << ' '
            << s.x[i] << ' ' << s.y[i] << " 0\n";
    }
    out << "\nVelocities\n\n";
    for (std::size_t i = 0; i < s.size(); ++i)
        out << s.id[i] + 1 << ' ' << s.vx[i] << ' ' << s.vy[i] << " 0 0 0 0\n";
    return out.str();
}

std::string inputScript(const GasModel& gas, int types, const std::vector<std::string>& notes,
                        const std::string& command, const LammpsExportOptions& options) {
    const GasParams& p = gas.parameters();
    std::ostringstream in;
    in.precision(17);
    in << "# ParticleLab gas (" << gas.state().size() << " disks, seed " << gas.toPreset().seed
       << ") as a LAMMPS deck. Run: " << command << "\n";
    for (const auto& note : notes) in << "# " << note << "\n";
    in << "units           lj\n"
          "dimension       2\n"
          "boundary        f f p\n"
          "atom_style      sphere\n"
          "comm_modify     vel yes\n"
       << "read_data       " << kLammpsData << "\n";
    for (int t = 0; t < types; ++t)
        in << "set             type " << t + 1 << " mass " << Exact{p.species(t).mass} << "\n";
    in << "# gran/hooke Kn Kt gamma_n gamma_t xmu dampflag: F = Kn (r_i + r_j - r), nothing else\n"
       << "pair_style      gran/hooke " << Exact{p.stiffness} << " 0.0 0.0 0.0 0.0 0\n"
       << "pair_coeff      * *\n"
       << "neighbor        " << Exact{0.5 * p.maxDiameter()} << " bin\n"
       << "neigh_modify    every 1 delay 0 check yes\n"
       << "fix             integrate all nve\n"
       << "fix             walls all wall/reflect xlo EDGE xhi EDGE ylo EDGE yhi EDGE\n";
    if (p.appliedGravity() != 0)
        in << "fix             fall all gravity " << Exact{p.appliedGravity()} << " vector 0 -1 0\n";
    in << "fix             plane all enforce2d\n"
       << "timestep        " << Exact{p.dt} << "\n"
       << "# kT = kinetic energy per disk, as ParticleLab counts it (2 degrees of freedom, none removed)\n"
       << "compute_modify  thermo_temp extra/dof 0\n";
    std::string speciesColumns;
    for (int t = 0; t < types; ++t) {
        if (p.species(t).count == 0) continue; // an absent species has no kT: NaN, as in `run`
        const std::string name = t == 0 ? "a" : "b";
        in << "group           species_" << name << " type " << t + 1 << "\n"
           << "compute         kT_" << name << " species_" << name << " temp\n"
           << "compute_modify  kT_" << name << " extra/dof 0\n";
        speciesColumns += " c_kT_" + name;
    }
    in << "variable        px equal mass(all)*vcm(all,x)\n"
       << "variable        py equal mass(all)*vcm(all,y)\n"
       << "thermo_style    custom step time atoms ke temp press" << speciesColumns << " v_px v_py\n"
       << "thermo_modify   norm no format float %.17g\n"
       << "thermo          " << options.every << "\n"
       << "dump            particles all custom " << options.every << ' ' << kLammpsDump
       << " id type x y vx vy\n"
       << "dump_modify     particles format float %.17g sort id\n"
       << "run             " << options.steps << "\n";
    return in.str();
}

} // namespace

LammpsExportOptions defaultLammpsOptions(const GasModel& gas) {
    constexpr long long kOpenEndedSteps = 1000, kOpenEndedEvery = 100;
    const long long planned = gas.plannedSteps();
    LammpsExportOptions options;
    options.steps = planned > 0 ? planned : kOpenEndedSteps;
    options.every = planned > 0 ? 1 : kOpenEndedEvery;
    return options;
}

std::unique_ptr<GasModel> gasToExport(const Model& model) {
    if (model.kind() != "gas")
        throw ExportError("only the gas exports to LAMMPS, not a " + model.kind() +
                          " experiment (the DSMC cell exports to SPARTA)");
    auto gas = std::make_unique<GasModel>();
    gas->reset(model.toPreset());
    gas->restoreState(model.saveState()); // a GPU model hands its particles over here
    return gas;
}

Deck lammpsDeck(const GasModel& gas, const LammpsExportOptions& options) {
    if (options.steps < 0 || options.every < 1) throw ExportError("steps must be >= 0 and every >= 1");
    checkExportable(gas);
    const GasParams& p = gas.parameters();
    const int types = p.b.count > 0 ? 2 : 1;
    Deck deck;
    deck.notes = mappingNotes(p);
    deck.command = std::string("mpirun -np 2 lmp -in ") + kLammpsInput;
    deck.files.push_back({kLammpsInput, inputScript(gas, types, deck.notes, deck.command, options)});
    deck.files.push_back({kLammpsData, dataFile(gas, types)});
    deck.files.push_back({kExperimentFile, serializePreset(gas.toPreset(), GasParams::describe())});
    deck.files.push_back(
        {"README", "A ParticleLab gas as a LAMMPS deck. Run it here with\n  " + deck.command +
                       "\n(Debian: apt install lammps openmpi-bin) and read the run back with\n"
                       "  particlelab-cli import lammps . --out series.csv --histogram hist.csv\n" +
                       std::string(kExperimentFile) +
                       " is the exported experiment: import needs it for masses, diameters and k.\n"});
    return deck;
}

void writeDeck(const Deck& deck, const std::string& dir) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) throw FileError("cannot create " + dir + ": " + error.message());
    for (const auto& file : deck.files)
        writeFileAtomically((std::filesystem::path(dir) / file.name).string(), file.content);
}

} // namespace pl::scaleout
