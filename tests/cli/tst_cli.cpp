// particlelab-cli as a user runs it: list, run with every output file, bench, and each error path with
// its exit code and message.
#include "catalog/ModelCatalog.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

namespace {

struct Result {
    int exitCode;
    QString out, err;
};

Result cli(const QStringList& args) {
    QProcess p;
    p.start(PARTICLELAB_CLI, args);
    p.waitForFinished(120000);
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

QStringList readLines(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
}

} // namespace

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void listShowsBuiltins() {
        const auto r = cli({"list"});
        QCOMPARE(r.exitCode, 0);
        for (const char* name : {"gas-write-up", "gas-classroom", "gas-mixture", "dsmc-write-up", "dsmc-bkw",
                                 "dsmc-maxwell-relax", "fluid-write-up", "fluid-dam-break", "fluid-obstacle"})
            QVERIFY(r.out.contains(name));
        // Each line ends in the unit system its kind declares.
        for (const QString& line : r.out.split('\n', Qt::SkipEmptyParts)) {
            const pl::ModelDescriptor* kind = pl::findModel(line.section('\t', 1, 1).toStdString());
            QVERIFY2(kind, qPrintable(line));
            QCOMPARE(line.section('\t', -1), QString::fromStdString(kind->units.name));
        }
    }

    // The write-up's scenes were named "-seed": the old names run the renamed preset, with a notice.
    void oldPresetNamesRunWithANotice() {
        for (const char* name : {"gas-seed", "dsmc-seed", "fluid-seed"}) {
            const auto r = cli({"run", name, "--steps", "1", "--quiet"});
            QCOMPARE(r.exitCode, 0);
            const QString now = QString(name).replace("-seed", "-write-up");
            QVERIFY2(r.err.contains(QString("the preset '%1' is now called '%2'").arg(name, now)),
                     qPrintable(r.err));
        }
    }

    // The help of the commands that take parameters or print columns names every kind's units.
    void helpSaysEachKindsUnits() {
        for (const char* command : {"run", "bench", "columns"}) {
            const auto r = cli({command, "--help"});
            QCOMPARE(r.exitCode, 0);
            for (const pl::ModelDescriptor& kind : pl::modelCatalog())
                QVERIFY2(r.out.contains(QString::fromStdString(kind.units.name + ": " + kind.units.summary)),
                         qPrintable(QString(command) + ": " + r.out));
        }
    }

