// A seeded fuzzer of particlelab-cli: mutated options, --set values and preset files, each run with a
// time limit. Every outcome must be one of the documented ones: exit 0 with finite observables, exit 2
// with a message (bad input), exit 3 naming what blew up; never a signal, a hang or another code.
// PARTICLELAB_FUZZ_SEED and PARTICLELAB_FUZZ_CASES change the seed and the number of cases.
#include "CliRunner.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <map>
#include <mutex>
#include <random>
#include <thread>

using pl::test::CliResult;
using pl::test::runCli;

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

class CaseMaker {
public:
    explicit CaseMaker(std::uint64_t seed) : rng_(seed) {}

    // A command line; preset files it needs are written into dir under the case number.
    QStringList next(const QString& dir, int index, QString& seriesPath) {
        const Scene& scene = scenes()[pick(scenes().size())];
        seriesPath = dir + "/s" + QString::number(index) + ".csv";
        QStringList args{
            "run",   scene.preset, "--quiet", "--backend", "cpu", "--steps", QString::number(pick(25)),
            "--out", seriesPath};
        for (const QString& s : scene.small) args << "--set" << s;
        if (chance(0.35)) args[1] = writePreset(scene, dir + "/p" + QString::number(index) + ".json");
        if (scene.model == QString("gas") && chance(0.3)) { // valid but maybe unstable: blow-ups
            args[6] = QString::number(100 + pick(200));
            static const QStringList integrators{"velocity-verlet", "rk4", "forest-ruth", "symplectic-euler",
                                                 "explicit-euler"};
            args << "--set"
                 << "integrator=" + integrators[int(pick(integrators.size()))] << "--set"
                 << "dt=" + QString::number(
                                std::pow(10.0, std::uniform_real_distribution<double>(-3.3, -2)(rng_)))
                 << "--set"
                 << "stiffness=" +
                        QString::number(std::pow(10.0, std::uniform_real_distribution<double>(5, 7)(rng_)));
        }
        const int mutations = int(pick(3));
        for (int m = 0; m < mutations; ++m) mutateOptions(scene, args);
        return args;
    }

private:
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
        return r.err.startsWith("particlelab-cli: ") && r.err.size() > 30 ? "" : "exit 2 without a message";
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
        CaseMaker maker(seed);
        std::vector<QStringList> commands(cases);
        std::vector<QString> series(cases);
        for (int i = 0; i < cases; ++i) commands[i] = maker.next(dir.path(), i, series[i]);

        std::atomic<int> nextCase{0};
        std::mutex mutex;
        std::map<QString, int> counts;
        QStringList problems;
        auto worker = [&] {
            for (int i = nextCase++; i < cases; i = nextCase++) {
                const CliResult r = runCli(commands[i], 20000, dir.path()); // stray files land there
                QString outcome;
                const QString problem =
                    judge(r, series[i], commands[i].join(' ').contains("wall_mode"), outcome);
                QFile::remove(series[i]);
                const std::lock_guard lock(mutex);
                ++counts[problem.isEmpty() ? outcome : "wrong"];
                if (!problem.isEmpty())
                    problems << problem + ": particlelab-cli " + commands[i].join(' ') + "\n  " +
                                    r.err.left(300);
            }
        };
        std::thread second(worker);
        worker();
        second.join();

        QString summary = QString("seed %1, %2 cases:").arg(seed).arg(cases);
        for (const auto& [outcome, n] : counts) summary += QString(" %1 %2,").arg(outcome).arg(n);
        qInfo().noquote() << summary;
        for (const QString& p : problems.mid(0, 20)) qWarning().noquote() << p;
        QVERIFY2(problems.isEmpty(), qPrintable(QString::number(problems.size()) + " wrong outcomes"));
        // The mutations reach every class: a fuzzer that only ever hits bad input tests nothing else.
        for (const char* outcome : {"ok", "bad input", "blow-up"})
            QVERIFY2(counts[outcome] >= cases / 100, outcome);
    }
};

QTEST_GUILESS_MAIN(TestCliFuzz)
#include "tst_cli_fuzz.moc"
