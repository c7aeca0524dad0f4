// A seeded fuzzer of particlelab-cli and particlelab-bench: mutated options and --set values, mutated
// preset files (schema 3 and schema 1), corrupted snapshots of every kind, and mutated bench options, each
// run with a time limit. Every outcome must be one of the documented ones: exit 0 with finite
// observables, exit 2 with a message (bad input), exit 3 naming what blew up, exit 4 for an output that
// cannot be written (the bench); never a signal, a hang or another code. The counts go out per category
// and outcome. PARTICLELAB_FUZZ_SEED and PARTICLELAB_FUZZ_CASES change the seed and the number of cases;
// PARTICLELAB_FUZZ_CLASSES (e.g. "snapshot,preset", as the sanitizer job runs it) keeps the cases of those
// categories only.
#include "CliRunner.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <map>
#include <mutex>
#include <random>
#include <thread>

using pl::test::CliResult;
using pl::test::runCli;
using pl::test::runProgram;

namespace {

struct Scene {
    const char* preset;
    const char* model;
    QStringList small; // --set values that keep a run short
    QStringList keys;  // parameters worth mutating
};

const std::vector<Scene>& scenes() {
    static const std::vector<Scene> list{
        {"gas-classroom",
         "gas",
         {"count_a=80"},
         {"count_a", "count_b", "mass_a", "diameter_a", "box_width", "box_height", "stiffness", "init_speed",
          "dt", "gravity", "piston_enabled", "piston_x", "integrator", "force_method", "wall_mode",
          "init_velocity", "histogram_bins", "max_particles"}},
        {"gas-mixture",
         "gas",
         {"count_a=60", "count_b=20"},
         {"count_b", "mass_b", "diameter_b", "dt", "stiffness"}},
        {"dsmc-bkw",
         "dsmc",
         {"count_a=300"},
         {"count_a", "fn", "dt", "cell_volume", "cross_section", "initial", "temperature",
          "velocity_components", "histogram_bins", "sigma_cr_max_init"}},
        {"dsmc-write-up",
         "dsmc",
         {"count_a=200", "count_b=200"},
         {"count_b", "drift_a", "drift_b", "mass_amu", "fn", "dt"}},
        {"fluid-dam-break",
         "fluid",
         {},
         {"dt", "iterations", "h", "epsilon", "rest_density", "scorr_k", "particle_radius", "xsph",
          "vorticity", "max_particles", "fill_x1"}},
        {"fluid-obstacle",
         "fluid",
         {"fill_x1=20"},
         {"dt", "gravity", "tool_speed_factor", "fill_y1", "box_width", "particle_radius", "h", "drain"}},
        {"tunnel-shock-tube",
         "tunnel",
         {"fn=1.6e14"},
         {"dt", "fn", "cells_x", "cells_y", "stream_density", "stream_temperature", "piston_speed",
          "piston_on", "sample_start", "box_width", "wall_temperature", "initial"}},
        {"tunnel-cylinder",
         "tunnel",
         {"fn=5e15"},
         {"dt", "fn", "stream_speed", "stream_temperature", "surface", "body_temperature", "tool_speed",
          "bottom_wall_speed", "top_wall_speed", "cells_x", "box_height", "view"}},
    };
    return list;
}

const QStringList kNastyValues{"",
                               "-1",
                               "0",
                               "1",
                               "1e12",
                               "abc",
                               "0x10",
                               " 1",
                               "nan",
                               "inf",
                               "-0",
                               "1e-320",
                               "2.5",
                               "+3",
                               "1e3",
                               "1e",
                               "--",
                               "1,5",
                               "99999999999999999999999",
                               "true",
                               "rk4",
                               "-1e300",
                               "1e308",
                               "\xc3\xa9"};

// One command: the program, its arguments, the series file it may write, and what was mutated.
struct Case {
    QString program = PARTICLELAB_CLI;
    QStringList args;
    QString series;
    QString category; // "options", "preset", "schema 1", "snapshot", "bench"
};

// Snapshots of each kind to corrupt, written once by the CLI itself.
struct SnapshotSource {
    QString path, model;
};

class CaseMaker {
public:
    CaseMaker(std::uint64_t seed, std::vector<SnapshotSource> snapshots, QStringList categories)
        : rng_(seed), snapshots_(std::move(snapshots)), categories_(std::move(categories)) {}

