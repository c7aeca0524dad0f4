// export lammps, import lammps and run-lammps as a user runs them: the deck's content, every refusal
// with its exit code, LAMMPS (1 and 2 MPI ranks) against our gas from the identical state, and the
// import round trip. The LAMMPS cases need lmp and mpirun (.ci/install-deps.sh installs them).
#include "catalog/ModelCatalog.h"
#include "common/Snapshot.h"
#include "gas/GasModel.h"

#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

namespace {

struct Result {
    int exitCode;
    QString out, err;
};

Result execute(const QString& program, const QStringList& args, const QString& workDir = {}) {
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("OMPI_ALLOW_RUN_AS_ROOT", "1");
    env.insert("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1");
    env.insert("OMP_NUM_THREADS", "1");
    p.setProcessEnvironment(env);
    if (!workDir.isEmpty()) p.setWorkingDirectory(workDir);
    p.start(program, args);
    p.waitForFinished(120000);
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

Result cli(const QStringList& args) {
    return execute(PARTICLELAB_CLI, args);
}

QString readText(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

void writeText(const QString& path, const QString& text) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text.toUtf8());
}

// A CSV as rows of cells, the header first.
QList<QStringList> readCsv(const QString& path) {
    QList<QStringList> rows;
    for (const auto& line : readText(path).split('\n', Qt::SkipEmptyParts)) rows.push_back(line.split(','));
    return rows;
}

double cell(const QList<QStringList>& csv, int row, const char* column) {
    return csv[row][csv[0].indexOf(column)].toDouble();
}

bool haveLammps() {
    return !QStandardPaths::findExecutable("lmp").isEmpty() &&
           !QStandardPaths::findExecutable("mpirun").isEmpty();
}

// Exports the preset, runs LAMMPS on ranks processes in the deck and imports the run.
QList<QStringList> lammpsRun(const QString& dir, const QStringList& exportArgs, int ranks) {
    const auto e = cli(QStringList{"export", "lammps"} + exportArgs + QStringList{"--out", dir, "--quiet"});
    if (e.exitCode != 0) qWarning() << e.err;
    const auto l = execute("mpirun", {"-np", QString::number(ranks), "lmp", "-in", "in.lammps"}, dir);
    if (l.exitCode != 0) qWarning() << l.out.right(2000) << l.err;
    const auto i = cli({"import", "lammps", dir, "--out", dir + "/imported.csv", "--quiet"});
    if (i.exitCode != 0) qWarning() << i.err;
    return readCsv(dir + "/imported.csv");
}

// The largest relative difference of a column between two series with the same rows.
double worstRelative(const QList<QStringList>& a, const QList<QStringList>& b, const char* column) {
    double worst = 0;
    for (int r = 1; r < a.size(); ++r)
        worst =
            std::max(worst, std::abs(cell(a, r, column) - cell(b, r, column)) / std::abs(cell(b, r, column)));
    return worst;
}

} // namespace

