// Golden regression: a short run of every built-in preset, compared with the series (and, where kept,
// the final particles) recorded in tests/data/golden, so a refactor that changes a result is caught.
// PARTICLELAB_REGENERATE_GOLDEN=1 rewrites the files instead (tests/data/golden/README.md says when).
#include "catalog/ModelCatalog.h"
#include "common/TimeSeries.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <omp.h>
#include <optional>
#include <set>
#include <sstream>

using namespace pl;

namespace {

const std::string kGoldenDir = PARTICLELAB_TEST_DATA "/golden/";

// One line of runs.txt: which preset, how long, how often sampled, whether its particles are kept.
struct GoldenRun {
    std::string preset;
    long long steps = 0;
    long long every = 1;
    bool particles = false;
};

std::vector<GoldenRun> readRuns() {
    std::ifstream in(kGoldenDir + "runs.txt");
    std::vector<GoldenRun> runs;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        GoldenRun run;
        std::string particles;
        fields >> run.preset >> run.steps >> run.every >> particles;
        if (!fields || (particles != "yes" && particles != "no"))
            throw std::runtime_error("runs.txt: cannot read the line \"" + line + "\"");
        run.particles = particles == "yes";
        runs.push_back(run);
    }
    return runs;
}

// A CSV as the CLI writes it: one header line, then numbers ("nan" and "inf" included).
struct Table {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
};

std::vector<std::string> splitCommas(const std::string& line) {
    std::vector<std::string> cells;
    std::istringstream in(line);
    std::string cell;
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    return cells;
}

Table parseTable(std::istream& in) {
    Table table;
    std::string line;
    if (!std::getline(in, line)) return table;
    table.columns = splitCommas(line);
    while (std::getline(in, line)) {
        std::vector<double> row;
        for (const auto& cell : splitCommas(line)) row.push_back(std::strtod(cell.c_str(), nullptr));
        table.rows.push_back(std::move(row));
    }
    return table;
}

std::string tableText(const Table& table) {
    std::ostringstream out;
    out.precision(17); // round-trips every double
    for (std::size_t c = 0; c < table.columns.size(); ++c) out << (c ? "," : "") << table.columns[c];
    out << '\n';
    for (const auto& row : table.rows) TimeSeries::writeCsvRow(out, row);
    return out.str();
}

// Exactly the loop of `particlelab-cli run PRESET --steps N --every M --out …`: a row at step 0, one
// every M steps and one at the end, each after a health check. sampleSeries() closes accumulation
// windows (collision rates), so the rows depend on when it is called: it is called at the same steps.
Table runSeries(Model& model, const GoldenRun& run) {
    Table table{model.seriesColumns(), {}};
    const auto sample = [&] {
        model.checkHealthNow();
        if (!model.failure()) table.rows.push_back(model.sampleSeries());
    };
    sample();
    for (long long s = 1; s <= run.steps && !model.failure(); ++s) {
        model.step();
        if (!model.failure() && (s % run.every == 0 || s == run.steps)) sample();
    }
    return table;
}

// The particles as the model writes them (its own precision: the fluid writes 6 digits), and parsed.
struct Written {
    std::string text;
    Table table;
};

Written particlesOf(const Model& model) {
    std::ostringstream out;
    model.writeParticles(out);
    std::istringstream in(out.str());
    return {out.str(), parseTable(in)};
}

Written seriesWritten(Table series) {
    std::string text = tableText(series);
    return {std::move(text), std::move(series)};
}

// The tolerance of a run's comparison, relative to the size of the value or of its column.
//
// Not exact equality: the CPU models are deterministic (bit-identical at 1 and 2 threads), but speed
// work legitimately reorders floating-point sums (forces, densities, moments), which changes the last
// bits, and the dynamics then amplify those bits. Measured with the recorded runs by changing the time
// step by one ulp (a perturbation of the same size as a reordered sum): the gas and DSMC series and
// the gas particles stay within 3e-11 of their column's scale, so 1e-9 leaves a margin of 30 and
// still catches any change of physics. The fluid's constraint projection amplifies faster (one ulp of
// Δt or ε grows to 1e-9 of the series and 2e-7 of a particle's velocity in 20–40 steps, and to 1e-3
// after 100): its series are compared to 1e-7, its particles to 1e-5 (the fluid writes particles
// with 6 significant digits, so a rounding change can also flip their last digit, 1e-6 of the value).
struct Tolerance {
    double series;
    double particles;
};