    // A case of one of the chosen categories (any when none were chosen); preset and snapshot files it
    // needs are written into dir under the case number.
    Case next(const QString& dir, int index) {
        for (;;)
            if (Case c = anyCase(dir, index); categories_.isEmpty() || categories_.contains(c.category))
                return c;
    }

private:
    Case anyCase(const QString& dir, int index) {
        Case c;
        c.series = dir + "/s" + QString::number(index) + ".csv";
        const double kind = std::uniform_real_distribution<double>(0, 1)(rng_);
        if (kind < 0.06) return bench(c);
        if (kind < 0.18 && !snapshots_.empty()) return corruptedSnapshot(c, dir, index);
        const Scene& scene = scenes()[pick(scenes().size())];
        c.args = QStringList{
            "run",   scene.preset, "--quiet", "--backend", "cpu", "--steps", QString::number(pick(25)),
            "--out", c.series};
        for (const QString& s : scene.small) c.args << "--set" << s;
        c.category = "options";
        if (kind < 0.26 && schemaOne(scene, c, dir + "/p" + QString::number(index) + ".json")) return c;
        if (chance(0.35)) {
            c.args[1] = writePreset(scene, dir + "/p" + QString::number(index) + ".json");
            c.category = "preset";
        }
        if (scene.model == QString("gas") && chance(0.3)) { // valid but maybe unstable: blow-ups
            c.args[6] = QString::number(100 + pick(200));
            static const QStringList integrators{"velocity-verlet", "rk4", "forest-ruth", "symplectic-euler",
                                                 "explicit-euler"};
            c.args << "--set"
                   << "integrator=" + integrators[int(pick(integrators.size()))] << "--set"
                   << "dt=" + QString::number(
                                  std::pow(10.0, std::uniform_real_distribution<double>(-3.3, -2)(rng_)))
                   << "--set"
                   << "stiffness=" +
                          QString::number(std::pow(10.0, std::uniform_real_distribution<double>(5, 7)(rng_)));
        }
        const int mutations = int(pick(3));
        for (int m = 0; m < mutations; ++m) mutateOptions(scene, c.args);
        return c;
    }

    // A schema-1 file of the scene's kind (tests/data/schema1) with one parameter changed; false when the
    // kind has none.
    bool schemaOne(const Scene& scene, Case& c, const QString& path) {
        const QStringList files =
            QDir(PARTICLELAB_TEST_DATA "/schema1").entryList({QString(scene.model) + "-*.json"}, QDir::Files);
        if (files.isEmpty()) return false;
        QFile in(PARTICLELAB_TEST_DATA "/schema1/" + files[int(pick(files.size()))]);
        if (!in.open(QIODevice::ReadOnly)) return false;
        QString text = QString::fromUtf8(in.readAll());
        // One "key": value of the file's params set to a mutated value (the JSON may break: bad input).
        static const QRegularExpression entry(
            R"re("([a-z_0-9]+)"\s*:\s*(-?[0-9.eE+-]+|true|false|"[a-z0-9-]*"))re");
        std::vector<QRegularExpressionMatch> entries;
        for (auto it = entry.globalMatch(text); it.hasNext();) entries.push_back(it.next());
        if (!entries.empty()) {
            const QRegularExpressionMatch& m = entries[pick(entries.size())];
            text.replace(m.capturedStart(2), m.capturedLength(2), chance(0.5) ? number() : jsonValue());
        }
        QFile out(path);
        if (out.open(QIODevice::WriteOnly)) out.write(text.toUtf8());
        c.args = QStringList{
            "run",   path,    "--quiet", "--backend", "cpu", "--steps", QString::number(1 + pick(10)),
            "--out", c.series};
        c.category = "schema 1";
        return true;
    }