    // The columns command lists what run writes: its names are the CSV header, in order.
    void columnsListTheRunsHeader() {
        QTemporaryDir dir;
        for (const char* preset : {"gas-write-up", "dsmc-write-up", "fluid-dam-break"}) {
            const QString series = dir.filePath(QString(preset) + ".csv");
            QCOMPARE(cli({"run", preset, "--steps", "2", "--out", series, "--quiet"}).exitCode, 0);
            const auto r = cli({"columns", preset});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
            QCOMPARE(lines.takeFirst(), QString("name\tunit\tlabel"));
            QStringList names;
            for (const QString& line : lines) names << line.section('\t', 0, 0);
            QCOMPARE(names.join(','), readLines(series).value(0));
        }
        QCOMPARE(cli({"columns", "gas"}).out, cli({"columns", "gas-classroom"}).out);
        const auto bad = cli({"columns", "no-such-scene"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("no-such-scene"), qPrintable(bad.err));
    }

    void aSnapshotContinuesTheRunExactly() {
        // 200 steps, a snapshot, 100 more from it: the same disks, to the last bit, as 300 at once.
        QTemporaryDir dir;
        const QString snapshot = dir.filePath("s.json"), resumed = dir.filePath("b.csv"),
                      straight = dir.filePath("c.csv");
        auto r = cli({"run", "gas-classroom", "--steps", "200", "--snapshot", snapshot, "--quiet",
                      "--backend", "cpu"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({"run", snapshot, "--steps", "100", "--dump-final", resumed, "--quiet", "--backend", "cpu"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({"run", "gas-classroom", "--steps", "300", "--dump-final", straight, "--quiet", "--backend",
                 "cpu"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(readLines(resumed), readLines(straight));
        // A snapshot is continued as saved: changing it is refused with the reason.
        r = cli({"run", snapshot, "--set", "dt=1e-4", "--steps", "5"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("is a snapshot"), qPrintable(r.err));
    }

    void dsmcSeedRunsItsPlannedLengthAndPrintsTheSeedsColumns() {
        QTemporaryDir dir;
        const QString series = dir.filePath("s.csv"), hist = dir.filePath("h.csv");
        const auto r = cli({"run", "dsmc-write-up", "--out", series, "--histogram", hist, "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList rows = readLines(series);
        QCOMPARE(rows.size(), 1 + 501); // the write-up's 500 steps, every one sampled, plus the start
        const QStringList header = rows[0].split(',');
        for (const char* column : {"step", "time", "particles", "Tx", "Ty", "Tz", "T", "ux", "kurtosis_vx",
                                   "ng", "nc", "sigma_cr_max", "M4", "M6", "M8"})
            QVERIFY2(header.contains(column), column);
        const QStringList last = rows.last().split(',');
        QCOMPARE(last[header.indexOf("step")], QString("500"));
        QVERIFY(std::abs(last[header.indexOf("T")].toDouble() - 17.83) < 0.005);
        QVERIFY(std::abs(last[header.indexOf("ux")].toDouble() - 200.0) < 1e-9);
        const QStringList bins = readLines(hist);
        QCOMPARE(bins.filter(QRegularExpression("^speed,")).size(),
                 25); // the write-up's 0–450 m/s in 25 bins
        QCOMPARE(bins.filter(QRegularExpression("^vx,")).size(), 50);
    }

    // A snapshot of a preset with a run length resumes for what is left of it (before: another full
    // run, to step 560 of 500); at the end, it runs nothing and says so.
    void aResumedSnapshotRunsWhatIsLeftOfThePlannedRun() {
        QTemporaryDir dir;
        const QString at60 = dir.filePath("at60.plsnap"), at500 = dir.filePath("at500.plsnap"),
                      series = dir.filePath("s.csv");
        auto r = cli({"run", "dsmc-write-up", "--steps", "60", "--snapshot", at60, "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({"run", at60, "--out", series, "--snapshot", at500, "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList rows = readLines(series);
        QCOMPARE(rows.size(), 1 + 441); // steps 60 … 500, every one sampled
        QVERIFY(rows.value(1).startsWith("60,"));
        QVERIFY(rows.last().startsWith("500,"));
        r = cli({"run", at500, "--out", series, "--quiet"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains("nothing is left to run"), qPrintable(r.err));
        QCOMPARE(readLines(series).size(), 1 + 1);
    }

    void damBreakRunsItsPlannedLengthWithTheFrontColumns() {
        QTemporaryDir dir;
        const QString series = dir.filePath("s.csv"), particles = dir.filePath("p.csv");
        const auto r = cli({"run", "fluid-dam-break", "--out", series, "--dump-final", particles, "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList rows = readLines(series);
        QCOMPARE(rows.size(), 1 + 301); // run_steps = 300, every step sampled, plus the start
        const QStringList header = rows[0].split(',');
        for (const char* column : {"step", "time", "particles", "density_error_mean", "density_error_max",
                                   "kinetic", "front_Z", "front_T"})
            QVERIFY2(header.contains(column), column);
        const QStringList first = rows[1].split(','), last = rows.last().split(',');
        QCOMPARE(first[header.indexOf("front_Z")].toDouble(), 1.0); // Z(0) = 1 by construction
        QCOMPARE(last[header.indexOf("particles")], QString("1250"));
        const double z = last[header.indexOf("front_Z")].toDouble(),
                     t = last[header.indexOf("front_T")].toDouble();
        QVERIFY2(z > 1.0 && z < 1.0 + 2.0 * t, qPrintable(rows.last()));
        QCOMPARE(readLines(particles).size(), 1 + 1250);
        QCOMPARE(readLines(particles)[0], QString("index,x,y,vx,vy,density_ratio"));
    }

    void runWritesEveryFile() {
        QTemporaryDir dir;
        const QString series = dir.filePath("s.csv"), hist = dir.filePath("h.csv"),
                      init = dir.filePath("i.csv"), fin = dir.filePath("f.csv");
        const auto r =
            cli({"run", "gas-write-up", "--steps", "200", "--every", "50", "--threads", "2", "--out", series,
                 "--histogram", hist, "--dump-initial", init, "--dump-final", fin});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList rows = readLines(series);
        QCOMPARE(rows.size(), 1 + 5); // header, steps 0, 50, 100, 150, 200
        const QStringList header = rows[0].split(',');
        for (const char* column :
             {"step", "time", "kinetic", "potential", "total", "kT", "pressure_virial", "pressure_wall"})
            QVERIFY2(header.contains(column), column);
        QCOMPARE(rows.last().split(',')[0], QString("200"));
        QCOMPARE(readLines(init).size(), 4097);
        QCOMPARE(readLines(fin)[0], QString("id,species,x,y,vx,vy"));
        QVERIFY(readLines(hist)[1].startsWith("speed_a,0,"));
        // The initial dump is the write-up's start: speed 1 everywhere.
        const QStringList first = readLines(init)[1].split(',');
        QVERIFY(std::abs(std::hypot(first[4].toDouble(), first[5].toDouble()) - 1.0) < 1e-12);
    }

    void setAndSeedChangeTheRun() {
        QTemporaryDir dir;
        const QString a = dir.filePath("a.csv"), b = dir.filePath("b.csv");
        QCOMPARE(cli({"run", "gas-classroom", "--steps", "0", "--set", "count_a=100", "--seed", "5",
                      "--dump-final", a})
                     .exitCode,
                 0);
        QCOMPARE(cli({"run", "gas-classroom", "--steps", "0", "--set", "count_a=100", "--seed", "6", "--set",
                      "init_placement=random", "--dump-final", b})
                     .exitCode,
                 0);
        QCOMPARE(readLines(a).size(), 101);
        QVERIFY(readLines(a)[1] != readLines(b)[1]);
    }

    void presetFileRuns() {
        QTemporaryDir dir;
        const QString path = dir.filePath("mine.json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"schema": 1, "model": "gas", "params": {"count_a": 50, "diameter_a": 0.02}})");
        f.close();
        QCOMPARE(cli({"run", path, "--steps", "10", "--quiet"}).exitCode, 0);
    }

    void badInputsNameTheProblem_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown preset")
            << QStringList{"run", "no-such-preset"} << 2 << "neither a built-in preset";
        QTest::newRow("unknown key") << QStringList{"run", "gas-write-up", "--set", "stifness=3"} << 2
                                     << "unknown parameter 'stifness'";
        QTest::newRow("renamed key") << QStringList{"run", "gas-write-up", "--set", "tool_speed=3"} << 2
                                     << "'tool_speed' is called 'tool_speed_factor'";
        QTest::newRow("renamed choice") << QStringList{"run", "dsmc-bkw", "--set", "cross_section=seed"} << 2
                                        << "\"seed\" is called \"inverse-root\"";
        QTest::newRow("out of range")
            << QStringList{"run", "gas-write-up", "--set", "dt=5"} << 2 << "[-1, 1] except 0 T";
        QTest::newRow("nan") << QStringList{"run", "gas-write-up", "--set", "stiffness=nan"} << 2
                             << "must be finite";
        QTest::newRow("wrong type") << QStringList{"run", "gas-write-up", "--set", "count_a=many"} << 2
                                    << "must be an integer";
        QTest::newRow("not key=value")
            << QStringList{"run", "gas-write-up", "--set", "dt"} << 2 << "key=value";
        QTest::newRow("too many") << QStringList{"run", "gas-write-up", "--set", "count_a=2000000"} << 2
                                  << "exceeds max_particles";
        QTest::newRow("unwritable") << QStringList{"run", "gas-write-up", "--steps",
                                                   "1",   "--out",        "/nonexistent/s.csv"}
                                    << 4 << "/nonexistent/s.csv";
    }
    void badInputsNameTheProblem() {
        QFETCH(QStringList, args);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        const auto r = cli(args);
        QCOMPARE(r.exitCode, exitCode);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }

    void blowUpExitsWithTheModelsMessage() {
        QTemporaryDir dir;
        const QString series = dir.filePath("s.csv");
        const auto r = cli({"run", "gas-classroom", "--steps", "3000", "--set", "dt=0.0056", "--out", series,
                            "--allow-unstable"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains("dt·ω = 2.50 > 2.00"), qPrintable(r.err));
        QVERIFY(readLines(series).size() > 1); // what was measured before the failure is kept
    }

    void echoWritesTheReturnErrors() {
        QTemporaryDir dir;
        const QString out = dir.filePath("echo.csv");
        const auto r = cli({"echo", "--disks", "25", "--steps", "10", "2000", "--out", out});
        QCOMPARE(r.exitCode, 0);
        const QStringList lines = readLines(out);
        QCOMPARE(lines.size(), 3);
        QCOMPARE(lines[0], QString("steps,rms_double,rms_float,rms_integer"));
        const QStringList short_ = lines[1].split(','), long_ = lines[2].split(',');
        QCOMPARE(short_[0], QString("10"));
        QCOMPARE(long_[3].toDouble(), 0.0);                  // bit-reversible
        QVERIFY(long_[2].toDouble() > long_[1].toDouble());  // float returns worse than double
        QVERIFY(long_[1].toDouble() > short_[1].toDouble()); // and both grow with n
    }

    void sweepWritesErrorsAndOrders() {
        QTemporaryDir dir;
        const QString out = dir.filePath("sweep.csv");
        const auto r = cli(
            {"sweep", "--integrators", "velocity-verlet", "rk4", "--steps", "16", "32", "64", "--out", out});
        QCOMPARE(r.exitCode, 0);
        const QStringList lines = readLines(out);
        QCOMPARE(lines.size(), 7);
        QCOMPARE(lines[0],
                 QString("integrator,dt,trajectory_error,energy_error,forces_per_time,seconds_per_time"));
        QVERIFY(lines[4].startsWith("rk4,"));
        QVERIFY2(r.err.contains("velocity-verlet: measured order 2"), qPrintable(r.err));
        QCOMPARE(cli({"sweep", "--integrators", "leapfrog"}).exitCode, 2);
    }

    void stabilityWritesClassifiedCells() {
        QTemporaryDir dir;
        const QString out = dir.filePath("stability.csv");
        const auto r = cli({"stability", "--integrators", "velocity-verlet", "--stiffness", "1000",
                            "--omega-dt", "1", "2.5", "--steps", "500", "--out", out});
        QCOMPARE(r.exitCode, 0);
        const QStringList lines = readLines(out);
        QCOMPARE(lines.size(), 3);
        QCOMPARE(lines[0],
                 QString("integrator,dt,stiffness,omega_dt,outcome,energy_error,steps,seconds,detail"));
        const QStringList stable = lines[1].split(','), unstable = lines[2].split(',');
        QCOMPARE(stable[4], QString("inaccurate")); // Verlet's bounded error at ω dt = 1 is 0.19
        QCOMPARE(stable[6], QString("500"));
        QCOMPARE(unstable[4], QString("unstable"));
        QVERIFY(unstable[6].toLongLong() < 100);
        QVERIFY2(r.err.contains("velocity-verlet, k = 1000: stable up to ω dt = 1 (linear theory 2)"),
                 qPrintable(r.err));
        QCOMPARE(cli({"stability", "--integrators", "leapfrog"}).exitCode, 2);
    }

    void fluidSweepWritesDensityErrorsAndCost() {
        QTemporaryDir dir;
        const QString out = dir.filePath("fluid.csv");
        const auto r = cli(
            {"fluid-sweep", "--dt", "0.02", "0.08", "--iterations", "4", "--duration", "0.3", "--out", out});
        QCOMPARE(r.exitCode, 0);
        const QStringList lines = readLines(out);
        QCOMPARE(lines.size(), 3);
        QCOMPARE(lines[0], QString("dt,iterations,outcome,density_error_mean,density_error_max,max_speed,"
                                   "seconds_per_time,steps,detail"));
        const QStringList fine = lines[1].split(','), coarse = lines[2].split(',');
        QCOMPARE(fine[2], QString("stable"));
        QCOMPARE(coarse[2], QString("over-compressed"));
        QVERIFY(coarse[3].toDouble() > fine[3].toDouble());
        QCOMPARE(fine[7], QString("15"));
    }

    void relaxComparesMdAndDsmc() {
        QTemporaryDir dir;
        const QString out = dir.filePath("relax.csv");
        const auto r = cli({"relax", "--particles", "256", "--collisions", "6", "--out", out});
        QCOMPARE(r.exitCode, 0);
        const QStringList lines = readLines(out);
        QCOMPARE(lines[0], QString("method,collisions_per_particle,kurtosis_vx,seconds"));
        int md = 0, dsmc = 0;
        for (const QString& line : lines.mid(1)) {
            const QStringList f = line.split(',');
            QCOMPARE(f.size(), 4);
            (f[0] == "md" ? md : dsmc) += 1;
        }
        QVERIFY(md > 5 && dsmc > 5);
        QVERIFY2(r.err.contains("cost ratio") && r.err.contains("KS distance"), qPrintable(r.err));
        QCOMPARE(cli({"relax", "--particles", "2"}).exitCode, 2); // out of range: bad input
    }

    void benchPrintsOneJsonLine() {
        const auto r = cli({"bench", "gas-classroom", "--steps", "50", "--repeats", "3", "--threads", "1"});
        QCOMPARE(r.exitCode, 0);
        const auto json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(json["particles"].toInt(), 2500);
        QCOMPARE(json["steps"].toInt(), 50);
        QCOMPARE(json["threads"].toInt(), 1);
        QCOMPARE(json["backend"].toString(), QString("cpu"));
        QVERIFY(json["p_steps_per_s"].toDouble() > 0);
        QVERIFY(std::abs(json["p_steps_per_s"].toDouble() - 2500.0 * 50 / json["seconds"].toDouble()) <
                1e-6 * json["p_steps_per_s"].toDouble());
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
