// particlelab-cli run with the wind tunnel's outputs: --fields (one row per cell at the end, also when
// stopped) and --surface (the body forces per sample, the series' drag and lift), and both refused with
// exit 2, before anything is written, for scenes that sample no fields.
#include "CliRunner.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <csignal>
#include <limits>
#include <set>
#include <sys/types.h>
#include <unistd.h>

using pl::test::runCli;

namespace {

constexpr int kSteps = 40, kEvery = 10, kSampleStart = 5;

QStringList readLines(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
}

double number(const QString& text) {
    return text == "nan" ? std::numeric_limits<double>::quiet_NaN() : text.toDouble();
}

QJsonObject snapshotParams(const QString& path, QJsonArray* obstacles = nullptr) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    const QJsonObject preset = QJsonDocument::fromJson(f.readAll()).object()["preset"].toObject();
    if (obstacles) *obstacles = preset["obstacles"].toArray();
    return preset["params"].toObject();
}

// The fields file: every cell once, row-major, with the columns of the header.
struct Fields {
    int nx = 0, ny = 0;
    std::vector<std::vector<double>> rows; // i, j, x, y, n, ux, uy, T, Tx, Ty, mach
    const std::vector<double>& cell(int i, int j) const { return rows[std::size_t(j * nx + i)]; }
};

Fields readFields(const QString& path) {
    Fields fields;
    QStringList lines = readLines(path);
    if (lines.isEmpty() || lines.takeFirst() != "i,j,x,y,n,ux,uy,T,Tx,Ty,mach") return fields;
    for (const QString& line : lines) {
        std::vector<double> row;
        for (const QString& value : line.split(',')) row.push_back(number(value));
        if (row.size() != 11) return {};
        fields.nx = std::max(fields.nx, int(row[0]) + 1);
        fields.ny = std::max(fields.ny, int(row[1]) + 1);
        fields.rows.push_back(row);
    }
    return fields;
}

} // namespace

