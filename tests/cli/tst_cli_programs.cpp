// The programs as a package's user meets them: --version with the project's version; with no display,
// the desktop app's --help and --version, a methods-lab page, and a window refused in one sentence;
// experiment (.particlelab) and snapshot (.plsnap) files opened by the CLI and the app.
#include "CliRunner.h"

#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QtTest>

using pl::test::CliResult;

namespace {

// Runs a program in an environment: the display variables removed, others set ("NAME=value"). The
// app's settings, recent files, presets and autosaves go to a folder of their own, not the user's.
CliResult runWithEnvironment(const QString& program, const QStringList& args, const QStringList& unset,
                             const QStringList& set = {}) {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    static const QTemporaryDir home;
    for (const char* name : {"XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_STATE_HOME", "XDG_CACHE_HOME"})
        environment.insert(name, home.filePath(name));
    for (const QString& name : unset) environment.remove(name);
    for (const QString& entry : set) environment.insert(entry.section('=', 0, 0), entry.section('=', 1));
    return pl::test::runProgram(program, args, 120000, {}, environment);
}

// Neither X, nor Wayland, nor a chosen Qt platform: a shell over ssh, a script, a package's build.
const QStringList kDisplayVariables{"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"};

int lineCount(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return -1;
    return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts).size();
}

} // namespace

class TestCliPrograms : public QObject {
    Q_OBJECT
private slots:
    void everyProgramPrintsTheProjectVersion_data() {
        QTest::addColumn<QString>("program");
        QTest::addColumn<QString>("name");
        QTest::newRow("particlelab-cli") << PARTICLELAB_CLI << "particlelab-cli";
        QTest::newRow("particlelab-bench") << PARTICLELAB_BENCH << "particlelab-bench";
#ifdef PARTICLELAB_GUI
        QTest::newRow("particlelab") << PARTICLELAB_GUI << "particlelab";
#endif
    }
    void everyProgramPrintsTheProjectVersion() {
        QFETCH(QString, program);
        QFETCH(QString, name);
        for (const char* option : {"--version", "--help"}) {
            const CliResult r = runWithEnvironment(program, {option}, kDisplayVariables);
            QVERIFY2(r.startError.isEmpty() && !r.crashed && !r.timedOut, qPrintable(r.startError + r.err));
            QCOMPARE(r.exitCode, 0);
            if (QString(option) == "--version")
                QCOMPARE(r.out, name + " " + PARTICLELAB_VERSION + "\n");
            else
                QVERIFY2(r.out.contains("--version") && r.out.contains("--help"), qPrintable(r.out));
        }
    }

#ifdef PARTICLELAB_GUI
    // The app's whole help, printed without a display: every option it takes.
    void appHelpNeedsNoDisplay() {
        const CliResult r = runWithEnvironment(PARTICLELAB_GUI, {"--help"}, kDisplayVariables);
        QCOMPARE(r.exitCode, 0);
        for (const char* option : {"--lab", "--plot", "--backend", "--screenshot", "--frames", "--present"})
            QVERIFY2(r.out.contains(option), qPrintable(r.out));
        QVERIFY2(r.err.isEmpty(), qPrintable(r.err));
    }

    // A window without a display: one sentence on stderr and exit status 2, not Qt's abort.
    void appWithoutDisplaySaysSo() {
        for (const QStringList& args : {QStringList{}, QStringList{"gas-write-up", "--present"}}) {
            const CliResult r = runWithEnvironment(PARTICLELAB_GUI, args, kDisplayVariables);
            QVERIFY(!r.crashed && !r.timedOut);
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.startsWith("particlelab: there is no display") && r.err.count('\n') == 1,
                     qPrintable(r.err));
        }
    }

    // A methods-lab page draws no window: without a display it draws off screen and saves its plot.
    void labPageNeedsNoDisplay() {
        QTemporaryDir dir;
        const QString plot = dir.filePath("echo.png");
        const CliResult r =
            runWithEnvironment(PARTICLELAB_GUI, {"--lab", "echo", "--plot", plot}, kDisplayVariables);
        QVERIFY2(!r.crashed && r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(QFileInfo(plot).size() > 0, qPrintable(plot));
    }

    // The window opens an experiment and a snapshot by their own suffixes, as a file manager hands them
    // over (the .desktop file's %f). The offscreen platform needs no X server.
    void appOpensExperimentAndSnapshotFiles() {
        QTemporaryDir dir;
        const QString experiment = dir.filePath("classroom.particlelab"), snapshot = dir.filePath("s.plsnap");
        QVERIFY(
            QFile::copy(PARTICLELAB_TEST_DATA "/../../resources/presets/gas/gas-classroom.json", experiment));
        QCOMPARE(
            pl::test::runCli({"run", experiment, "--steps", "5", "--snapshot", snapshot, "--quiet"}).exitCode,
            0);
        for (const QString& file : {experiment, snapshot}) {
            const QString shot = file + ".png";
            const CliResult r =
                runWithEnvironment(PARTICLELAB_GUI, {file, "--screenshot", shot, "--frames", "2"},
                                   kDisplayVariables, {"QT_QPA_PLATFORM=offscreen"});
            QVERIFY2(!r.crashed && r.exitCode == 0, qPrintable(r.err));
            QVERIFY2(QFileInfo(shot).size() > 0, qPrintable(shot));
        }
    }
#endif

    // An experiment saved as .particlelab runs; a snapshot saved as .plsnap continues (and is read as a
    // snapshot: it refuses --set); .json presets keep working beside them.
    void cliReadsExperimentAndSnapshotFiles() {
        QTemporaryDir dir;
        const QString experiment = dir.filePath("classroom.particlelab"),
                      json = dir.filePath("classroom.json");
        for (const QString& copy : {experiment, json})
            QVERIFY(
                QFile::copy(PARTICLELAB_TEST_DATA "/../../resources/presets/gas/gas-classroom.json", copy));
        for (const QString& file : {experiment, json}) {
            const QString out = file + ".csv";
            const CliResult r =
                pl::test::runCli({"run", file, "--steps", "20", "--every", "10", "--out", out});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            QCOMPARE(lineCount(out), 1 + 3); // the header and steps 0, 10, 20
        }
        const QString snapshot = dir.filePath("s.plsnap"), continued = dir.filePath("continued.csv");
        CliResult r =
            pl::test::runCli({"run", experiment, "--steps", "10", "--snapshot", snapshot, "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = pl::test::runCli(
            {"run", snapshot, "--steps", "10", "--every", "10", "--out", continued, "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(lineCount(continued) > 1);
        r = pl::test::runCli({"run", snapshot, "--set", "dt=1e-4", "--steps", "5"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("is a snapshot"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliPrograms)
#include "tst_cli_programs.moc"
