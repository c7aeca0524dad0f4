// Autosave: one snapshot file per running process, named by its process id, so two windows never
// overwrite each other and a file whose process is gone is known to be an orphan.
#include "Autosave.h"

#include "ExperimentDocument.h"
#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "common/Snapshot.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <csignal>

namespace pl::ui {

namespace {

const QString kPrefix = QStringLiteral("autosave-");

bool processRuns(qint64 pid) {
    return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
}

} // namespace

Autosave::Autosave(SimulationController* controller, ExperimentDocument* document, QWidget* dialogParent)
    : QObject(dialogParent), controller_(controller), document_(document), parent_(dialogParent) {
    timer_.setInterval(kIntervalMs);
    connect(&timer_, &QTimer::timeout, this, [this] {
        if (controller_->isRunning()) saveNow();
    });
    timer_.start();
}

QString Autosave::directory() {
    const QString state = qEnvironmentVariable("XDG_STATE_HOME");
    const QString base = state.isEmpty() ? QDir::home().filePath(".local/state") : state;
    return QDir(base).filePath(QStringLiteral("ParticleLab")); // the product's, whatever runs it
}

QString Autosave::path() const {
    return QDir(directory())
        .filePath(kPrefix + QString::number(QCoreApplication::applicationPid()) + ".json");
}

QString Autosave::saveNow() {
    const Model* model = controller_->model();
    if (!model || model->particleCount() > kMaxParticles) return {};
    if (model == savedModel_ && model->stepCount() == savedStep_) return {}; // nothing new
    if (!QDir().mkpath(directory())) return tr("Cannot create %1").arg(directory());
    try {
        Snapshot snapshot = takeSnapshot(*model);
        snapshot.preset.name = document_->title().toStdString();
        writeFileAtomically(path().toStdString(), serializeSnapshot(snapshot, model->paramSpecs()));
    } catch (const std::exception& e) {
        return QString::fromUtf8(e.what());
    }
    savedModel_ = model;
    savedStep_ = model->stepCount();
    return {};
}

bool Autosave::offerRestore() {
    const QDir dir(directory());
    QFileInfo newest;
    QStringList orphans;
    for (const QFileInfo& file : dir.entryInfoList({kPrefix + "*.json"}, QDir::Files, QDir::Time)) {
        const qint64 pid = file.completeBaseName().mid(kPrefix.size()).toLongLong();
        if (pid == QCoreApplication::applicationPid() || processRuns(pid)) continue;
        if (orphans.isEmpty()) newest = file; // sorted newest first
        orphans << file.absoluteFilePath();
    }
    if (orphans.isEmpty()) return false;
    const auto answer = QMessageBox::question(
        parent_, tr("Restore the last experiment?"),
        tr("ParticleLab did not close normally. Its last experiment was saved %1. Restore it?")
            .arg(QLocale().toString(newest.lastModified(), QLocale::ShortFormat)),
        QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
    bool restored = false;
    if (answer == QMessageBox::Yes) {
        try {
            const Snapshot snapshot =
                readSnapshotFile(newest.absoluteFilePath().toStdString(), specsForModel);
            restored = document_->restore(snapshot);
        } catch (const std::exception& e) {
            QMessageBox::warning(parent_, tr("Cannot restore the experiment"), QString::fromUtf8(e.what()));
        }
    }
    for (const QString& file : orphans) QFile::remove(file);
    return restored;
}

void Autosave::discard() {
    QFile::remove(path());
    savedModel_ = nullptr;
    savedStep_ = -1;
}

} // namespace pl::ui