class TestCliTunnel : public QObject {
    Q_OBJECT
private slots:
    void helpListsTheTunnelsOutputs() {
        const auto r = runCli({"run", "--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("--fields") && r.out.contains("--surface"));
    }

    void cylinderWritesFieldsAndForces() {
        QTemporaryDir dir;
        const QString fieldsPath = dir.filePath("fields.csv"), surfacePath = dir.filePath("surface.csv"),
                      seriesPath = dir.filePath("series.csv"), snapshot = dir.filePath("end.json");
        const auto r = runCli(
            {"run", "tunnel-cylinder", "--steps", QString::number(kSteps), "--every", QString::number(kEvery),
             "--set", "sample_start=" + QString::number(kSampleStart), "--backend", "cpu", "--quiet",
             "--fields", fieldsPath, "--surface", surfacePath, "--out", seriesPath, "--snapshot", snapshot});
        QVERIFY2(!r.crashed && !r.timedOut && r.exitCode == 0, qPrintable(r.err));
        QJsonArray obstacles;
        const QJsonObject params = snapshotParams(snapshot, &obstacles);
        QVERIFY(!params.isEmpty());

        // The surface rows are the model's step and time with the series' drag and lift, one per sample:
        // step 0 and then every kEvery steps.
        const QStringList surface = readLines(surfacePath), series = readLines(seriesPath);
        QCOMPARE(surface.value(0), QString("step,time,drag,lift"));
        QCOMPARE(surface.size(), 1 + 1 + kSteps / kEvery);
        QCOMPARE(series.size(), surface.size());
        const QStringList header = series[0].split(',');
        const double dt = params["dt"].toDouble();
        for (int k = 1; k < surface.size(); ++k) {
            const QStringList s = surface[k].split(','), full = series[k].split(',');
            QCOMPARE(s.size(), 4);
            QCOMPARE(s[0].toInt(), (k - 1) * kEvery);
            QCOMPARE(s[1], full[header.indexOf("time")]);
            QVERIFY(std::abs(s[1].toDouble() - s[0].toInt() * dt) <= 1e-12 * kSteps * dt);
            QCOMPARE(s[2], full[header.indexOf("drag")]);
            QCOMPARE(s[3], full[header.indexOf("lift")]);
        }
        // The stream pushes the body downstream from the first interval on.
        for (int k = 2; k < surface.size(); ++k)
            QVERIFY2(surface[k].split(',')[2].toDouble() > 0, qPrintable(surface[k]));

        // The fields: every cell once, row-major, centres a cell apart.
        const Fields fields = readFields(fieldsPath);
        const int nx = params["cells_x"].toInt(), ny = params["cells_y"].toInt();
        QCOMPARE(fields.nx, nx);
        QCOMPARE(fields.ny, ny);
        QCOMPARE(fields.rows.size(), std::size_t(nx * ny));
        const double dx = params["box_width"].toDouble() / nx, dy = params["box_height"].toDouble() / ny;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const auto& row = fields.cell(i, j);
                QCOMPARE(int(row[0]), i);
                QCOMPARE(int(row[1]), j);
                QVERIFY(std::abs(row[2] - fields.cell(0, 0)[2] - i * dx) < 1e-9 * dx * nx);
                QVERIFY(std::abs(row[3] - fields.cell(0, 0)[3] - j * dy) < 1e-9 * dy * ny);
            }
        // A cell wholly inside a body holds no gas: nan.
        for (const QJsonValue& o : obstacles) {
            const QJsonObject body = o.toObject();
            if (body["shape"].toString() != "disc" || body["radius"].toDouble() < 2 * std::hypot(dx, dy))
                continue;
            const int i = int((body["x"].toDouble() - (fields.cell(0, 0)[2] - dx / 2)) / dx);
            const int j = int((body["y"].toDouble() - (fields.cell(0, 0)[3] - dy / 2)) / dy);
            if (i < 0 || i >= nx || j < 0 || j >= ny) continue;
            QVERIFY2(std::isnan(fields.cell(i, j)[4]), "a cell inside a body has a density");
        }

        // The inflow column, away from the sides, is the free stream. Pooled over those cells, the
        // standard errors come from the particle-steps sampled there, N = Σ n dx dy w / fn over the
        // window of w steps, divided by the steps a particle stays in a cell (dx / (U dt)), since those
        // samples repeat the same molecules: u_x ± σ/√N_eff, T ± T √(2/(3 N_eff)), n ± n/√N_eff; five
        // standard errors.
        const double U = params["stream_speed"].toDouble(), T = params["stream_temperature"].toDouble();
        const double n = params["stream_density"].toDouble(), fn = params["fn"].toDouble();
        const double mass = params["mass_amu"].toDouble() * 1.66053906660e-27;
        const double window = kSteps - kSampleStart;
        double sumN = 0, sumUx = 0, sumT = 0, cells = 0;
        for (int j = ny / 4; j < 3 * ny / 4; ++j) {
            const auto& row = fields.cell(0, j);
            sumN += row[4], sumUx += row[5], sumT += row[7], cells += 1;
        }
        QVERIFY(cells > 0);
        const double samples = n * dx * dy * window * cells / fn;
        const double effective = samples / std::max(1.0, dx / (U * dt));
        const double sigma = std::sqrt(1.380649e-23 * T / mass);
        const QString summary = QString("n %1 (stream %2), ux %3 (%4), T %5 (%6), %7 independent samples")
                                    .arg(sumN / cells)
                                    .arg(n)
                                    .arg(sumUx / cells)
                                    .arg(U)
                                    .arg(sumT / cells)
                                    .arg(T)
                                    .arg(effective);
        QVERIFY2(effective > 100, qPrintable(summary));
        QVERIFY2(std::abs(sumN / cells - n) < 5 * n / std::sqrt(effective), qPrintable(summary));
        QVERIFY2(std::abs(sumUx / cells - U) < 5 * sigma / std::sqrt(effective), qPrintable(summary));
        QVERIFY2(std::abs(sumT / cells - T) < 5 * T * std::sqrt(2.0 / (3.0 * effective)),
                 qPrintable(summary));
    }

    // Stopped by SIGINT: the force rows sampled so far stay, and the fields of the window are written.
    void sigintKeepsTheFieldsAndForces() {
        QTemporaryDir dir;
        const QString fieldsPath = dir.filePath("fields.csv"), surfacePath = dir.filePath("surface.csv");
        QProcess p;
        p.start(PARTICLELAB_CLI,
                {"run", "tunnel-cylinder", "--steps", "1000000000", "--every", "2", "--set", "sample_start=1",
                 "--backend", "cpu", "--quiet", "--fields", fieldsPath, "--surface", surfacePath});
        QVERIFY(p.waitForStarted());
        QElapsedTimer clock;
        clock.start();
        while (readLines(surfacePath).size() < 4 && clock.elapsed() < 30000) QTest::qWait(50);
        QVERIFY2(readLines(surfacePath).size() >= 4, "no force rows were written while the run went on");
        ::kill(static_cast<pid_t>(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 130);
        for (const QString& row : readLines(surfacePath)) QCOMPARE(row.split(',').size(), 4);
        const Fields fields = readFields(fieldsPath);
        QVERIFY(fields.nx > 0 && fields.ny > 0);
        QCOMPARE(fields.rows.size(), std::size_t(fields.nx * fields.ny));
        std::size_t measured = 0;
        for (const auto& row : fields.rows) measured += std::isfinite(row[4]) ? 1 : 0;
        QVERIFY2(measured > fields.rows.size() / 2, "the stopped run's window holds no samples");
    }

    void scenesWithoutFieldsRefuseBeforeWriting_data() {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QString>("option");
        QTest::newRow("gas --fields") << "gas-write-up"
                                      << "--fields";
        QTest::newRow("gas --surface") << "gas-write-up"
                                       << "--surface";
        QTest::newRow("dsmc cell --fields") << "dsmc-write-up"
                                            << "--fields";
        QTest::newRow("fluid --surface") << "fluid-dam-break"
                                         << "--surface";
    }
    void scenesWithoutFieldsRefuseBeforeWriting() {
        QFETCH(QString, preset);
        QFETCH(QString, option);
        QTemporaryDir dir;
        const QString target = dir.filePath("asked.csv"), series = dir.filePath("series.csv"),
                      dump = dir.filePath("initial.csv");
        const auto r = runCli(
            {"run", preset, "--steps", "5", option, target, "--out", series, "--dump-initial", dump}, 30000);
        QVERIFY(!r.crashed && !r.timedOut);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("particlelab-cli: " + option) && r.err.contains("wind tunnel"),
                 qPrintable(r.err));
        // Nothing ran and nothing was written: the folder is as empty as it was.
        QCOMPARE(QDir(dir.path()).entryList(QDir::NoDotAndDotDot | QDir::AllEntries), QStringList());
    }

    // A preset or --set whose free stream collides more than a step can do is refused before the run,
    // as the DSMC cell refuses it, naming dt and a value that works (before, a huge cross-section sat
    // in its first step for minutes and a huge dt grew to gigabytes).
    void stepsTheTunnelCannotDoAreRefusedBeforeTheRun_data() {
        QTest::addColumn<QString>("set");
        QTest::newRow("huge cross-section") << "vhs_d_ref=1e-6";
        QTest::newRow("huge dt") << "dt=1000";
    }
    void stepsTheTunnelCannotDoAreRefusedBeforeTheRun() {
        QFETCH(QString, set);
        QTemporaryDir dir;
        const QString series = dir.filePath("series.csv");
        const auto r = runCli({"run", "tunnel-cylinder", "--set", set, "--steps", "2", "--every", "1",
                               "--threads", "1", "--out", series},
                              30000);
        QVERIFY(!r.crashed && !r.timedOut);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("times per molecule and step") && r.err.contains("use dt ≤"),
                 qPrintable(r.err));
        QVERIFY(!QFile::exists(series));
    }