Tolerance toleranceFor(const std::string& kind) {
    if (kind == "fluid") return {1e-7, 1e-5};
    return {1e-9, 1e-9};
}

// Columns that are a small difference of large numbers carry the rounding error of those numbers, not
// their own: (E − E₀)/E₀ is ~1e-7 while its rounding is ~1e-16 of E, so it is compared absolutely: an
// energy that agrees to 1e-12 of itself (measured: 3e-15 after a one-ulp change of Δt).
const std::map<std::string, double> kAbsoluteTolerance = {{"energy_drift", 1e-12}};

// Compares actual with expected column by column; returns the first mismatch, or an empty string.
// A value passes when |a − e| ≤ tol · max(|a|, |e|, S), S the largest |e| of its column: a value near
// zero in a column that is large elsewhere (a momentum sum that cancels) carries the column's rounding.
std::string compareTables(const Table& actual, const Table& expected, double tolerance) {
    if (actual.columns != expected.columns) {
        std::string a, e;
        for (const auto& c : actual.columns) a += c + ",";
        for (const auto& c : expected.columns) e += c + ",";
        return "columns differ:\n   actual   " + a + "\n   expected " + e;
    }
    if (actual.rows.size() != expected.rows.size())
        return "rows: " + std::to_string(actual.rows.size()) + " instead of " +
               std::to_string(expected.rows.size());
    for (std::size_t c = 0; c < expected.columns.size(); ++c) {
        double scale = 0;
        for (const auto& row : expected.rows)
            if (std::isfinite(row[c])) scale = std::max(scale, std::abs(row[c]));
        const auto absolute = kAbsoluteTolerance.find(expected.columns[c]);
        for (std::size_t r = 0; r < expected.rows.size(); ++r) {
            if (actual.rows[r].size() <= c || expected.rows[r].size() <= c)
                return "row " + std::to_string(r) + " has fewer cells than columns";
            const double a = actual.rows[r][c], e = expected.rows[r][c];
            if (std::isnan(a) && std::isnan(e)) continue;
            if (std::isinf(e) && a == e) continue;
            const double allowed = absolute != kAbsoluteTolerance.end()
                                       ? absolute->second
                                       : tolerance * std::max({std::abs(a), std::abs(e), scale});
            if (!(std::abs(a - e) <= allowed)) {
                std::ostringstream why;
                why.precision(17);
                why << "row " << r << ", column " << expected.columns[c] << ": " << a << " instead of " << e
                    << " (allowed difference " << allowed << ")";
                return why.str();
            }
        }
    }
    return {};
}

bool regenerating() {
    const char* flag = std::getenv("PARTICLELAB_REGENERATE_GOLDEN");
    return flag && std::string(flag) == "1";
}

// The recorded table, or why there is none.
std::optional<Table> readGolden(const std::string& file) {
    std::ifstream in(kGoldenDir + file);
    if (!in) return std::nullopt;
    return parseTable(in);
}

void writeGolden(const std::string& file, const std::string& text) {
    std::ofstream out(kGoldenDir + file, std::ios::trunc);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + kGoldenDir + file);
}

// Compares with the golden file (or rewrites it in regenerate mode); true when the caller goes on.
// Regenerating writes the text the CLI would write, byte for byte.
bool checkAgainstGolden(const std::string& file, const Written& actual, double tolerance) {
    if (regenerating()) {
        writeGolden(file, actual.text);
        return true;
    }
    const auto expected = readGolden(file);
    if (!expected) {
        QTest::qFail(("no golden file " + kGoldenDir + file + ": record it (README.md)").c_str(), __FILE__,
                     __LINE__);
        return false;
    }
    const std::string mismatch = compareTables(actual.table, *expected, tolerance);
    if (!mismatch.empty()) {
        QTest::qFail((file + ": " + mismatch).c_str(), __FILE__, __LINE__);
        return false;
    }
    return true;
}

} // namespace

