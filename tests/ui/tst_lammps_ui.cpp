// File → Export to LAMMPS… and File → Open LAMMPS run… under a real X server: a small gas-write-up exports
// through the window's code path, refusals write nothing, LAMMPS runs the deck, and the run opens
// read-only in the docks (series rows, speed histogram with its Maxwell–Boltzmann curve) until a preset
// is opened again; Simulation → Run on LAMMPS… runs the deck in a worker and opens the result. A
// screenshot of the opened run is saved.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "panels/ParameterPanel.h"
#include "plots/DistributionPlot.h"
#include "plots/SeriesPlot.h"

#include <QDockWidget>
#include <QLabel>
#include <QProcess>
#include <QProgressDialog>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

using namespace pl;

namespace {

constexpr int kDisks = 400; // gas-write-up's box and disks, fewer of them: LAMMPS runs the deck in a blink

bool runLammps(const QString& dir, QString& output) {
    QProcess lmp;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("OMP_NUM_THREADS", "1");
    lmp.setProcessEnvironment(env);
    lmp.setWorkingDirectory(dir);
    lmp.setProcessChannelMode(QProcess::MergedChannels);
    lmp.start("lmp", {"-in", "in.lammps", "-log", "log.lammps"});
    const bool finished = lmp.waitForFinished(120000);
    output = QString::fromUtf8(lmp.readAll()).right(2000);
    return finished && lmp.exitStatus() == QProcess::NormalExit && lmp.exitCode() == 0;
}

int thermoRows(const QString& logPath) {
    QFile log(logPath);
    if (!log.open(QIODevice::ReadOnly)) return -1;
    int rows = 0;
    bool inTable = false;
    while (!log.atEnd()) {
        const QString line = QString::fromUtf8(log.readLine()).trimmed();
        if (line.startsWith("Step "))
            inTable = true;
        else if (line.startsWith("Loop time"))
            inTable = false;
        else if (inTable && !line.isEmpty())
            ++rows;
    }
    return rows;
}

QString statusText(ui::MainWindow& window) {
    QStringList texts;
    for (QLabel* label : window.statusBar()->findChildren<QLabel*>()) texts << label->text();
    return texts.join('\n');
}

} // namespace

