// Every column comes from the cell model's own observables on SPARTA's velocities, so both codes are
// measured by one formula; the collision counters come from SPARTA's stats (Natt, Ncoll, Ncollave) and
// (σ c_r)_max, which SPARTA does not print, is NaN.
#include "SpartaImport.h"

#include "SpartaDeck.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace pl::scaleout {

namespace {

// The stats row of each step.
std::map<long long, std::vector<double>> rowsByStep(const ThermoTable& stats) {
    for (const char* needed : {"Step", "Time", "Natt", "Ncoll", "Ncollave"})
        if (stats.column(needed) < 0)
            throw ImportError(std::string("log.sparta: no stats column ") + needed +
                              " (export sparta writes it)");
    std::map<long long, std::vector<double>> rows;
    for (const auto& row : stats.rows) rows[static_cast<long long>(row[0])] = row;
    return rows;
}

} // namespace

ImportedCell importSpartaRun(const std::string& dir) {
    const Preset preset = readExportedExperiment(dir, "dsmc");
    ImportedCell run;
    run.final = std::make_unique<DsmcModel>();
    DsmcModel& cell = *run.final;
    cell.reset(preset);
    const std::vector<double> origin = cell.saveState().arrays.at("origin"); // by particle, as exported
    run.series = TimeSeries(cell.seriesColumns());
    const std::vector<std::string> columns = cell.seriesColumns();
    const auto sigmaColumn =
        static_cast<std::size_t>(std::find(columns.begin(), columns.end(), "sigma_cr_max") - columns.begin());
    if (sigmaColumn == columns.size()) throw std::logic_error("the cell's series has no sigma_cr_max column");

    std::ifstream log = openRunFile(dir, kSpartaLog);
    const ThermoTable stats = readThermo(log);
    const auto rows = rowsByStep(stats);
    auto value = [&](const std::vector<double>& row, const char* name) {
        return row[static_cast<std::size_t>(stats.column(name))];
    };

    std::ifstream dump = openRunFile(dir, kSpartaDump);
    DumpReader reader(dump);
    DumpFrame frame;
    while (reader.next(frame)) {
        const auto row = rows.find(frame.step);
        if (row == rows.end()) continue; // nothing to line the velocities up with
        const std::string needed = "id vx vy vz";
        const std::size_t id = frame.column("id", needed), vx = frame.column("vx", needed),
                          vy = frame.column("vy", needed), vz = frame.column("vz", needed);
        if (frame.values.size() != origin.size())
            throw ImportError("dump, step " + std::to_string(frame.step) + ": " +
                              std::to_string(frame.values.size()) + " particles, the exported cell has " +
                              std::to_string(origin.size()));
        std::vector<double> x(origin.size()), y(origin.size()), z(origin.size());
        for (const auto& v : frame.values) {
            const auto index = static_cast<long long>(v[id]) - 1;
            if (index < 0 || index >= static_cast<long long>(origin.size()))
                throw ImportError("dump, step " + std::to_string(frame.step) + ": particle id " +
                                  std::to_string(index + 1) + " was not exported");
            x[static_cast<std::size_t>(index)] = v[vx];
            y[static_cast<std::size_t>(index)] = v[vy];
            z[static_cast<std::size_t>(index)] = v[vz];
        }
        StateRecord state;
        state.put("step", static_cast<double>(frame.step));
        state.put("time", value(row->second, "Time"));
        state.put("sigma_cr_max", 0.0); // not known: the series reads NaN (below); a state holds numbers
        state.put("remainder", 0.0);
        state.put("candidates", value(row->second, "Natt"));
        state.put("collisions_this_step", value(row->second, "Ncoll"));
        // Ncollave is the mean per step since the run began: times the steps, all collisions so far.
        const double total =
            frame.step == 0 ? 0.0
                            : std::round(value(row->second, "Ncollave") * static_cast<double>(frame.step));
        if (!std::isfinite(total) || !std::isfinite(value(row->second, "Natt")) ||
            !std::isfinite(value(row->second, "Ncoll")))
            throw ImportError("log.sparta, step " + std::to_string(frame.step) +
                              ": collision counts are not numbers");
        state.put("collisions_total", total);
        state.put("vx", x);
        state.put("vy", y);
        state.put("vz", z);
        state.put("origin", origin);
        cell.restoreState(state);
        std::vector<double> sample = cell.sampleSeries();
        sample[sigmaColumn] = std::numeric_limits<double>::quiet_NaN();
        run.series.append(sample);
        ++run.frames;
    }
    if (run.frames == 0) throw ImportError(dir + ": no dumped step matches a stats row");
    return run;
}

} // namespace pl::scaleout
