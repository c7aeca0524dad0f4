// MainWindow's LAMMPS entries: the deck, the run and the import come from core/scaleout, as for
// `particlelab-cli export lammps`, `run-lammps` and `import lammps`; this file asks for folders, runs
// LAMMPS off the GUI thread and reports.
#include "ExperimentDocument.h"
#include "FileDialogs.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "scaleout/LammpsDeck.h"
#include "scaleout/LammpsImport.h"
#include "scaleout/LammpsRun.h"

#include <QInputDialog>
#include <QProgressDialog>
#include <QThread>
#include <algorithm>
#include <atomic>
#include <climits>
#include <memory>

#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

namespace pl::ui {

namespace {
constexpr int kNoticeMs = 10000;
} // namespace

void MainWindow::createLammpsActions(QMenu* file) {
    QAction* exportAction = file->addAction(tr("Export to &LAMMPS…"));
    exportAction->setObjectName("exportLammpsAction");
    exportAction->setStatusTip(tr("Write the gas in its current state as a LAMMPS deck into a folder"));
    connect(exportAction, &QAction::triggered, this, [this] {
        const QString dir =
            files::existingFolder(this, files::Place::Exports, tr("Export to LAMMPS: choose a folder"));
        if (dir.isEmpty()) return;
        const QString problem = exportToLammps(dir);
        if (!problem.isEmpty()) QMessageBox::warning(this, tr("Cannot export to LAMMPS"), problem);
    });
    QAction* openAction = file->addAction(tr("Open LAMMPS r&un…"));
    openAction->setObjectName("openLammpsRunAction");
    openAction->setStatusTip(tr("Show a LAMMPS run of an exported deck (log.lammps and its dump) read-only"));
    connect(openAction, &QAction::triggered, this, [this] {
        if (!document_->maybeSave()) return;
        const QString dir =
            files::existingFolder(this, files::Place::Exports,
                                  tr("Open LAMMPS run: choose the deck's folder after LAMMPS ran in it"));
        if (dir.isEmpty()) return;
        const QString problem = openLammpsRun(dir);
        if (!problem.isEmpty()) QMessageBox::warning(this, tr("Cannot open the LAMMPS run"), problem);
    });
}

QString MainWindow::writeLammpsDeck(const QString& dir, long long& steps) {
    const Model* model = controller_->model();
    if (!model) return tr("No experiment is loaded.");
    scaleout::Deck deck;
    try {
        const auto gas = scaleout::gasToExport(*model);
        const scaleout::LammpsExportOptions options = scaleout::defaultLammpsOptions(*gas);
        deck = scaleout::lammpsDeck(*gas, options);
        scaleout::writeDeck(deck, dir.toStdString());
        steps = options.steps;
    } catch (const std::exception& e) { // a refusal names what LAMMPS cannot reproduce
        return QString::fromUtf8(e.what());
    }
    statusBar()->showMessage(tr("Wrote the LAMMPS deck to %1; run it there with: %2")
                                 .arg(QDir::toNativeSeparators(dir), QString::fromStdString(deck.command)),
                             kNoticeMs);
    return {};
}

QString MainWindow::exportToLammps(const QString& dir) {
    long long steps = 0;
    return writeLammpsDeck(dir, steps);
}

QString MainWindow::openLammpsRun(const QString& dir) {
    scaleout::ImportedRun run;
    try {
        run = scaleout::importLammpsRun(dir.toStdString());
    } catch (const std::exception& e) {
        return QString::fromUtf8(e.what());
    }
    const Preset preset = run.final->toPreset();
    const QString folder = QDir(dir).absolutePath();
    controller_->showImported(std::move(run.final), std::move(run.series),
                              tr("LAMMPS run in %1").arg(QDir::toNativeSeparators(folder)));
    document_->adoptImported(preset, tr("LAMMPS run %1").arg(QFileInfo(folder).fileName()));
    statusBar()->clearMessage(); // the status line says where the data came from
    return {};
}

void MainWindow::createRunOnLammpsAction(QMenu* sim) {
    QAction* run = sim->addAction(tr("Run on &LAMMPS…"));
    run->setObjectName("runOnLammpsAction");
    run->setStatusTip(tr("Export the gas, run it with mpirun and LAMMPS, and open the run"));
    connect(run, &QAction::triggered, this, [this] {
        const QString dir =
            files::existingFolder(this, files::Place::Exports,
                                  tr("Run on LAMMPS: choose a folder for the deck and LAMMPS's output"));
        if (dir.isEmpty()) return;
        bool ok = false;
        const int ranks = QInputDialog::getInt(this, tr("Run on LAMMPS"), tr("MPI ranks:"), 2, 1,
                                               std::max(1, QThread::idealThreadCount()), 1, &ok);
        if (!ok) return;
        const QString problem = runOnLammps(dir, ranks);
        if (!problem.isEmpty()) QMessageBox::warning(this, tr("Cannot run LAMMPS"), problem);
    });
    connect(this, &MainWindow::lammpsRunFinished, this, [this](const QString& problem) {
        if (!problem.isEmpty()) QMessageBox::warning(this, tr("The LAMMPS run did not open"), problem);
    });
}

QString MainWindow::runOnLammps(const QString& dir, int ranks) {
    if (const std::string missing = scaleout::missingLammpsProgram(); !missing.empty())
        return tr("%1 is not installed: running on LAMMPS needs LAMMPS and MPI (Debian: apt install lammps "
                  "openmpi-bin).")
            .arg(QString::fromStdString(missing));
    long long steps = 0;
    if (const QString problem = writeLammpsDeck(dir, steps); !problem.isEmpty()) return problem;
    controller_->pause();

    auto* progress =
        new QProgressDialog(tr("LAMMPS runs %1 steps on %2 ranks…").arg(steps).arg(ranks), tr("Cancel"), 0,
                            static_cast<int>(std::min<long long>(steps, INT_MAX)), this);
    progress->setWindowTitle(tr("Run on LAMMPS"));
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(0);
    progress->setAutoClose(false);
    progress->setAutoReset(false);
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    auto result = std::make_shared<scaleout::LammpsRunResult>();
    connect(progress, &QProgressDialog::canceled, this, [cancel] { cancel->store(true); });
    const std::string folder = dir.toStdString();
    QThread* worker = QThread::create([progress, cancel, result, folder, ranks] {
        const auto onStep = [progress](long long step) {
            QMetaObject::invokeMethod(
                progress, [progress, step] { progress->setValue(static_cast<int>(step)); },
                Qt::QueuedConnection);
        };
        *result = scaleout::runLammps(folder, ranks, onStep, [cancel] { return cancel->load(); });
    });
    connect(worker, &QThread::finished, this, [this, worker, progress, result, dir] {
        worker->deleteLater();
        progress->deleteLater();
        QString problem;
        if (result->cancelled)
            problem = tr("The LAMMPS run was cancelled; its deck and output so far are in %1.")
                          .arg(QDir::toNativeSeparators(dir));
        else if (result->status != 0)
            problem = tr("LAMMPS failed (exit status %1) in %2; its last output:\n%3")
                          .arg(result->status)
                          .arg(QDir::toNativeSeparators(dir), QString::fromStdString(result->lastOutput));
        else
            problem = openLammpsRun(dir);
        emit lammpsRunFinished(problem);
    });
    progress->setValue(0);
    progress->show(); // now, not after the dialog's own estimate of the run's length
    worker->start();
    return {};
}

} // namespace pl::ui
