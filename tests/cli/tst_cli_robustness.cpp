// One test per defect the CLI had: bad options (exit 2 with a sentence), blow-ups caught at the row and
// at the end, DSMC runs it cannot do in reasonable time, output files (links, FIFOs, devices,
// permissions, paths checked first), rows kept when a run is stopped by a signal, strict input syntax.
#include "CliRunner.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

using pl::test::runCli;

namespace {

QStringList readLines(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
}

void writeFile(const QString& path, const QByteArray& text) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

// A stopped run: the series file has rows, every row whole, the final outputs are written, then the
// signal ends it cleanly with one line that names it; the snapshot continues.
void stopRunWith(int signal, int expectedExit) {
    QTemporaryDir dir;
    const QString series = dir.filePath("s.csv"), hist = dir.filePath("h.csv"),
                  final = dir.filePath("final.csv"), snapshot = dir.filePath("end.plsnap");
    QProcess p;
    p.start(PARTICLELAB_CLI,
            {"run", "gas-classroom", "--steps", "1000000000", "--every", "5", "--out", series, "--histogram",
             hist, "--dump-final", final, "--snapshot", snapshot, "--quiet", "--threads", "1"});
    QVERIFY(p.waitForStarted());
    QElapsedTimer clock;
    clock.start();
    while (readLines(series).size() < 4 && clock.elapsed() < 30000) QTest::qWait(50); // rows as sampled
    QVERIFY2(readLines(series).size() >= 4, "no rows were written while the run went on");
    ::kill(static_cast<pid_t>(p.processId()), signal);
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), expectedExit);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QVERIFY2(err.startsWith("particlelab-cli: stopped by SIG") && err.count('\n') == 1 &&
                 err.contains("rows sampled until then are kept"),
             qPrintable(err));
    const QStringList rows = readLines(series);
    const qsizetype columns = rows[0].split(',').size();
    for (const QString& row : rows) QCOMPARE(row.split(',').size(), columns);
    QVERIFY(readLines(hist).size() > 1);  // the final histogram of what was measured
    QVERIFY(readLines(final).size() > 1); // the particles where the run stopped
    const auto resumed = runCli({"run", snapshot, "--steps", "1", "--quiet"});
    QVERIFY2(resumed.exitCode == 0, qPrintable(resumed.err));
}

// Whether process pid has a handler of its own for signal: Linux lists the caught signals as a hex mask
// on the SigCgt line of /proc/PID/status (bit signal − 1).
bool catchesSignal(qint64 pid, int signal) {
    QFile status(QString("/proc/%1/status").arg(pid));
    if (!status.open(QIODevice::ReadOnly)) return false;
    for (const QByteArray& line : status.readAll().split('\n'))
        if (line.startsWith("SigCgt:"))
            return (line.mid(7).trimmed().toULongLong(nullptr, 16) >> (signal - 1)) & 1u;
    return false;
}

} // namespace