    // A step of 2.4 M molecules takes seconds: SIGINT in the middle of it undoes the step and ends the run
    // within a second, at the last whole step, with its rows (before: the signal waited for the step).
    void aSignalEndsALongStepWithinASecond() {
        QTemporaryDir dir;
        const QString series = dir.filePath("series.csv");
        QProcess p;
        p.start(PARTICLELAB_CLI,
                {"run", "tunnel-cylinder", "--set", "fn=1e13", "--set", "vhs_d_ref=5.3e-9", "--steps", "3",
                 "--every", "1", "--threads", "1", "--backend", "cpu", "--quiet", "--out", series});
        QVERIFY(p.waitForStarted());
        QElapsedTimer clock;
        clock.start();
        while (readLines(series).size() < 2 && clock.elapsed() < 60000) QTest::qWait(20); // the set-up's row
        QCOMPARE(readLines(series).size(), 2);
        QTest::qWait(300); // well inside the first step
        QCOMPARE(p.state(), QProcess::Running);
        ::kill(static_cast<pid_t>(p.processId()), SIGINT);
        QElapsedTimer stopping;
        stopping.start();
        QVERIFY(p.waitForFinished(60000));
        const qint64 ms = stopping.elapsed();
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitCode(), 130);
        // The second is the release build's promise; under .ci/sanitize.sh every memory access is checked,
        // which makes undoing the step (copying the 2.4 M molecules back) about three times slower.
        const qint64 bound = qEnvironmentVariableIsSet("ASAN_OPTIONS") ? 3000 : 1000;
        QVERIFY2(ms < bound, qPrintable(QString("the run took %1 ms to stop").arg(ms)));
        QVERIFY2(err.contains("stopped by SIGINT at step 0") && err.contains("the 1 row sampled"),
                 qPrintable(err));
        QCOMPARE(readLines(series).size(), 2);
    }

    // A run resumed from a snapshot taken with the fields window open writes the fields, the forces and
    // the rows of the run that never stopped (before: every cell NaN, drag_avg and sampled_steps from 0,
    // no drag in the first row).
    void resumedRunKeepsItsFieldsAndRows_data() {
        QTest::addColumn<QString>("preset");
        QTest::newRow("cylinder") << "tunnel-cylinder";
        QTest::newRow("shock tube") << "tunnel-shock-tube";
    }
    void resumedRunKeepsItsFieldsAndRows() {
        QFETCH(QString, preset);
        QTemporaryDir dir;
        const QString snapshot = dir.filePath("at20.plsnap");
        const QStringList common{"--every", "5", "--set", "sample_start=5", "--threads", "1", "--quiet"};
        const auto first =
            runCli(QStringList{"run", preset, "--steps", "20", "--snapshot", snapshot} + common);
        QCOMPARE(first.exitCode, 0);
        const auto resumed =
            runCli(QStringList{"run", snapshot, "--steps", "10", "--out", dir.filePath("b.csv"), "--fields",
                               dir.filePath("b-fields.csv")} +
                   common.mid(0, 2) + common.mid(4));
        QCOMPARE(resumed.exitCode, 0);
        const auto whole = runCli(QStringList{"run", preset, "--steps", "30", "--out", dir.filePath("c.csv"),
                                              "--fields", dir.filePath("c-fields.csv")} +
                                  common);
        QCOMPARE(whole.exitCode, 0);
        const QStringList fields = readLines(dir.filePath("b-fields.csv"));
        QVERIFY(fields.size() > 100);
        QVERIFY2(fields == readLines(dir.filePath("c-fields.csv")), "the resumed run's fields differ");
        const QStringList rows = readLines(dir.filePath("b.csv")),
                          wholeRows = readLines(dir.filePath("c.csv"));
        QCOMPARE(rows.size(), 1 + 3);                                      // the header and steps 20, 25, 30
        QCOMPARE(rows, QStringList{wholeRows.front()} + wholeRows.mid(5)); // steps 0, 5, 10, 15 before
    }
};

QTEST_GUILESS_MAIN(TestCliTunnel)
#include "tst_cli_tunnel.moc"
