// LAMMPS's thermo columns map one to one onto ours where it computes them (kinetic energy, kT overall
// and per species, momentum, virial pressure); the rest comes from the dumped state through the gas
// model's own observables, so both codes are measured by one formula (docs/scale-out.md).
#include "LammpsImport.h"

#include "LammpsDeck.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

namespace pl::scaleout {

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// What the dumped state gives that the thermo table does not.
struct FrameObservables {
    double potential, ksA, ksB;
};

// The gas's disks of a dump snapshot, in atom-id order.
std::vector<GasParticle> disksOf(const DumpFrame& frame) {
    const std::string needed = "id type x y vx vy";
    const std::size_t id = frame.column("id", needed), type = frame.column("type", needed),
                      x = frame.column("x", needed), y = frame.column("y", needed),
                      vx = frame.column("vx", needed), vy = frame.column("vy", needed);
    std::vector<std::pair<double, GasParticle>> atoms;
    atoms.reserve(frame.values.size());
    for (const auto& v : frame.values) {
        const int species = static_cast<int>(v[type]) - 1;
        if (species != 0 && species != 1)
            throw ImportError("dump, step " + std::to_string(frame.step) + ": atom types must be 1 or 2");
        atoms.push_back({v[id], {v[x], v[y], v[vx], v[vy], species}});
    }
    std::sort(atoms.begin(), atoms.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<GasParticle> disks;
    disks.reserve(atoms.size());
    for (const auto& a : atoms) disks.push_back(a.second);
    return disks;
}

} // namespace

ImportedRun importLammpsRun(const std::string& dir) {
    const Preset preset = readExportedExperiment(dir, "gas");
    ImportedRun run;
    run.final = std::make_unique<GasModel>();
    GasModel& gas = *run.final;
    gas.reset(preset);

    std::map<long long, FrameObservables> frames;
    {
        std::ifstream dump = openRunFile(dir, kLammpsDump);
        DumpReader reader(dump);
        DumpFrame frame;
        while (reader.next(frame)) {
            gas.placeParticles(disksOf(frame));
            const GasObservables o = gas.observe();
            frames[frame.step] = {o.potential, o.ksDistance[0], o.ksDistance[1]};
            ++run.frames;
        }
    }
    std::ifstream log = openRunFile(dir, kLammpsLog);
    const ThermoTable thermo = readThermo(log);
    auto value = [&](const std::vector<double>& row, const char* name) {
        const int c = thermo.column(name);
        return c < 0 ? kNaN : row[static_cast<std::size_t>(c)];
    };
    const GasParams& p = gas.parameters();
    const double area = (p.right() - p.left()) * p.boxHeight;
    const auto columns = gas.seriesColumns();
    run.series = TimeSeries(columns);
    double firstTotal = kNaN;
    for (const auto& row : thermo.rows) {
        std::map<std::string, double> v;
        v["step"] = value(row, "Step");
        v["time"] = value(row, "Time");
        v["particles"] = value(row, "Atoms");
        v["kinetic"] = value(row, "KinEng");
        v["kT"] = value(row, "Temp");
        v["kT_a"] = value(row, "c_kT_a");
        v["kT_b"] = value(row, "c_kT_b");
        v["px"] = value(row, "v_px");
        v["py"] = value(row, "v_py");
        v["pressure_virial"] = value(row, "Press");
        v["pressure_ideal"] = v["particles"] * v["kT"] / area;
        const auto frame = frames.find(static_cast<long long>(v["step"]));
        const bool dumped = frame != frames.end();
        v["potential"] = dumped ? frame->second.potential : kNaN;
        v["total"] = v["kinetic"] + v["potential"];
        v["ks_a"] = dumped ? frame->second.ksA : kNaN;
        v["ks_b"] = dumped ? frame->second.ksB : kNaN;
        if (std::isnan(firstTotal)) firstTotal = v["total"];
        v["energy_drift"] = std::abs(v["total"] - firstTotal) / std::abs(firstTotal);
        std::vector<double> out;
        for (const auto& c : columns) out.push_back(v.count(c) ? v[c] : kNaN);
        run.series.append(std::move(out));
    }
    return run;
}

} // namespace pl::scaleout