class TestCliRobustness : public QObject {
    Q_OBJECT
private slots:
    void badOptionsAreExit2WithASentence_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QStringList run{"run", "gas-write-up", "--quiet"};
        QTest::newRow("threads 0") << run + QStringList{"--threads", "0"} << "--threads: must be from 1 to";
        QTest::newRow("threads 5000") << run + QStringList{"--threads", "5000"} << "4 × the";
        QTest::newRow("threads 100000")
            << run + QStringList{"--threads", "100000"} << "cores of this machine";
        QTest::newRow("steps -5") << run + QStringList{"--steps", "-5"}
                                  << "--steps: must be from 0 to 1000000000";
        QTest::newRow("steps 1e12") << run + QStringList{"--steps", "1e12"} << "days of computing";
        QTest::newRow("steps 2.5") << run + QStringList{"--steps", "2.5"} << "must be a whole number";
        QTest::newRow("steps abc") << run + QStringList{"--steps", "abc"} << "must be a whole number";
        QTest::newRow("every 0") << run + QStringList{"--every", "0"} << "--every: must be from 1";
        QTest::newRow("huge steps") << run + QStringList{"--steps", QString(309, '9')} << "(309 characters)";
        QTest::newRow("unknown flag") << run + QStringList{"--bogus"} << "not expected: --bogus";
        QTest::newRow("no subcommand") << QStringList{} << "A subcommand is required";
        QTest::newRow("empty out") << run + QStringList{"--out", ""} << "--out: needs a file name";
        QTest::newRow("bench repeats")
            << QStringList{"bench", "gas-write-up", "--repeats", "0"} << "--repeats";
        QTest::newRow("relax particles") << QStringList{"relax", "--particles", "2"} << "from 4 to";
        QTest::newRow("stiffness 0") << QStringList{"sweep", "--stiffness", "0"} << "above 0";
        QTest::newRow("set with space")
            << run + QStringList{"--set", "dt= 1"} << "must be a number, got \" 1\"";
        QTest::newRow("set hexadecimal") << run + QStringList{"--set", "dt=0x10"} << "got \"0x10\"";
    }
    void badOptionsAreExit2WithASentence() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const auto r = runCli(args, 30000);
        QVERIFY(!r.crashed && !r.timedOut);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("particlelab-cli: ") && r.err.contains(message), qPrintable(r.err));
        QVERIFY2(!r.err.contains(QRegularExpression("\\d{25}")), qPrintable(r.err)); // no 309-digit bounds
        QVERIFY(r.err.size() < 600);
    }

    // The GPU benchmark answers bad options as the CLI does, before it looks for a GL context.
    void benchBadOptionsAreExit2WithASentence_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("force lanes 3") << QStringList{"--force-lanes", "3"} << "--force-lanes: 3 not in";
        QTest::newRow("repeats abc") << QStringList{"--repeats", "abc"} << "--repeats";
        QTest::newRow("unknown scene") << QStringList{"--scenes", "plasma"} << "--scenes: plasma not in";
        QTest::newRow("unknown flag") << QStringList{"--bogus"} << "--bogus";
        QTest::newRow("gas -5") << QStringList{"--gas", "-5"} << "--gas: must be from 1 to 67108864";
        QTest::newRow("gas 0") << QStringList{"--gas", "4096", "0"} << "--gas: must be from 1 to";
        QTest::newRow("gas 1e20") << QStringList{"--gas", "99999999999999999999"}
                                  << "--gas: must be from 1 to";
        QTest::newRow("fluid 0") << QStringList{"--fluid", "0"} << "--fluid: must be from 1 to";
        QTest::newRow("tunnel 0") << QStringList{"--tunnel", "0"} << "--tunnel: must be from 1 to";
        QTest::newRow("repeats 0") << QStringList{"--repeats", "0"} << "--repeats: must be from 1 to";
        QTest::newRow("repeats -1") << QStringList{"--repeats", "-1"} << "--repeats: must be from 1 to";
        QTest::newRow("seconds -1") << QStringList{"--seconds", "-1"}
                                    << "--seconds: must be a finite number above 0";
        QTest::newRow("seconds nan") << QStringList{"--seconds", "nan"}
                                     << "--seconds: must be a finite number";
        QTest::newRow("seconds 0") << QStringList{"--seconds", "0"}
                                   << "--seconds: must be a finite number above 0";
        QTest::newRow("seconds 1e9") << QStringList{"--seconds", "1e9"} << "and at most 60";
        QTest::newRow("settle -1") << QStringList{"--settle", "-1"}
                                   << "--settle: must be a finite number of at least 0";
        QTest::newRow("settle inf") << QStringList{"--settle", "inf"} << "--settle: must be a finite number";
        QTest::newRow("cpu-max -1") << QStringList{"--cpu-max", "-1"} << "--cpu-max: must be from 0 to";
    }
    void benchBadOptionsAreExit2WithASentence() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const auto r = pl::test::runProgram(PARTICLELAB_BENCH, args, 30000);
        QVERIFY2(r.startError.isEmpty(), qPrintable(r.startError));
        QVERIFY(!r.crashed && !r.timedOut);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("particlelab-bench: ") && r.err.contains(message), qPrintable(r.err));
        QVERIFY2(r.out.isEmpty(), qPrintable(r.out)); // nothing measured, no JSON line
    }

    // Both ends of each advertised range pass the points' check (the fluid's 1 and 8388096 were refused:
    // a box narrower than 4 h, a box wider than box_width allows). The file is checked after the points,
    // so an unwritable --out ends the run there (exit 4) without a GL context or a sweep.
    void benchRangeEndsPassThePointCheck_data() {
        QTest::addColumn<QString>("option");
        QTest::addColumn<QString>("scene");
        for (const char* scene : {"gas", "fluid", "tunnel"})
            QTest::newRow(scene) << QString("--") + scene << scene;
    }
    void benchRangeEndsPassThePointCheck() {
        QFETCH(QString, option);
        QFETCH(QString, scene);
        const auto help = pl::test::runProgram(PARTICLELAB_BENCH, {"--help"}, 30000);
        const QRegularExpressionMatch range =
            QRegularExpression(option + R"( UINT:INT in (\d+)…(\d+))").match(help.out);
        QVERIFY2(range.hasMatch(), qPrintable(help.out));
        const auto r = pl::test::runProgram(PARTICLELAB_BENCH,
                                            {"--scenes", scene, option, range.captured(1), range.captured(2),
                                             "--out", "/proc/no-such/bench.jsonl"},
                                            30000);
        QVERIFY2(r.exitCode == 4 && r.err.contains("cannot write"), qPrintable(r.err));
    }

    // The benchmark's file is checked before the sweep: a directory, /proc or a FIFO used to exit 0 having
    // written nothing (or to block on the FIFO).
    void benchOutIsCheckedBeforeTheSweep() {
        QTemporaryDir dir;
        const QString fifo = dir.filePath("fifo");
        QVERIFY(::mkfifo(fifo.toUtf8().constData(), 0644) == 0);
        for (const QString& path : {dir.path(), QString("/proc/particlelab-bench.json"), fifo}) {
            const auto r = pl::test::runProgram(
                PARTICLELAB_BENCH,
                {"--scenes", "gas", "--gas", "64", "--cpu-max", "0", "--repeats", "1", "--out", path}, 20000);
            QVERIFY2(r.startError.isEmpty(), qPrintable(r.startError));
            QVERIFY2(!r.crashed && !r.timedOut, qPrintable(path));
            QCOMPARE(r.exitCode, 4);
            QVERIFY2(r.err.startsWith("particlelab-bench: ") && r.err.contains(path), qPrintable(r.err));
            QCOMPARE(r.err.count('\n'), 1);
            QVERIFY2(r.out.isEmpty(), qPrintable(r.out)); // nothing measured
        }
        QVERIFY(QFileInfo(fifo).exists() && !QFileInfo(fifo).isFile()); // the FIFO is still a FIFO
    }

    void helpStaysExit0() {
        const auto r = runCli({"run", "--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("--threads"));
    }

    // A snapshot that is valid JSON but holds a null velocity or time used to run on with NaN rows.
    void snapshotWithANullIsRefused() {
        QTemporaryDir dir;
        const QString good = dir.filePath("good.json");
        QCOMPARE(runCli({"run", "gas-classroom", "--steps", "5", "--quiet", "--snapshot", good}).exitCode, 0);
        QFile in(good);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray text = in.readAll();
        const auto refusedWith = [&](const QRegularExpression& field, const QString& entry) {
            QByteArray broken = QString::fromUtf8(text).replace(field, "\\1null").toUtf8();
            QVERIFY2(broken != text, qPrintable(field.pattern()));
            const QString path = dir.filePath("broken.json");
            writeFile(path, broken);
            const QString series = dir.filePath("s.csv");
            const auto r = runCli({"run", path, "--steps", "5", "--quiet", "--out", series});
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains(entry) && r.err.contains("not a finite number"), qPrintable(r.err));
            QVERIFY(!QFile::exists(series));
        };
        refusedWith(QRegularExpression(R"(("vx":\s*\[\s*)[-0-9.eE+]+)"), "state.vx");
        refusedWith(QRegularExpression(R"(("time":\s*)[-0-9.eE+]+)"), "state.time");
    }

    void blowUpAtTheLastStepIsNotExit0() {
        const auto r = runCli({"run", "gas-classroom", "--steps", "63", "--set", "dt=0.002", "--set",
                               "stiffness=1e6", "--quiet", "--allow-unstable"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains("the total energy grew") && r.err.contains("at step 63"), qPrintable(r.err));
    }

    void noExplodedRowIsWritten() {
        QTemporaryDir dir;
        const QString series = dir.filePath("s.csv");
        const auto r = runCli({"run", "gas-classroom", "--steps", "64", "--every", "1", "--set", "dt=0.002",
                               "--set", "stiffness=1e6", "--out", series, "--quiet", "--allow-unstable"});
        QCOMPARE(r.exitCode, 3);
        QStringList rows = readLines(series);
        QVERIFY2(rows.value(0).startsWith("# warning: dt·ω = 2.83 > 2.00"), qPrintable(rows.value(0)));
        rows.removeFirst(); // the warning the insisting flag writes
        QVERIFY(rows.size() > 2);
        const int total = int(rows[0].split(',').indexOf("total"));
        const double first = rows[1].split(',')[total].toDouble();
        for (const QString& row : rows.mid(1)) {
            const double e = row.split(',')[total].toDouble();
            QVERIFY2(std::isfinite(e) && e <= 100 * first, qPrintable(row)); // within the runaway bound
        }
    }

    void rk4HintComparesWithTheUnroundedLimit() {
        const auto inside = runCli({"run", "gas-classroom", "--steps", "200", "--set", "integrator=rk4",
                                    "--set", "stiffness=1e6", "--set", "dt=0.0019996", "--quiet"});
        QCOMPARE(inside.exitCode, 3);
        QVERIFY2(inside.err.contains("dt·ω = 2.8279 is inside the stability limit 2.8284"),
                 qPrintable(inside.err));
        const auto outside =
            runCli({"run", "gas-classroom", "--steps", "200", "--set", "integrator=rk4", "--set",
                    "stiffness=1e6", "--set", "dt=0.0020001", "--quiet", "--allow-unstable"});
        QCOMPARE(outside.exitCode, 3);
        QVERIFY2(outside.err.contains("dt·ω = 2.829 > 2.828: rk4 is unstable"), qPrintable(outside.err));
    }

    // A dt·ω equal to RK4's limit 2√2 used to read "2.82842712474619029 is inside the stability limit
    // 2.82842712474619029": shown to 4 decimals, it is at the limit, and the hint says so.
    void rk4HintAtTheLimitSaysItIsAtTheLimit() {
        const auto r = runCli({"run", "gas-classroom", "--steps", "200", "--set", "integrator=rk4", "--set",
                               "stiffness=1e6", "--set", "dt=0.002", "--quiet"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains("dt·ω = 2.8284 is at the stability limit 2.8284 of rk4") &&
                     r.err.contains("use |dt| < 0.0018"),
                 qPrintable(r.err));
        QVERIFY2(!r.err.contains(QRegularExpression("\\d\\.\\d{5}")), qPrintable(r.err)); // few digits
        QVERIFY2(!r.err.contains("inside"), qPrintable(r.err));
    }

    void dsmcRefusesWhatItCannotDoInTime() {
        QElapsedTimer clock;
        clock.start();
        const auto r = runCli({"run", "dsmc-bkw", "--set", "dt=3.33", "--steps", "1", "--quiet"}, 30000);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("collisions per particle and step") &&
                     r.err.contains("use dt ≤ 8.33e-05 s") && r.err.contains("fn ≤"),
                 qPrintable(r.err));
        const auto huge =
            runCli({"run", "dsmc-write-up", "--set", "fn=9223372036854775807", "--steps", "1"}, 30000);
        QCOMPARE(huge.exitCode, 2);
        QVERIFY(clock.elapsed() < 20000); // refused before any step, not after a 27 s one
    }

    // A fluid fill far larger than its tank is refused at once, also when the backend is chosen by the
    // particle count (before, counting the 1e10 grid points of the fill took minutes).
    void fluidFillLargerThanTheTankIsRefusedAtOnce() {
        QElapsedTimer clock;
        clock.start();
        const auto r = runCli({"run", "fluid-write-up", "--set", "fill_x1=1e5", "--set", "fill_y1=1e5",
                               "--backend", "auto", "--steps", "1", "--quiet"},
                              30000);
        QVERIFY(!r.timedOut);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("initial block must lie inside the box"), qPrintable(r.err));
        QVERIFY2(clock.elapsed() < 5000, qPrintable(QString::number(clock.elapsed()) + " ms"));
    }

    // Thousands of tunnel bodies: refused before the run with how many a step can take (before, the
    // set-up took 42 s and each step 3.5 s); as many as allowed build and step at once.
    void tunnelBodiesAStepCannotTakeAreRefused() {
        QTemporaryDir dir;
        const auto withBodies = [&](int count) {
            QString bodies;
            for (int k = 0; k < count; ++k)
                bodies += QString(R"(%1{"shape": "disc", "x": %2, "y": %3, "radius": 0.0005})")
                              .arg(k ? ", " : "")
                              .arg(0.002 + 0.096 * ((k * 37) % 1000) / 1000.0)
                              .arg(0.002 + 0.046 * ((k * 91) % 997) / 997.0);
            const QString path = dir.filePath(QString("bodies%1.json").arg(count));
            writeFile(path, QString(R"({"schema": 3, "model": "tunnel", "seed": 1,
                "params": {"box_width": 0.1, "box_height": 0.05, "cells_x": 100, "cells_y": 50, "fn": 1.0001e14},
                "obstacles": [%1]})")
                                .arg(bodies)
                                .toUtf8());
            return path;
        };
        QElapsedTimer clock;
        clock.start();
        const auto refused = runCli({"run", withBodies(5000), "--steps", "2", "--quiet"}, 30000);
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains("body tests a step") && refused.err.contains("use at most 1000 bodies"),
                 qPrintable(refused.err));
        QVERIFY2(clock.elapsed() < 5000, qPrintable(QString::number(clock.elapsed()) + " ms"));
        clock.restart();
        const auto allowed = runCli({"run", withBodies(1000), "--steps", "2", "--quiet"}, 30000);
        QVERIFY2(allowed.exitCode == 0, qPrintable(allowed.err));
        QVERIFY2(clock.elapsed() < 20000, qPrintable(QString::number(clock.elapsed()) + " ms"));
    }

    void dsmcWarnsWhenInaccurate() {
        const auto r = runCli({"run", "dsmc-bkw", "--set", "dt=6.67e-4", "--steps", "2", "--quiet"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains("warning: ν Δt is up to 2 collisions per particle and step, above Bird's"),
                 qPrintable(r.err));
        QVERIFY(!runCli({"run", "dsmc-bkw", "--steps", "2", "--quiet"}).err.contains("warning"));
    }

    void outputsWriteThroughLinksAndKeepPermissions() {
        QTemporaryDir dir;
        const QString target = dir.filePath("target.csv"), link = dir.filePath("link.csv"),
                      hist = dir.filePath("h.csv"), histLink = dir.filePath("hl.csv");
        writeFile(target, "old\n");
        writeFile(hist, "old\n");
        QVERIFY(::chmod(target.toUtf8().constData(), 0600) == 0 &&
                ::chmod(hist.toUtf8().constData(), 0640) == 0);
        QVERIFY(QFile::link(target, link) && QFile::link(hist, histLink));
        const auto r = runCli({"run", "gas-write-up", "--steps", "2", "--every", "1", "--out", link,
                               "--histogram", histLink, "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFileInfo(link).isSymLink() && QFileInfo(histLink).isSymLink()); // links stay links
        QCOMPARE(readLines(target).size(), 1 + 3);
        QVERIFY(readLines(hist).size() > 1);
        struct stat st {};
        QVERIFY(::stat(target.toUtf8().constData(), &st) == 0);
        QCOMPARE(int(st.st_mode & 07777), 0600);
        QVERIFY(::stat(hist.toUtf8().constData(), &st) == 0);
        QCOMPARE(int(st.st_mode & 07777), 0640); // replaced atomically, permissions kept
    }

    void nonRegularTargetsAreRefusedBeforeTheRun() {
        QTemporaryDir dir;
        const QString fifo = dir.filePath("fifo");
        QVERIFY(::mkfifo(fifo.toUtf8().constData(), 0644) == 0);
        QElapsedTimer clock;
        clock.start();
        for (const QString& path : {fifo, QString("/dev/null"), dir.path(), QString("/nonexistent/s.csv")})
            for (const char* option : {"--out", "--histogram", "--dump-final"}) {
                const auto r = runCli({"run", "gas-write-up", "--steps", "1000000000", option, path}, 20000);
                QVERIFY2(!r.timedOut, qPrintable(path));
                QCOMPARE(r.exitCode, 4);
                QVERIFY2(r.err.contains(path), qPrintable(r.err));
            }
        QVERIFY(clock.elapsed() < 20000); // found before a 10⁹-step run, not after it
        QVERIFY(QFileInfo(fifo).exists() && !QFileInfo(fifo).isFile()); // the FIFO is still a FIFO
    }

    void staleTempFilesOfAKilledWriteAreRemoved() {
        QTemporaryDir dir;
        const QString hist = dir.filePath("h.csv"), stale = hist + ".tmp-AbC123",
                      fresh = hist + ".tmp-XyZ789", unrelated = hist + ".backup";
        for (const QString& f : {stale, fresh, unrelated}) writeFile(f, "half");
        QFile old(stale);
        QVERIFY(old.open(QIODevice::ReadWrite));
        QVERIFY(
            old.setFileTime(QDateTime::currentDateTime().addSecs(-3600), QFileDevice::FileModificationTime));
        old.close();
        QCOMPARE(runCli({"run", "gas-write-up", "--steps", "1", "--histogram", hist, "--quiet"}).exitCode, 0);
        QVERIFY(!QFileInfo::exists(stale));
        QVERIFY(QFileInfo::exists(fresh));     // may belong to a writer that is still alive
        QVERIFY(QFileInfo::exists(unrelated)); // not a temporary file's name
        QVERIFY(readLines(hist).size() > 1);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 3);
    }

    // A temporary file whose process is gone is removed by the next write to its file (or the check of an
    // output before a run), however young: it used to stay until a run at least 10 s later.
    void tempFilesOfADeadProcessAreRemovedWhateverTheirAge() {
        QProcess gone;
        gone.start("true");
        QVERIFY(gone.waitForStarted());
        const qint64 deadPid = gone.processId();
        QVERIFY(gone.waitForFinished());
        QTemporaryDir dir;
        const QString hist = dir.filePath("h.csv"), series = dir.filePath("s.csv");
        const QString dead = hist + QString(".tmp-%1-AbC123").arg(deadPid),
                      deadSeries = series + QString(".tmp-%1-XyZ789").arg(deadPid),
                      living = hist + QString(".tmp-%1-Qwe456").arg(::getpid());
        for (const QString& f : {dead, deadSeries, living}) writeFile(f, "half");
        const auto r =
            runCli({"run", "gas-seed", "--steps", "1", "--histogram", hist, "--out", series, "--quiet"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(!QFileInfo::exists(dead));
        QVERIFY(!QFileInfo::exists(deadSeries)); // the streamed series is checked before the run
        QVERIFY(QFileInfo::exists(living));      // its writer may still be writing
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 3);
    }

    // A signal while a large scene is set up used to end the process by the signal, saying nothing.
    void aSignalDuringSetUpEndsWithASentence_data() {
        QTest::addColumn<int>("signal");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("name");
        QTest::newRow("SIGINT") << int(SIGINT) << 130 << "SIGINT";
        QTest::newRow("SIGTERM") << int(SIGTERM) << 143 << "SIGTERM";
        QTest::newRow("SIGHUP") << int(SIGHUP) << 129 << "SIGHUP";
    }
    void aSignalDuringSetUpEndsWithASentence() {
        QFETCH(int, signal);
        QFETCH(int, exitCode);
        QFETCH(QString, name);
        QTemporaryDir dir;
        const QString series = dir.filePath("s.csv");
        QProcess p;
        // Seconds of set-up: the free stream of 2.5 M molecules placed before the first step.
        p.start(PARTICLELAB_CLI, {"run", "tunnel-cylinder", "--set", "fn=1.5e12", "--steps", "0", "--quiet",
                                  "--threads", "1", "--out", series});
        QVERIFY(p.waitForStarted());
        // The CLI catches the signals from the start of the set-up on: wait for that rather than for a
        // fixed time, which a loaded machine or a sanitizer build can outlast (then the signal ends the
        // process before it has a handler, as it would any program).
        QTRY_VERIFY_WITH_TIMEOUT(catchesSignal(p.processId(), signal), 30000);
        QTest::qWait(100); // into the set-up's seconds
        QElapsedTimer clock;
        clock.start();
        ::kill(static_cast<pid_t>(p.processId()), signal);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), exitCode);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.endsWith("particlelab-cli: stopped by " + name +
                              " while setting up the experiment; nothing was written\n"),
                 qPrintable(err));
        QVERIFY(clock.elapsed() < 1000); // at once, not after the set-up
        QVERIFY(!QFileInfo::exists(series));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 0);
    }

    // A preset or snapshot path that is no regular file is refused at once: a FIFO used to block the run,
    // /dev/zero to be read without bound.
    void inputsThatAreNotRegularFilesAreRefusedAtOnce() {
        QTemporaryDir dir;
        const QString fifo = dir.filePath("fifo.json");
        QVERIFY(::mkfifo(fifo.toUtf8().constData(), 0644) == 0);
        QElapsedTimer clock;
        clock.start();
        for (const QString& path : {fifo, QString("/dev/zero"), dir.path()})
            for (const char* command : {"run", "columns"}) {
                const auto r = runCli({command, path}, 10000);
                QVERIFY2(!r.timedOut && !r.crashed, qPrintable(path));
                QCOMPARE(r.exitCode, 2);
                QVERIFY2(r.err.startsWith("particlelab-cli: ") && r.err.contains("'" + path + "'") &&
                             r.err.contains("only regular files are read"),
                         qPrintable(r.err));
                QCOMPARE(r.err.count('\n'), 1);
            }
        QVERIFY(clock.elapsed() < 10000);
    }

    // Under a 1 GiB address-space limit, a state that could not fit is refused before anything is built,
    // naming the parameter and a value that fits, instead of ending in an allocation failure.
    void runsThatDoNotFitInMemoryAreRefused_data() {
        QTest::addColumn<QStringList>("sets");
        QTest::addColumn<QString>("advice");
        QTest::newRow("gas cap") << QStringList{"gas-classroom", "--set", "max_particles=20000000"}
                                 << "use max_particles ≤";
        QTest::newRow("fluid cap") << QStringList{"fluid-write-up", "--set", "max_particles=10000000"}
                                   << "use max_particles ≤";
        QTest::newRow("dsmc count") << QStringList{"dsmc-write-up", "--set", "count_a=60000000"}
                                    << "particles (count_a + count_b)";
        QTest::newRow("tunnel molecules")
            << QStringList{"tunnel-cylinder", "--set", "fn=5e11"} << "raise fn to at least";
    }
    void runsThatDoNotFitInMemoryAreRefused() {
        QFETCH(QStringList, sets);
        QFETCH(QString, advice);
        if (qEnvironmentVariableIsSet("ASAN_OPTIONS")) // .ci/sanitize.sh
            QSKIP(
                "AddressSanitizer reserves terabytes of address space for its shadow memory at start, so no "
                "program built with it starts under an address-space limit");
        QTemporaryDir dir;
        const QString series = dir.filePath("s.csv");
        QProcess p;
        p.start("/bin/sh",
                QStringList{"-c", "ulimit -v 1048576 && exec \"$0\" \"$@\"", PARTICLELAB_CLI, "run"} + sets +
                    QStringList{"--steps", "1", "--threads", "1", "--quiet", "--out", series});
        QVERIFY(p.waitForFinished(60000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QVERIFY2(p.exitCode() == 2, qPrintable(err));
        QVERIFY2(err.contains("memory") && err.contains(advice), qPrintable(err));
        QVERIFY(!QFile::exists(series));
    }

    // A file larger than a preset or snapshot may be is refused before it is read past its start, naming
    // the bound.
    void hugeInputFilesAreRefusedBeforeTheyAreRead() {
        QTemporaryDir dir;
        const QString huge = dir.filePath("huge.json"), big = dir.filePath("big.json");
        QFile hugeFile(huge), bigFile(big);
        QVERIFY(hugeFile.open(QIODevice::WriteOnly) && hugeFile.resize(qint64(1) << 30)); // sparse: no disk
        hugeFile.close();
        QVERIFY(bigFile.open(QIODevice::WriteOnly));
        bigFile.write(R"({"schema": 2, "model": "gas"})");
        QVERIFY(bigFile.resize(qint64(20) << 20)); // a valid preset, then 20 MiB of NUL bytes
        bigFile.close();
        QElapsedTimer clock;
        clock.start();
        const auto r = runCli({"run", huge, "--steps", "1"}, 20000);
        QCOMPARE(r.exitCode, 2);
        // No snapshot (it starts with a NUL byte): a preset, of at most 16 MiB; or, on a machine whose
        // memory reads no snapshot of 1 GiB, refused as a snapshot from its size.
        QVERIFY2(r.err.contains("'" + huge + "'") &&
                     (r.err.contains("holds 1 GiB, more than the 16 MiB that a preset file may hold") ||
                      r.err.contains("that this machine can read back as a snapshot now")),
                 qPrintable(r.err));
        QVERIFY2(clock.elapsed() < 3000, "the file was read"); // refused from its size
        const auto preset = runCli({"run", big, "--steps", "1"}, 20000);
        QCOMPARE(preset.exitCode, 2);
        QVERIFY2(preset.err.contains("holds 20 MiB, more than the 16 MiB that a preset file may hold"),
                 qPrintable(preset.err));
    }

    // JSON nested 200 000 deep used to overflow the stack (SIGSEGV) in the preset's migration or the
    // snapshot's copy of its preset.
    void deeplyNestedJsonIsRefusedNamingTheDepth_data() {
        QTest::addColumn<QByteArray>("json");
        const QByteArray deep = QByteArray(200000, '[') + QByteArray(200000, ']');
        QTest::newRow("preset") << QByteArray(R"({"schema":2,"model":"gas","params":{"dt":)") + deep + "}}";
        QTest::newRow("schema-1 preset")
            << QByteArray(R"({"schema":1,"model":"fluid","params":{"gravity_y":)") + deep + "}}";
        QTest::newRow("snapshot")
            << QByteArray(R"({"snapshot_schema":1,"preset":{"schema":2,"model":"gas","name":)") + deep +
                   R"(},"state":{"scalars":{},"arrays":{}}})";
        QTest::newRow("unbalanced") << QByteArray(200000, '{');
    }
    void deeplyNestedJsonIsRefusedNamingTheDepth() {
        QFETCH(QByteArray, json);
        QTemporaryDir dir;
        const QString path = dir.filePath("deep.json");
        writeFile(path, json);
        for (const char* command : {"run", "columns"}) {
            const auto r = runCli({command, path}, 30000);
            QVERIFY2(!r.crashed && !r.timedOut, qPrintable(r.err));
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains(path) && r.err.contains("more than 64 levels deep (line 1)"),
                     qPrintable(r.err));
            QCOMPARE(r.err.count('\n'), 1);
        }
    }

    // Two outputs on one file, or an output over what the command reads, used to lose data silently: the
    // series replaced by the histogram, two streams interleaved, the input preset overwritten.
    void outputsThatShareAFileAreRefusedBeforeTheRun_data() {
        QTest::addColumn<QStringList>("args"); // DIR is the test's folder
        QTest::addColumn<QString>("message");
        const QStringList gas{"run", "gas-seed", "--steps", "3", "--quiet"};
        const QStringList tunnel{"run", "tunnel-cylinder", "--steps", "3", "--quiet"};
        QTest::newRow("out and histogram")
            << gas + QStringList{"--out", "DIR/same.csv", "--histogram", "DIR/same.csv"}
            << "--out and --histogram name 'DIR/same.csv': one output would replace the other";
        QTest::newRow("out and surface")
            << tunnel + QStringList{"--out", "DIR/s.csv", "--surface", "DIR/s.csv"} << "--out and --surface";
        QTest::newRow("fields and snapshot, spelled apart")
            << tunnel + QStringList{"--snapshot", "DIR/f.csv", "--fields", "DIR/./f.csv"}
            << "--snapshot and --fields name 'DIR/f.csv' and 'DIR/./f.csv', which are one file";
        QTest::newRow("through a link")
            << gas + QStringList{"--histogram", "DIR/target.csv", "--out", "DIR/link.csv"}
            << "--out and --histogram name 'DIR/link.csv' and 'DIR/target.csv', which are one file";
        QTest::newRow("through a link to a new file")
            << gas + QStringList{"--dump-initial", "DIR/newlink.csv", "--dump-final", "DIR/new.csv"}
            << "--dump-initial and --dump-final";
        QTest::newRow("through a linked folder")
            << gas + QStringList{"--dump-final", "DIR/sub/d.csv", "--out", "DIR/sublink/d.csv"}
            << "--out and --dump-final";
        QTest::newRow("over the input preset")
            << QStringList{"run", "DIR/mine.json", "--out", "DIR/mine.json"}
            << "--out and the input name 'DIR/mine.json': the output would "
               "replace what the run reads";
        QTest::newRow("over the input snapshot")
            << QStringList{"run", "DIR/snap.json", "--snapshot", "DIR/snap.json"}
            << "--snapshot and the input";
        QTest::newRow("sweep over its preset")
            << QStringList{"sweep", "--from", "DIR/gas.json", "--out", "DIR/gas.json"} << "--out and --from";
        QTest::newRow("import lammps")
            << QStringList{"import", "lammps", "DIR", "--out", "DIR/i.csv", "--histogram", "DIR/i.csv"}
            << "--out and --histogram";
        QTest::newRow("import over the log")
            << QStringList{"import", "sparta", "DIR", "--histogram", "DIR/log.sparta"}
            << "--histogram and the run's log";
    }
    void outputsThatShareAFileAreRefusedBeforeTheRun() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const auto withDir = [&](QString text) { return text.replace("DIR", dir.path()); };
        for (QString& arg : args) arg = withDir(arg);
        const QByteArray preset = R"({"schema": 2, "model": "gas", "name": "mine"})";
        writeFile(dir.filePath("mine.json"), preset);
        writeFile(dir.filePath("gas.json"), preset);
        writeFile(dir.filePath("target.csv"), "old\n");
        writeFile(dir.filePath("log.sparta"), "a log\n");
        QVERIFY(QFile::link(dir.filePath("target.csv"), dir.filePath("link.csv")));
        QVERIFY(QFile::link(dir.filePath("new.csv"), dir.filePath("newlink.csv")));
        QVERIFY(QDir(dir.path()).mkdir("sub") && QFile::link(dir.filePath("sub"), dir.filePath("sublink")));
        QCOMPARE(
            runCli({"run", "gas-seed", "--steps", "2", "--quiet", "--snapshot", dir.filePath("snap.json")})
                .exitCode,
            0);
        const auto contents = [&] {
            QStringList all;
            for (const QFileInfo& f : QDir(dir.path()).entryInfoList(QDir::Files | QDir::NoDotAndDotDot))
                all << f.fileName() + ":" + QString::number(f.size()) + ":" +
                           f.lastModified().toString(Qt::ISODateWithMs);
            return all;
        };
        const QStringList before = contents();
        const auto r = runCli(args, 30000);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("particlelab-cli: ") && r.err.contains(withDir(message)),
                 qPrintable(r.err));
        QCOMPARE(r.err.count('\n'), 1);
        QCOMPARE(contents(), before); // nothing written, nothing replaced
        QVERIFY(!QFileInfo::exists(dir.filePath("sub/d.csv")));
    }

    void memoryStaysFlatOverALongRun() {
        if (qEnvironmentVariableIsSet("ASAN_OPTIONS")) // .ci/sanitize.sh
            QSKIP("AddressSanitizer keeps freed memory in quarantine: resident memory grows by design");
        QTemporaryDir dir;
        const QString series = dir.filePath("s.csv");
        QProcess p;
        p.start(PARTICLELAB_CLI, {"run", "dsmc-write-up", "--steps", "100000", "--out", series, "--quiet"});
        QVERIFY(p.waitForStarted());
        const QString status = QString("/proc/%1/status").arg(p.processId());
        long long early = 0, peak = 0; // resident kB once a tenth of the rows is written, and the most
        while (!p.waitForFinished(50)) {
            QFile f(status);
            if (!f.open(QIODevice::ReadOnly)) continue;
            const QString text = QString::fromUtf8(f.readAll());
            const auto match = QRegularExpression("VmRSS:\\s+(\\d+) kB").match(text);
            if (!match.hasMatch()) continue;
            const long long rss = match.captured(1).toLongLong();
            if (early == 0 && readLines(series).size() > 10000) early = rss;
            if (early > 0) peak = std::max(peak, rss);
        }
        QCOMPARE(p.exitCode(), 0);
        QCOMPARE(readLines(series).size(), 1 + 100001);
        QVERIFY2(early > 0, "the run ended before it could be measured");
        // Every sampled row held in memory would be about 20 MB more here.
        QVERIFY2(peak - early < 4000, qPrintable(QString("%1 kB then %2 kB").arg(early).arg(peak)));
    }

    // Every signal a terminal or a session manager sends to stop a program keeps every output: SIGHUP (a
    // closed terminal) and SIGUSR1 used to end the run with rc 129 / 138 and no message, without the
    // histogram, the final particles or the snapshot.
    void aStopSignalKeepsEveryOutput_data() {
        QTest::addColumn<int>("signal");
        QTest::addColumn<int>("exitCode");
        QTest::newRow("SIGINT") << int(SIGINT) << 130;
        QTest::newRow("SIGTERM") << int(SIGTERM) << 143;
        QTest::newRow("SIGHUP") << int(SIGHUP) << 129;
        QTest::newRow("SIGQUIT") << int(SIGQUIT) << 131;
        QTest::newRow("SIGUSR1") << int(SIGUSR1) << 138;
        QTest::newRow("SIGUSR2") << int(SIGUSR2) << 140;
    }
    void aStopSignalKeepsEveryOutput() {
        QFETCH(int, signal);
        QFETCH(int, exitCode);
        stopRunWith(signal, exitCode);
    }

    // The benchmarks had no handler: a signal ended them at once with nothing said. The CLI's bench keeps
    // the repeats it finished (its line is printed from them) and says how many.
    void aStopSignalEndsTheBenchKeepingWhatItTimed() {
        QProcess p;
        p.start(PARTICLELAB_CLI,
                {"bench", "gas-write-up", "--steps", "200", "--repeats", "1000", "--threads", "1"});
        QVERIFY(p.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(catchesSignal(p.processId(), SIGHUP), 30000);
        QTest::qWait(3000); // the warm-up and some repeats
        ::kill(static_cast<pid_t>(p.processId()), SIGHUP);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 129);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.startsWith("particlelab-cli: stopped by SIGHUP; the ") &&
                     err.contains("of 1000 timed repeats"),
                 qPrintable(err));
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(out.startsWith("{\"preset\":\"gas-write-up\"") && out.contains("\"p_steps_per_s\""),
                 qPrintable(out));
    }

    // The GPU benchmark: a stop during the sweep ends it at the point being timed, with the points
    // measured before it printed and the usual exit code (on llvmpipe here).
    void aStopSignalEndsTheGpuBenchSweep() {
        QTemporaryDir dir;
        const QString out = dir.filePath("bench.jsonl");
        QProcess p;
        p.start(PARTICLELAB_BENCH, {"--scenes", "gas", "--gas", "1024", "4096", "--cpu-max", "0", "--seconds",
                                    "60", "--out", out});
        QVERIFY(p.waitForStarted());
        // Into the sweep: the context's line is written once the GL context and the copy bandwidth are there.
        QTRY_VERIFY_WITH_TIMEOUT(readLines(out).size() >= 1 || p.state() == QProcess::NotRunning, 120000);
        QVERIFY2(p.state() == QProcess::Running, qPrintable(QString::fromUtf8(p.readAllStandardError())));
        QTest::qWait(500);
        QElapsedTimer clock;
        clock.start();
        ::kill(static_cast<pid_t>(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(60000));
        QVERIFY2(clock.elapsed() < 20000,
                 qPrintable(QString::number(clock.elapsed()) + " ms")); // not a 60 s repeat
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 130);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(
            err.contains("particlelab-bench: stopped by SIGINT; the 0 points measured until then are kept"),
            qPrintable(err));
        QVERIFY2(readLines(out).value(0).contains("copy_bandwidth_bytes_per_s"),
                 qPrintable(readLines(out).value(0)));
    }

    // The step known to be unstable (dt·ω beyond the integrator's limit) used to run: 4 steps of velocity
    // Verlet at dt·ω = 4.47 exited 0 with the energy ×77 in its rows. It is refused before anything is
    // written, naming the values that fit; --allow-unstable runs it, saying so on stderr and in the file.
    void aStepKnownToBeUnstableIsRefused_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<QString>("dt");
        QTest::addColumn<QString>("message");
        QTest::newRow("velocity-verlet") << "velocity-verlet"
                                         << "0.01"
                                         << "dt·ω = 4.47 > 2.00: velocity-verlet";
        QTest::newRow("rk4") << "rk4"
                             << "0.01"
                             << "dt·ω = 4.47 > 2.83: rk4";
        QTest::newRow("symplectic-euler") << "symplectic-euler"
                                          << "0.01"
                                          << "dt·ω = 4.47 > 2.00";
        QTest::newRow("forest-ruth") << "forest-ruth"
                                     << "0.004"
                                     << "dt·ω = 1.79 > 1.57: forest-ruth";
    }
    void aStepKnownToBeUnstableIsRefused() {
        QFETCH(QString, integrator);
        QFETCH(QString, dt);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString series = dir.filePath("o.csv");
        const QStringList args{"run",       "gas-classroom",
                               "--set",     "integrator=" + integrator,
                               "--set",     "dt=" + dt,
                               "--steps",   "4",
                               "--every",   "1",
                               "--threads", "1",
                               "--quiet",   "--out",
                               series};
        const auto refused = runCli(args);
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains(message) && refused.err.contains("use dt ≤") &&
                     refused.err.contains("or stiffness ≤") && refused.err.contains("--allow-unstable"),
                 qPrintable(refused.err));
        QVERIFY(!QFile::exists(series));
        const auto insisted = runCli(args + QStringList{"--allow-unstable"});
        QVERIFY2(insisted.exitCode == 0 || insisted.exitCode == 3, qPrintable(insisted.err));
        QVERIFY2(insisted.err.contains("warning: " + message), qPrintable(insisted.err));
        const QStringList rows = readLines(series);
        QVERIFY2(rows.value(0).startsWith("# warning: " + message), qPrintable(rows.value(0)));
        QVERIFY(rows.value(1).startsWith("step,"));
    }

    // Within the limit nothing is refused: the classroom preset as shipped, and RK4 at its limit to the
    // decimals shown (the hint's case, which explains a blow-up rather than forbidding a run).
    void aStableStepIsNotRefused() {
        const auto shipped = runCli({"run", "gas-classroom", "--steps", "4", "--quiet"});
        QVERIFY2(shipped.exitCode == 0 && !shipped.err.contains("dt·ω"), qPrintable(shipped.err));
        const auto atTheLimit = runCli({"run", "gas-classroom", "--steps", "4", "--set", "integrator=rk4",
                                        "--set", "stiffness=1e6", "--set", "dt=0.002", "--quiet"});
        QVERIFY2(atTheLimit.exitCode != 2, qPrintable(atTheLimit.err));
    }

    // A full disk during --out used to leave half a row at the end of the file. A file-size limit stands
    // in for the full disk (write(2) then fails half way through a row, as on a full disk).
    void aFullDiskLeavesWholeRows() {
        QTemporaryDir dir;
        const QString series = dir.filePath("s.csv");
        QProcess p;
        // SIGXFSZ ignored: the write fails with EFBIG instead of ending the process, as ENOSPC would.
        p.start("/bin/sh", {"-c", "ulimit -f 8 && trap '' XFSZ && exec \"$0\" \"$@\"", PARTICLELAB_CLI, "run",
                            "gas-classroom", "--steps", "100000", "--every", "1", "--threads", "1", "--quiet",
                            "--out", series});
        QVERIFY(p.waitForFinished(60000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QVERIFY2(p.exitCode() == 4 && err.contains("cannot write"), qPrintable(err));
        QFile f(series);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY(text.size() > 1000 && text.size() <= 8 * 512);
        QVERIFY2(text.endsWith('\n'), text.right(80).constData());
        const QStringList rows = QString::fromUtf8(text).split('\n', Qt::SkipEmptyParts);
        QVERIFY(rows.size() > 3);
        for (const QString& row : rows) QCOMPARE(row.split(',').size(), rows[0].split(',').size());
    }

    // A snapshot's step of 1e19 or −1e308 used to be cast to an integer it does not fit (undefined
    // behaviour; the rows then read step −9.22e18); a piston direction of 1e300 the same.
    void integersReadFromASnapshotAreRangeChecked_data() {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("message");
        QTest::newRow("step 1e19") << "gas-classroom"
                                   << "step"
                                   << "1e19"
                                   << "state.step must be a whole number";
        QTest::newRow("step -1e308") << "gas-classroom"
                                     << "step"
                                     << "-1e308"
                                     << "state.step must be a whole number";
        QTest::newRow("step 2.5") << "fluid-dam-break"
                                  << "step"
                                  << "2.5"
                                  << "state.step must be a whole number";
        QTest::newRow("piston direction") << "tunnel-shock-tube"
                                          << "piston_direction"
                                          << "1e300"
                                          << "state.piston_direction must be −1, 0 or 1";
    }
    void integersReadFromASnapshotAreRangeChecked() {
        QFETCH(QString, preset);
        QFETCH(QString, key);
        QFETCH(QString, value);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString good = dir.filePath("good.plsnap");
        const auto saved = runCli({"run", preset, "--steps", "3", "--quiet", "--snapshot", good});
        QVERIFY2(saved.exitCode == 0, qPrintable(saved.err));
        QFile in(good);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(in.readAll());
        QString broken = text;
        broken.replace(QRegularExpression("(\"" + key + "\":\\s*)[-0-9.eE+]+"), "\\1" + value);
        QVERIFY(broken != text);
        const QString path = dir.filePath("broken.plsnap"), series = dir.filePath("s.csv");
        writeFile(path, broken.toUtf8());
        const auto r = runCli({"run", path, "--steps", "2", "--quiet", "--out", series});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(series));
    }

    // An obstacle over the whole box: the gas refused it (no room for the disks), the fluid ran empty and
    // the tunnel put molecules inside the solid (a drag of 65 N/m). Every kind refuses it.
    void bodiesThatLeaveNoRoomAreRefused_data() {
        QTest::addColumn<QString>("preset");
        QTest::newRow("fluid")
            << "{\"schema\": 3, \"model\": \"fluid\", \"seed\": 1, "
               "\"params\": {\"fill_x1\": 10, \"fill_y1\": 5}, \"obstacles\": [{\"shape\": "
               "\"box\", \"x\": 20, \"y\": 10, \"width\": 1000, \"height\": 1000}]}";
        QTest::newRow("tunnel")
            << "{\"schema\": 3, \"model\": \"tunnel\", \"seed\": 1, \"params\": "
               "{\"box_width\": 0.1, \"box_height\": 0.05, \"cells_x\": 20, \"cells_y\": 10, "
               "\"fn\": 1e15}, \"obstacles\": [{\"shape\": \"disc\", \"x\": 0.05, \"y\": "
               "0.025, \"radius\": 1}]}";
        QTest::newRow("gas") << "{\"schema\": 3, \"model\": \"gas\", \"seed\": 1, \"params\": "
                                "{\"count_a\": 10}, \"obstacles\": [{\"shape\": \"box\", \"x\": 0, \"y\": 0, "
                                "\"width\": 1000, \"height\": 1000}]}";
    }
    void bodiesThatLeaveNoRoomAreRefused() {
        QFETCH(QString, preset);
        QTemporaryDir dir;
        const QString path = dir.filePath("p.json");
        writeFile(path, preset.toUtf8());
        const auto r = runCli({"run", path, "--steps", "2", "--quiet"}, 30000);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("obstacles") && r.err.contains("no room"), qPrintable(r.err));
    }

    void duplicateKeysAreRefusedByPath_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        QTest::newRow("param twice") << QByteArray(
                                            R"({"schema":1,"model":"gas","params":{"dt":5,"dt":0.0001}})")
                                     << "duplicate key 'params.dt'";
        QTest::newRow("params twice")
            << QByteArray(R"({"schema":1,"model":"gas","params":{"dt":0.0001},"params":{}})")
            << "duplicate key 'params'";
        QTest::newRow("obstacle key twice")
            << QByteArray(
                   R"({"schema":1,"model":"gas","obstacles":[{},{"shape":"disc","x":0,"x":1,"y":0,"radius":0.1}]})")
            << "duplicate key 'obstacles[1].x'";
    }
    void duplicateKeysAreRefusedByPath() {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString path = dir.filePath("p.json");
        writeFile(path, json);
        const auto r = runCli({"run", path, "--steps", "1"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliRobustness)
#include "tst_cli_robustness.moc"