    // A snapshot with one number replaced, an array entry dropped, or the text cut short.
    Case corruptedSnapshot(Case& c, const QString& dir, int index) {
        const SnapshotSource& source = snapshots_[pick(snapshots_.size())];
        QFile in(source.path);
        QString text = in.open(QIODevice::ReadOnly) ? QString::fromUtf8(in.readAll()) : QString();
        static const QRegularExpression numberToken(R"(-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?)");
        // Half the time a number of the state's scalars (the clock, counters, a piston's direction), which
        // are few among the particles' arrays but each read into an integer or a bound of its own.
        static const QRegularExpression scalarToken(
            R"("[a-z_0-9]+":\s?(-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?))");
        const bool scalar = chance(0.5);
        struct Span {
            qsizetype start, length;
        };
        std::vector<Span> numbers;
        for (auto it = (scalar ? scalarToken : numberToken).globalMatch(text); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            const int group = scalar ? 1 : 0;
            numbers.push_back({m.capturedStart(group), m.capturedLength(group)});
        }
        const double how = std::uniform_real_distribution<double>(0, 1)(rng_);
        if (how < 0.1 && !text.isEmpty()) {
            text.truncate(int(pick(text.size())));
        } else if (!numbers.empty()) {
            const Span m = numbers[pick(numbers.size())];
            if (how < 0.25 && text.mid(m.start + m.length, 1) == ",")
                text.remove(m.start, m.length + 1); // one entry fewer
            else {
                static const QStringList corrupt{
                    "null", "-1",    "0",      "1e999",  "-1e300",           "4294967296",
                    "0.5",  "\"x\"", "[]",     "1e-320", "9007199254740993", "1e18",
                    "-0",   "1e19",  "-1e308", "2.5"};
                text.replace(m.start, m.length, chance(0.7) ? corrupt[int(pick(corrupt.size()))] : number());
            }
        }
        const QString path = dir + "/snap" + QString::number(index) + ".plsnap";
        QFile out(path);
        if (out.open(QIODevice::WriteOnly)) out.write(text.toUtf8());
        c.args = QStringList{
            "run",     path, "--quiet", "--backend", "cpu", "--steps", QString::number(1 + pick(10)),
            "--every", "1",  "--out",   c.series};
        c.category = "snapshot";
        return c;
    }

    // particlelab-cli bench with mutated options, or particlelab-bench with mutated options and one
    // bad number.
    Case bench(Case& c) {
        c.category = "bench";
        if (chance(0.5)) {
            const Scene& scene = scenes()[pick(scenes().size())];
            c.args = QStringList{"bench",     scene.preset, "--steps", QString::number(1 + pick(20)),
                                 "--repeats", "1"};
            for (const QString& s : scene.small) c.args << "--set" << s;
            static const QStringList options{"--steps", "--repeats", "--threads",
                                             "--set",   "--backend", "--out"};
            for (int m = int(pick(3)); m > 0; --m) c.args << options[int(pick(options.size()))] << value();
            if (chance(0.1)) c.args.insert(int(pick(c.args.size())) + 1, nasty());
            return c;
        }
        c.program = PARTICLELAB_BENCH;
        static const QStringList options{"--gas",    "--fluid",   "--tunnel",      "--repeats", "--seconds",
                                         "--settle", "--cpu-max", "--force-lanes", "--scenes",  "--out"};
        for (int m = int(pick(3)); m > 0; --m) c.args << options[int(pick(options.size()))] << value();
        std::shuffle(c.args.begin(), c.args.end(), rng_); // options and values out of order, too
        // Last, a value no numeric option takes: the case never starts a sweep, which builds GL contexts
        // for tens of seconds on a software renderer.
        static const QStringList bad{"-5", "99999999999999999999", "nan", "inf", "-1", "abc", "1e", ""};
        c.args << options[int(pick(8))] << bad[int(pick(bad.size()))];
        return c;
    }

    QString jsonValue() {
        static const QStringList jsonValues{"1",    "-1", "0",  "1e999", "\"x\"",
                                            "null", "[]", "{}", "true",  "1e-9"};
        return jsonValues[int(pick(jsonValues.size()))];
    }

    std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
    bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
    QString nasty() { return kNastyValues[int(pick(kNastyValues.size()))]; }
    // A plausible number: any sign, 18 decades.
    QString number() {
        const double magnitude = std::pow(10.0, std::uniform_real_distribution<double>(-9, 9)(rng_));
        return QString::number(chance(0.2) ? -magnitude : magnitude, 'g', 6);
    }
    QString value() { return chance(0.6) ? number() : nasty(); }

