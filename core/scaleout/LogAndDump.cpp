// Readers of LAMMPS's and SPARTA's log tables and text dumps (both codes write the same layout).
#include "LogAndDump.h"

#include "LammpsDeck.h"
#include "catalog/ModelCatalog.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace pl::scaleout {

namespace {

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

bool parseNumbers(const std::vector<std::string>& tokens, std::vector<double>& values) {
    values.clear();
    for (const auto& t : tokens) {
        char* end = nullptr;
        const double v = std::strtod(t.c_str(), &end);
        if (end == t.c_str() || *end != '\0') return false;
        values.push_back(v);
    }
    return true;
}

} // namespace

int ThermoTable::column(const std::string& name) const {
    const auto it = std::find(columns.begin(), columns.end(), name);
    return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
}

ThermoTable readThermo(std::istream& log) {
    ThermoTable table;
    bool inBlock = false;
    std::vector<double> values;
    for (std::string line; std::getline(log, line);) {
        const auto tokens = words(line);
        if (tokens.empty()) continue;
        if (tokens[0] == "Step") {
            if (!table.columns.empty() && tokens != table.columns)
                throw ImportError("log: thermo columns change between runs: " + line);
            table.columns = tokens;
            inBlock = true;
        } else if (tokens[0] == "Loop") {
            inBlock = false;
        } else if (inBlock && tokens.size() == table.columns.size() && parseNumbers(tokens, values)) {
            if (table.rows.empty() || values[0] > table.rows.back()[0]) table.rows.push_back(values);
        }
    }
    if (table.rows.empty()) throw ImportError("log: no thermo output found");
    return table;
}

std::size_t DumpFrame::column(const std::string& name, const std::string& needed) const {
    const auto it = std::find(columns.begin(), columns.end(), name);
    if (it == columns.end()) throw ImportError("dump: no column " + name + " (needs " + needed + ")");
    return static_cast<std::size_t>(it - columns.begin());
}

bool DumpReader::next(DumpFrame& frame) {
    std::string line;
    auto read = [&](const std::string& item) {
        if (!std::getline(in_, line))
            throw ImportError("dump: ends inside a snapshot at line " + std::to_string(line_));
        ++line_;
        if (line.rfind(item, 0) != 0)
            throw ImportError("dump line " + std::to_string(line_) + ": expected \"" + item + "\", got \"" +
                              line + "\"");
    };
    auto readNumber = [&] {
        read("");
        char* end = nullptr;
        const long long value = std::strtoll(line.c_str(), &end, 10);
        if (end == line.c_str())
            throw ImportError("dump line " + std::to_string(line_) + ": expected a number");
        return value;
    };
    while (std::getline(in_, line)) {
        ++line_;
        if (!words(line).empty()) break;
    }
    if (!in_) return false;
    if (line.rfind("ITEM: TIMESTEP", 0) != 0)
        throw ImportError("dump line " + std::to_string(line_) + ": expected \"ITEM: TIMESTEP\"");
    frame.step = readNumber();
    read("ITEM: NUMBER OF ATOMS");
    const long long count = readNumber();
    read("ITEM: BOX BOUNDS");
    for (int i = 0; i < 3; ++i) read("");
    read("ITEM: ATOMS");
    frame.columns = words(line.substr(std::string("ITEM: ATOMS").size()));
    frame.values.assign(static_cast<std::size_t>(std::max(0LL, count)), {});
    for (auto& row : frame.values) {
        if (!std::getline(in_, line) || !parseNumbers(words(line), row) || row.size() != frame.columns.size())
            throw ImportError("dump line " + std::to_string(line_ + 1) + ": not a particle of " +
                              std::to_string(frame.columns.size()) + " numbers");
        ++line_;
    }
    return true;
}

Preset readExportedExperiment(const std::string& dir, const std::string& model) {
    Preset preset;
    try {
        preset = loadPreset((std::filesystem::path(dir) / kExperimentFile).string());
    } catch (const std::exception& e) {
        throw ImportError(std::string(e.what()) + " (import reads the experiment that export wrote)");
    }
    if (preset.model != model)
        throw ImportError(dir + ": the exported experiment is a " + preset.model + ", not a " + model);
    return preset;
}

std::ifstream openRunFile(const std::string& dir, const std::string& name) {
    const auto path = std::filesystem::path(dir) / name;
    // A FIFO would block the open and a device never end: only regular files are read (streamed, line by
    // line, so their size is not bounded).
    std::error_code error;
    if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
        throw ImportError("will not read " + path.string() + ": it is not a regular file");
    std::ifstream in(path);
    if (!in) throw ImportError("cannot read " + path.string() + " (has the run finished in this folder?)");
    return in;
}

} // namespace pl::scaleout