class TestGolden : public QObject {
    Q_OBJECT
private slots:
    // One thread: the CPU models give the same bits at any thread count (tst_gas_determinism and
    // tst_fluid_model check that), and on a machine busy with other work OpenMP's barriers make two
    // threads ten times slower than one.
    void initTestCase() { omp_set_num_threads(1); }

    // Every built-in preset has a golden run and every golden run is a built-in preset, so a new
    // preset cannot go unrecorded and a renamed one cannot leave a stale file behind.
    void everyBuiltinPresetHasAGoldenRun() {
        std::set<std::string> recorded, builtin;
        for (const auto& run : readRuns()) recorded.insert(run.preset);
        for (const auto& p : builtinPresets()) builtin.insert(p.name);
        for (const auto& name : builtin)
            QVERIFY2(recorded.count(name), ("add " + name + " to tests/data/golden/runs.txt").c_str());
        for (const auto& name : recorded)
            QVERIFY2(builtin.count(name), (name + " in runs.txt is no built-in preset").c_str());
    }

    void runMatchesGolden_data() {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<qlonglong>("steps");
        QTest::addColumn<qlonglong>("every");
        QTest::addColumn<bool>("particles");
        for (const auto& run : readRuns())
            QTest::newRow(run.preset.c_str()) << QString::fromStdString(run.preset) << qlonglong(run.steps)
                                              << qlonglong(run.every) << run.particles;
    }

    // The preset is loaded by name through the catalog, so a renamed parameter key changes nothing here.
    void runMatchesGolden() {
        QFETCH(QString, preset);
        QFETCH(qlonglong, steps);
        QFETCH(qlonglong, every);
        QFETCH(bool, particles);
        const GoldenRun run{preset.toStdString(), steps, every, particles};
        auto model = instantiate(loadPreset(run.preset));
        const Tolerance tolerance = toleranceFor(model->kind());

        const Written series = seriesWritten(runSeries(*model, run));
        if (const auto failure = model->failure()) QFAIL(("the model failed: " + failure->message()).c_str());
        if (!checkAgainstGolden(run.preset + ".series.csv", series, tolerance.series)) return;
        if (run.particles &&
            !checkAgainstGolden(run.preset + ".particles.csv", particlesOf(*model), tolerance.particles))
            return;
        if (regenerating()) QSKIP("golden files rewritten");
    }

    // The comparison itself can fail: a changed value, a renamed column and a missing row are caught.
    void comparisonCatchesChanges() {
        const Table expected{{"step", "kinetic"}, {{0, 2.0}, {10, 2.5}}};
        QVERIFY(compareTables(expected, expected, 1e-9).empty());
        Table nudged = expected;
        nudged.rows[1][1] *= 1 + 1e-12;
        QVERIFY(compareTables(nudged, expected, 1e-9).empty());
        Table changed = expected;
        changed.rows[1][1] *= 1 + 1e-6;
        QVERIFY(!compareTables(changed, expected, 1e-9).empty());
        Table renamed = expected;
        renamed.columns[1] = "kinetic_energy";
        QVERIFY(!compareTables(renamed, expected, 1e-9).empty());
        Table shorter = expected;
        shorter.rows.pop_back();
        QVERIFY(!compareTables(shorter, expected, 1e-9).empty());
        const Table drift{{"energy_drift"}, {{1e-7}}};
        QVERIFY(!compareTables(Table{{"energy_drift"}, {{1.0001e-7}}}, drift, 1e-9).empty());
    }
};

QTEST_APPLESS_MAIN(TestGolden)
#include "tst_golden.moc"