    void mutateOptions(const Scene& scene, QStringList& args) {
        switch (pick(9)) {
        case 0:
        case 1:
        case 2:
            args << "--set" << scene.keys[int(pick(scene.keys.size()))] + "=" + value();
            break;
        case 3:
            args << "--set" << (chance(0.5) ? nasty() : "no_such_key=" + number());
            break;
        case 4: {
            static const QStringList options{"--steps", "--every", "--threads", "--seed", "--backend"};
            args << options[int(pick(options.size()))] << (chance(0.5) ? nasty() : QString::number(pick(40)));
            break;
        }
        case 5:
            args << (chance(0.5) ? "--bogus" : "--histogram") << nasty();
            break;
        case 6:
            args.insert(int(pick(args.size())) + 1, nasty()); // a stray word anywhere
            break;
        case 7:
            args.removeAt(int(pick(args.size() - 1)) + 1); // something dropped (maybe a value)
            break;
        default:
            args << "--every" << QString::number(1 + pick(5));
        }
    }

    QString writePreset(const Scene& scene, const QString& path) {
        QString params;
        for (const QString& s : scene.small) {
            const auto eq = s.indexOf('=');
            params += QString("\"%1\": %2, ").arg(s.left(eq), s.mid(eq + 1));
        }
        const QString key = scene.keys[int(pick(scene.keys.size()))];
        static const QStringList jsonValues{"1",    "-1", "0",  "1e999", "\"x\"",
                                            "null", "[]", "{}", "true",  "1e-9"};
        params +=
            QString("\"%1\": %2").arg(key, chance(0.5) ? number() : jsonValues[int(pick(jsonValues.size()))]);
        if (chance(0.2)) params += QString(", \"%1\": 1").arg(key); // a duplicate
        QString json =
            QString(R"({"schema": %1, "model": "%2", "seed": %3, "params": {%4}, "obstacles": %5})")
                .arg(chance(0.9) ? "3" : nasty(), chance(0.9) ? scene.model : "liquid",
                     chance(0.9) ? QString::number(pick(1000)) : nasty(), params,
                     chance(0.8) ? "[]"
                                 : R"([{"shape": "disc", "x": 0, "y": 0, "radius": )" + value() + "}]");
        if (chance(0.1)) json.truncate(int(pick(json.size())));
        QFile f(path);
        if (f.open(QIODevice::WriteOnly)) f.write(json.toUtf8());
        return path;
    }

    std::mt19937_64 rng_;
    std::vector<SnapshotSource> snapshots_;
    QStringList categories_;
};

// Empty when the outcome is one of the documented ones, else what is wrong.
QString judge(const CliResult& r, const QString& seriesPath, bool thermalWalls, QString& outcome) {
    if (!r.startError.isEmpty()) return "could not start: " + r.startError;
    if (r.timedOut) return "no result within the time limit (a hang)";
    if (r.crashed) return "ended by a signal";
    switch (r.exitCode) {
    case 0: {
        outcome = "ok";
        QFile f(seriesPath);
        if (!f.open(QIODevice::ReadOnly)) return {}; // the mutation may have dropped --out
        const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
        if (lines.isEmpty()) return "an empty series file";
        const QStringList header = lines[0].split(',');
        for (const char* column : {"total", "kinetic", "T"}) {
            const auto c = header.indexOf(column);
            if (c < 0) continue;
            for (const QString& row : lines.mid(1))
                if (!std::isfinite(row.split(',').value(c).toDouble()))
                    return QString("exit 0 with a non-finite %1 in the row %2").arg(column, row);
        }
        // Runaway (docs/gas.md): above 100 × the starting energy, unless thermal walls add their own.
        const auto total = header.indexOf("total");
        if (total >= 0 && lines.size() > 1 && !thermalWalls) {
            const double first = lines[1].split(',').value(total).toDouble();
            const double last = lines.last().split(',').value(total).toDouble();
            if (last > 100 * first * (1 + 1e-9))
                return QString("exit 0 with a runaway energy %1 from %2").arg(last).arg(first);
        }
        return {};
    }
    case 2:
        outcome = "bad input";
        return r.err.startsWith("particlelab-") && r.err.contains(": ") && r.err.size() > 30
                   ? ""
                   : "exit 2 without a message";
    case 4:
        outcome = "cannot write";
        return r.err.startsWith("particlelab-bench: cannot write") ? "" : "exit 4 without saying what";
    case 3:
        outcome = "blow-up";
        return r.err.contains("the model stopped: ") ? "" : "exit 3 without saying what failed";
    }
    return QString("exit code %1").arg(r.exitCode);
}

} // namespace