class TestScaleOut : public QObject {
    Q_OBJECT
private slots:
    void exportWritesTheExactStateAndTheMappedPhysics() {
        QTemporaryDir dir;
        const QString deck = dir.filePath("deck");
        const auto r =
            cli({"export", "lammps", "gas-mixture", "--set", "gravity=2.5", "--set", "piston_enabled=true",
                 "--set", "piston_x=0.5", "--steps", "300", "--every", "50", "--out", deck});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.err.contains("piston")); // what is mapped how is said on the command line
        const QString in = readText(deck + "/in.lammps");
        for (const char* line :
             {"pair_style      gran/hooke 100000 0.0 0.0 0.0 0.0 0", "fix             integrate all nve",
              "fix             fall all gravity 2.5 vector 0 -1 0", "timestep        0.00035",
              "set             type 2 mass 4", "run             300", "thermo          50",
              "dump            particles all custom 50 dump.lammpstrj id type x y vx vy"})
            QVERIFY2(in.contains(line), line);
        QVERIFY(in.contains("# the piston at x = 0.5")); // and in the deck's header
        const QStringList data = readText(deck + "/data.lammps").split('\n');
        QVERIFY(data.contains("1600 atoms"));
        QVERIFY(data.contains("2 atom types"));
        QVERIFY(data.contains("-1 0.5 xlo xhi")); // the piston is the box's right edge
        // Every disk of the initial state, to the last digit: the data file against our own dump.
        const auto ours =
            cli({"run", "gas-mixture", "--set", "gravity=2.5", "--set", "piston_enabled=true", "--set",
                 "piston_x=0.5", "--steps", "0", "--quiet", "--dump-initial", dir.filePath("init.csv")});
        QCOMPARE(ours.exitCode, 0);
        const auto init = readCsv(dir.filePath("init.csv"));
        QCOMPARE(init.size(), 1 + 1600);
        const int atoms = data.indexOf("Atoms # sphere") + 2;
        for (int i : {1, 800, 1600}) {
            const QStringList atom = data[atoms + i - 1].split(' ');
            QCOMPARE(atom[0].toInt(), init[i][0].toInt() + 1);
            QCOMPARE(atom[1].toInt(), init[i][1].toInt() + 1);
            QCOMPARE(atom[4].toDouble(), init[i][2].toDouble()); // every digit: both print exactly
            QCOMPARE(atom[5].toDouble(), init[i][3].toDouble());
        }
    }

    // A snapshot is exported in its saved state, not from its preset's start.
    void exportOfASnapshotWritesItsState() {
        QTemporaryDir dir;
        pl::Preset preset = pl::loadPreset("gas-classroom");
        preset.params["count_a"] = 300.0;
        pl::GasModel gas;
        gas.reset(preset);
        for (int s = 0; s < 50; ++s) gas.step();
        const QString snapshot = dir.filePath("moved.json");
        pl::writeSnapshotFile(snapshot.toStdString(), gas);
        const auto r = cli({"export", "lammps", snapshot, "--out", dir.filePath("deck"), "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList data = readText(dir.filePath("deck/data.lammps")).split('\n');
        const int atoms = data.indexOf("Atoms # sphere") + 2, velocities = data.indexOf("Velocities") + 2;
        const pl::GasState& s = gas.state();
        QCOMPARE(data.indexOf("300 atoms"), 2);
        for (std::size_t i : {std::size_t(0), std::size_t(299)}) {
            const QStringList atom = data[atoms + int(i)].split(' '),
                              velocity = data[velocities + int(i)].split(' ');
            QCOMPARE(atom[0].toUInt(), s.id[i] + 1);
            QCOMPARE(atom[4].toDouble(), s.x[i]);
            QCOMPARE(atom[5].toDouble(), s.y[i]);
            QCOMPARE(velocity[1].toDouble(), s.vx[i]);
            QCOMPARE(velocity[2].toDouble(), s.vy[i]);
        }
    }

    void exportRefusesWhatLammpsCannotReproduce() {
        QTemporaryDir dir;
        const QString deck = dir.filePath("deck");
        const struct {
            QStringList args;
            const char* message;
        } refusals[] = {
            {{"gas-write-up", "--set", "integrator=rk4"}, "fix nve is velocity Verlet"},
            {{"gas-write-up", "--set", "dt=-1e-4"}, "runs time backwards"},
            {{"gas-write-up", "--set", "wall_mode=thermal"}, "thermal walls"},
            {{"dsmc-write-up"}, "use export sparta"},
            {{"no-such-preset"}, "no-such-preset"},
        };
        for (const auto& refusal : refusals) {
            const auto r = cli(QStringList{"export", "lammps"} + refusal.args + QStringList{"--out", deck});
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains(refusal.message), qPrintable(r.err));
        }
        const QString withObstacle = dir.filePath("obstacle.json");
        writeText(withObstacle, R"({"schema": 1, "model": "gas", "params": {"count_a": 100},
            "obstacles": [{"shape": "disc", "x": 0, "y": 0, "radius": 0.2}]})");
        const auto o = cli({"export", "lammps", withObstacle, "--out", deck});
        QCOMPARE(o.exitCode, 2);
        QVERIFY2(o.err.contains("obstacle"), qPrintable(o.err));
        QVERIFY(!QFile::exists(deck + "/in.lammps")); // a refused deck is not written at all
        QVERIFY(!QFile::exists(deck + "/particlelab.json"));

        const auto gasToSparta = cli({"export", "sparta", "gas-write-up", "--out", deck});
        QCOMPARE(gasToSparta.exitCode, 2);
        QVERIFY2(gasToSparta.err.contains("use export lammps"), qPrintable(gasToSparta.err));
        const auto planar = cli({"export", "sparta", "dsmc-planar-beams", "--out", deck});
        QCOMPARE(planar.exitCode, 2);
        QVERIFY2(planar.err.contains("velocity_components"), qPrintable(planar.err));
        const auto sparta = cli({"export", "sparta", "dsmc-write-up", "--out", deck});
        QVERIFY2(sparta.exitCode == 0 && sparta.err.contains("omega = 3/4"), qPrintable(sparta.err));
        for (const char* name :
             {"in.sparta", "gas.species", "gas.vss", "particles.sparta", "particlelab.json"})
            QVERIFY2(QFile::exists(deck + "/" + name), name);
        // The wind tunnel exports too (a 2D deck with its bodies); its piston and a run that ends before
        // the fields window are refused, and the tunnel is no gas.
        const QString tunnel = dir.filePath("tunnel");
        const auto cylinder = cli({"export", "sparta", "tunnel-cylinder", "--out", tunnel, "--quiet"});
        QVERIFY2(cylinder.exitCode == 0, qPrintable(cylinder.err));
        for (const char* name : {"in.sparta", "gas.species", "gas.vss", "bodies.surf", "particlelab.json"})
            QVERIFY2(QFile::exists(tunnel + "/" + name), name);
        const auto piston = cli({"export", "sparta", "tunnel-shock-tube", "--out", deck});
        QCOMPARE(piston.exitCode, 2);
        QVERIFY2(piston.err.contains("piston_on"), qPrintable(piston.err));
        const auto early = cli({"export", "sparta", "tunnel-cylinder", "--steps", "500", "--out", deck});
        QCOMPARE(early.exitCode, 2);
        QVERIFY2(early.err.contains("sample_start"), qPrintable(early.err));
        const auto tunnelToLammps = cli({"export", "lammps", "tunnel-cylinder", "--out", deck});
        QCOMPARE(tunnelToLammps.exitCode, 2);
        QVERIFY2(tunnelToLammps.err.contains("use export sparta"), qPrintable(tunnelToLammps.err));

        const auto unwritable = cli({"export", "lammps", "gas-write-up", "--out", "/proc/particlelab-deck"});
        QCOMPARE(unwritable.exitCode, 4);
        const auto missing =
            cli({"import", "lammps", dir.filePath("nothing-here"), "--out", dir.filePath("s.csv")});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY2(missing.err.contains("particlelab.json"), qPrintable(missing.err));
    }

    // Our run exported as a LAMMPS dump and log and read back gives the histograms of `run --histogram`
    // bit for bit, and the energies of the run.
    void importRoundTripGivesIdenticalHistograms() {
        QTemporaryDir dir;
        const QString deck = dir.filePath("deck");
        const QStringList preset{"gas-classroom", "--set", "count_a=400"};
        QCOMPARE(
            cli(QStringList{"export", "lammps"} + preset + QStringList{"--out", deck, "--quiet"}).exitCode,
            0);
        const auto r =
            cli(QStringList{"run"} + preset +
                QStringList{"--steps", "200", "--every", "200", "--quiet", "--out", dir.filePath("s.csv"),
                            "--histogram", dir.filePath("h.csv"), "--dump-final", dir.filePath("f.csv")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const auto series = readCsv(dir.filePath("s.csv"));
        const auto particles = readCsv(dir.filePath("f.csv"));
        QString dump =
            "ITEM: TIMESTEP\n200\nITEM: NUMBER OF ATOMS\n400\nITEM: BOX BOUNDS ff ff pp\n-1 1\n-1 1\n"
            "-0.5 0.5\nITEM: ATOMS id type x y vx vy\n";
        for (int i = 1; i < particles.size(); ++i)
            dump += QString("%1 %2 %3 %4 %5 %6\n")
                        .arg(particles[i][0].toInt() + 1)
                        .arg(particles[i][1].toInt() + 1)
                        .arg(particles[i][2], particles[i][3], particles[i][4], particles[i][5]);
        writeText(deck + "/dump.lammpstrj", dump);
        const QStringList last = series.last();
        writeText(deck + "/log.lammps", "Step Time Atoms KinEng Temp Press c_kT_a v_px v_py\n" +
                                            QStringList{last[0], last[1], last[2], last[3], last[6], last[11],
                                                        last[7], last[9], last[10]}
                                                .join(' ') +
                                            "\nLoop time of 0.1 on 1 procs for 200 steps with 400 atoms\n");
        const auto i = cli({"import", "lammps", deck, "--out", dir.filePath("i.csv"), "--histogram",
                            dir.filePath("ih.csv")});
        QVERIFY2(i.exitCode == 0, qPrintable(i.err));
        QCOMPARE(readText(dir.filePath("h.csv")).count("\nspeed_a,"), 40); // gas-classroom's 40 bins
        QCOMPARE(readText(dir.filePath("ih.csv")), readText(dir.filePath("h.csv")));
        const auto imported = readCsv(dir.filePath("i.csv"));
        QCOMPARE(imported[0], series[0]); // the columns of run
        QCOMPARE(imported.size(), 2);
        QCOMPARE(imported[1][imported[0].indexOf("ks_a")], last[series[0].indexOf("ks_a")]);
        const double potential = cell(series, series.size() - 1, "potential");
        QVERIFY(std::abs(cell(imported, 1, "potential") - potential) <= 1e-12 * potential);
        QVERIFY(std::isnan(cell(imported, 1, "pressure_wall")));
    }

    // The write-up's soft disks: LAMMPS and our gas agree to round-off over 1000 steps, on 1 and 2 ranks.
    void lammpsAgreesWithTheSeedGas() {
        if (!haveLammps()) QSKIP("lmp or mpirun not installed (.ci/install-deps.sh installs them)");
        QTemporaryDir dir;
        const QStringList preset{"gas-write-up", "--set", "count_a=1024", "--set",
                                 "box_width=1",  "--set", "box_height=1"};
        const QStringList length{"--steps", "1000", "--every", "250"};
        QCOMPARE(
            cli(QStringList{"run"} + preset + length + QStringList{"--quiet", "--out", dir.filePath("s.csv")})
                .exitCode,
            0);
        const auto ours = readCsv(dir.filePath("s.csv"));
        for (int ranks : {1, 2}) {
            const auto lammps = lammpsRun(dir.filePath(QString("np%1").arg(ranks)), preset + length, ranks);
            QCOMPARE(lammps.size(), ours.size());
            QCOMPARE(cell(lammps, lammps.size() - 1, "step"), 1000.0);
            qInfo("%d rank(s): kinetic energy within %.2g relative", ranks,
                  worstRelative(lammps, ours, "kinetic"));
            QVERIFY2(worstRelative(lammps, ours, "kinetic") < 1e-6, qPrintable(QString::number(ranks)));
            QVERIFY(worstRelative(lammps, ours, "potential") < 1e-6);
            QVERIFY(worstRelative(lammps, ours, "pressure_virial") < 1e-6);
        }
    }

    // Two species under gravity: hard-ish disks are chaotic, so round-off (1e-16) grows about tenfold per
    // 100 steps here (measured 7e-9 in the kinetic energy after 1000 steps); 1e-6 leaves two decades.
    void lammpsAgreesWithTheMixtureUnderGravity() {
        if (!haveLammps()) QSKIP("lmp or mpirun not installed (.ci/install-deps.sh installs them)");
        QTemporaryDir dir;
        const QStringList preset{"gas-mixture", "--set", "gravity=1",   "--set", "count_a=300", "--set",
                                 "count_b=100", "--set", "box_width=1", "--set", "box_height=1"};
        const QStringList length{"--steps", "1000", "--every", "250"};
        QCOMPARE(
            cli(QStringList{"run"} + preset + length + QStringList{"--quiet", "--out", dir.filePath("s.csv")})
                .exitCode,
            0);
        const auto ours = readCsv(dir.filePath("s.csv"));
        const auto lammps = lammpsRun(dir.filePath("np2"), preset + length, 2);
        QCOMPARE(lammps.size(), ours.size());
        for (const char* column : {"kinetic", "potential", "kT_a", "kT_b"}) {
            qInfo("%s within %.2g relative", column, worstRelative(lammps, ours, column));
            QVERIFY2(worstRelative(lammps, ours, column) < 1e-6, column);
        }
    }

    void runLammpsExportsRunsAndImports() {
        if (!haveLammps()) QSKIP("lmp or mpirun not installed (.ci/install-deps.sh installs them)");
        QTemporaryDir dir;
        const auto r = cli({"run-lammps", "gas-write-up", "--set", "count_a=256", "--set", "box_width=0.5",
                            "--set", "box_height=0.5", "--np", "2", "--steps", "200", "--every", "100",
                            "--out", dir.filePath("s.csv"), "--histogram", dir.filePath("h.csv")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.err.contains("LAMMPS step 200/200"));
        const auto series = readCsv(dir.filePath("s.csv"));
        QCOMPARE(series.size(), 1 + 3);
        QCOMPARE(cell(series, 3, "particles"), 256.0);
        QVERIFY(readText(dir.filePath("h.csv"))
                    .startsWith("histogram,bin_lo,bin_hi,count,density,theory_density\n"));
    }

    // A LAMMPS that fails is reported with its own last words and exit code 3; a missing one with 2.
    void runLammpsReportsAFailedOrMissingLammps() {
        QTemporaryDir bin;
        const QString fakeLmp = bin.filePath("lmp");
        writeText(fakeLmp, "#!/bin/sh\necho 'ERROR: Lost atoms: original 256 current 255'\nexit 1\n");
        QFile::setPermissions(fakeLmp, QFile::ExeOwner | QFile::ReadOwner);
        writeText(bin.filePath("mpirun"), "#!/bin/sh\nshift 2\nexec \"$@\"\n"); // mpirun -np N cmd…
        QFile::setPermissions(bin.filePath("mpirun"), QFile::ExeOwner | QFile::ReadOwner);
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("PATH", bin.path() + ":/usr/bin:/bin");
        p.setProcessEnvironment(env);
        p.start(PARTICLELAB_CLI, {"run-lammps", "gas-write-up", "--steps", "10", "--out",
                                  bin.filePath("s.csv"), "--work", bin.filePath("work")});
        QVERIFY(p.waitForFinished(60000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitCode(), 3);
        QVERIFY2(err.contains("LAMMPS failed") && err.contains("Lost atoms"), qPrintable(err));
        QVERIFY(!QFile::exists(bin.filePath("s.csv")));
        QVERIFY(QFile::exists(bin.filePath("work/in.lammps"))); // the deck stays for a look at what failed

        env.insert("PATH", bin.path() + "/nowhere");
        p.setProcessEnvironment(env);
        p.start(PARTICLELAB_CLI, {"run-lammps", "gas-write-up"});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains("lmp not found"));
    }
};

QTEST_GUILESS_MAIN(TestScaleOut)
#include "tst_scaleout.moc"