class TestLammpsUi : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useCleanTestSettings(); }

    void init() {
        window_ = std::make_unique<ui::MainWindow>();
        QVERIFY(window_->openPreset("gas-write-up"));
        QVERIFY(window_->controller()->setParameters({{"count_a", static_cast<double>(kDisks)}}).isEmpty());
        window_->controller()->reset();
        QCOMPARE(window_->controller()->model()->particleCount(), std::size_t(kDisks));
        QVERIFY(test::showActive(*window_));
    }

    void cleanup() {
        window_->document()->setModified(false); // no "save changes?" question on close
        window_.reset();
    }

    void refusalNamesTheReasonAndWritesNothing() {
        QVERIFY(window_->controller()
                    ->setParameters({{"integrator", std::string("symplectic-euler")}})
                    .isEmpty());
        QTemporaryDir scratch;
        const QString dir = scratch.filePath("deck");
        const QString problem = window_->exportToLammps(dir);
        QVERIFY2(problem.contains("integrator symplectic-euler"), qPrintable(problem));
        QVERIFY(!QFileInfo::exists(dir));
    }

    void exportedRunOpensReadOnlyInTheDocks() {
        QTemporaryDir scratch;
        const QString dir = scratch.filePath("deck");
        QVERIFY2(window_->exportToLammps(dir).isEmpty(), "export refused");
        for (const char* file : {"in.lammps", "data.lammps", "particlelab.json"})
            QVERIFY2(QFileInfo::exists(dir + "/" + file), file);
        QVERIFY(window_->statusBar()->currentMessage().contains(dir));

        if (QStandardPaths::findExecutable("lmp").isEmpty())
            QSKIP("lmp not installed (.ci/install-deps.sh installs it)");
        QString output;
        QVERIFY2(runLammps(dir, output), qPrintable(output));
        const int rows = thermoRows(dir + "/log.lammps");
        QVERIFY(rows > 2);

        QVERIFY2(window_->openLammpsRun(dir).isEmpty(), "import failed");
        ui::SimulationController* controller = window_->controller();
        QVERIFY(controller->isReadOnly());
        QCOMPARE(controller->series()->rows(), std::size_t(rows));
        QCOMPARE(controller->model()->particleCount(), std::size_t(kDisks));
        QVERIFY(controller->model()->stepCount() > 0); // where the LAMMPS run ended
        QVERIFY(window_->document()->title().contains("LAMMPS"));

        // The energy dock plots every imported row; the histogram has bars and the theory curve.
        ui::SeriesPlot* energy = window_->seriesPlots().front();
        window_->findChild<QDockWidget*>(energy->spec().objectName + "Dock")->raise();
        QTest::qWait(50);
        QCPGraph* kinetic = energy->plot()->graph(0);
        QCOMPARE(kinetic->data()->size(), rows);
        QCustomPlot* histogram = window_->histogram()->plot();
        auto* bars = qobject_cast<QCPBars*>(histogram->plottable(0));
        QVERIFY(bars && bars->data()->size() > 10);
        QVERIFY(histogram->graphCount() >= 1);
        QCOMPARE(histogram->graph(0)->name(), QStringLiteral("Maxwell–Boltzmann"));

        // Read-only: Play and the parameters are off, and Space (the Play shortcut) does nothing.
        auto* play = window_->findChild<QAction*>("playAction");
        QVERIFY(play && !play->isEnabled());
        QVERIFY(!window_->parameters()->isEnabled());
        const auto step = controller->model()->stepCount();
        QTest::keyClick(window_->viewport(), Qt::Key_Space);
        QTest::keyClick(window_->viewport(), Qt::Key_Period);
        controller->play();
        QVERIFY(!controller->isRunning());
        QCOMPARE(controller->model()->stepCount(), step);
        QVERIFY(!controller->setParameters({{"dt", 2e-4}}).isEmpty());
        QTest::qWait(300); // the status line refreshes on its timer
        QVERIFY2(statusText(*window_).contains("LAMMPS run in"), qPrintable(statusText(*window_)));

        QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
        QVERIFY(window_->windowImage().save(QString(PARTICLELAB_SCREENSHOT_DIR) + "/lammps-run.png"));

        // Any preset returns to a running lab.
        QVERIFY(window_->openPreset("gas-write-up"));
        QVERIFY(!controller->isReadOnly());
        QVERIFY(play->isEnabled());
        QVERIFY(window_->parameters()->isEnabled());
        QTest::keyClick(window_->viewport(), Qt::Key_Period);
        QCOMPARE(controller->model()->stepCount(), 1);
    }

    void runOnLammpsOpensTheRunWhenItEnds() {
        if (QStandardPaths::findExecutable("lmp").isEmpty() ||
            QStandardPaths::findExecutable("mpirun").isEmpty())
            QSKIP("lmp or mpirun not installed (.ci/install-deps.sh installs them)");
        QTemporaryDir scratch;
        const QString dir = scratch.filePath("run");
        QSignalSpy finished(window_.get(), &ui::MainWindow::lammpsRunFinished);
        QVERIFY(window_->runOnLammps(dir, 1).isEmpty());
        auto* progress = window_->findChild<QProgressDialog*>();
        QVERIFY(progress && progress->isVisible());
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished.front().front().toString().isEmpty(),
                 qPrintable(finished.front().front().toString()));
        QVERIFY(window_->controller()->isReadOnly());
        QVERIFY(window_->controller()->series()->rows() > 2);
        QCOMPARE(window_->controller()->model()->stepCount(), 1000); // gas-write-up's open-ended default run
    }

    void cancelEndsTheRunAndSaysSo() {
        // A stand-in mpirun that reports one thermo row and then runs until it is stopped.
        QTemporaryDir bin;
        for (const char* name : {"lmp", "mpirun"}) {
            QFile script(bin.filePath(name));
            QVERIFY(script.open(QIODevice::WriteOnly));
            script.write("#!/bin/sh\necho 'Step Time KinEng'\necho '250 0.025 200'\nexec sleep 60\n");
            script.close();
            script.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        }
        const QByteArray path = qgetenv("PATH");
        qputenv("PATH", bin.path().toUtf8() + ":" + path);
        QTemporaryDir scratch;
        QSignalSpy finished(window_.get(), &ui::MainWindow::lammpsRunFinished);
        const QString problem = window_->runOnLammps(scratch.filePath("run"), 1);
        // The worker finds mpirun on PATH when it starts it; the real PATH returns once the run ended.
        const auto restorePath = qScopeGuard([path] { qputenv("PATH", path); });
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        QPointer<QProgressDialog> progress = window_->findChild<QProgressDialog*>();
        QVERIFY(progress);
        QTRY_COMPARE(progress->value(), 250);
        QPushButton* cancel = progress->findChild<QPushButton*>();
        QVERIFY(cancel);
        test::MessageBoxAnswerer answerer; // the "did not open" message
        QElapsedTimer clock;
        clock.start();
        QTest::mouseClick(cancel, Qt::LeftButton);
        QVERIFY(finished.wait(20000));
        QVERIFY(clock.elapsed() < 20000); // not the stand-in's 60 s
        QVERIFY(finished.front().front().toString().contains("cancelled"));
        QVERIFY(!window_->controller()->isReadOnly());
        QTRY_VERIFY(!answerer.texts.isEmpty());
    }

    void brokenRunFolderIsRefused() {
        QTemporaryDir scratch;
        const QString problem = window_->openLammpsRun(scratch.path());
        QVERIFY(!problem.isEmpty());
        QVERIFY(!window_->controller()->isReadOnly());
        QCOMPARE(window_->controller()->model()->particleCount(), std::size_t(kDisks));
    }

private:
    std::unique_ptr<ui::MainWindow> window_;
};

QTEST_MAIN(TestLammpsUi)
#include "tst_lammps_ui.moc"