class TestCliFuzz : public QObject {
    Q_OBJECT
private slots:
    void everyOutcomeIsADocumentedOne() {
        const std::uint64_t seed = qEnvironmentVariableIsSet("PARTICLELAB_FUZZ_SEED")
                                       ? qEnvironmentVariable("PARTICLELAB_FUZZ_SEED").toULongLong()
                                       : 15;
        const int cases = qEnvironmentVariableIsSet("PARTICLELAB_FUZZ_CASES")
                              ? qEnvironmentVariableIntValue("PARTICLELAB_FUZZ_CASES")
                              : 2500;
        QTemporaryDir dir;
        // One snapshot of each kind, a few steps in, to corrupt.
        std::vector<SnapshotSource> snapshots;
        for (const Scene& scene : scenes()) {
            const QString path = dir.filePath(QString(scene.preset) + ".plsnap");
            QStringList args{"run",       scene.preset, "--steps",    "7", "--quiet",
                             "--backend", "cpu",        "--snapshot", path};
            for (const QString& s : scene.small) args << "--set" << s;
            const CliResult r = runCli(args);
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            snapshots.push_back({path, scene.model});
        }
        const QStringList categories =
            qEnvironmentVariable("PARTICLELAB_FUZZ_CLASSES").split(',', Qt::SkipEmptyParts);
        CaseMaker maker(seed, snapshots, categories);
        std::vector<Case> commands(cases);
        for (int i = 0; i < cases; ++i) commands[i] = maker.next(dir.path(), i);

        std::atomic<int> nextCase{0};
        std::mutex mutex;
        std::map<QString, std::map<QString, int>> counts; // category → outcome → cases
        QStringList problems;
        auto worker = [&] {
            for (int i = nextCase++; i < cases; i = nextCase++) {
                const Case& c = commands[i];
                const CliResult r =
                    runProgram(c.program, c.args, 20000, dir.path()); // stray files land there
                QString outcome;
                const QString problem = judge(r, c.series, c.args.join(' ').contains("wall_mode"), outcome);
                QFile::remove(c.series);
                const std::lock_guard lock(mutex);
                ++counts[c.category][problem.isEmpty() ? outcome : "wrong"];
                if (!problem.isEmpty())
                    problems << problem + ": " + QFileInfo(c.program).fileName() + " " + c.args.join(' ') +
                                    "\n  " + r.err.left(300);
            }
        };
        std::thread second(worker);
        worker();
        second.join();

        qInfo().noquote() << QString("seed %1, %2 cases").arg(seed).arg(cases);
        for (const auto& [category, outcomes] : counts) {
            QString line = "  " + category + ":";
            for (const auto& [outcome, n] : outcomes) line += QString(" %1 %2,").arg(outcome).arg(n);
            qInfo().noquote() << line;
        }
        for (const QString& p : problems.mid(0, 20)) qWarning().noquote() << p;
        QVERIFY2(problems.isEmpty(), qPrintable(QString::number(problems.size()) + " wrong outcomes"));
        // The mutations reach every class: a fuzzer that only ever hits bad input tests nothing else.
        // (Blow-ups come from the gas's unstable integrators alone, about 1 case in 100.)
        for (const auto& [outcome, least] :
             {std::pair{"ok", cases / 100}, std::pair{"bad input", cases / 100},
              std::pair{"blow-up", std::max(1, cases / 500)}}) {
            int n = 0;
            for (const auto& [category, outcomes] : counts)
                if (const auto it = outcomes.find(outcome); it != outcomes.end()) n += it->second;
            QVERIFY2(n >= least, outcome);
        }
        for (const char* category : {"options", "preset", "schema 1", "snapshot", "bench"}) {
            if (!categories.isEmpty() && !categories.contains(category)) continue;
            QVERIFY2(counts[category]["ok"] > 0 || QString(category) == "bench", category);
            QVERIFY2(counts[category]["bad input"] > 0, category);
        }
    }
};

QTEST_GUILESS_MAIN(TestCliFuzz)
#include "tst_cli_fuzz.moc"
