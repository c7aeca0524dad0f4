// ExperimentDocument: the controller loads (and keeps the old model on failure); the document only
// tracks names, paths and the modified flag around it.
#include "ExperimentDocument.h"

#include "FileDialogs.h"
#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>

namespace pl::ui {

namespace {
constexpr int kMaxRecentFiles = 8;
const char* kRecentKey = "recentFiles";
} // namespace

ExperimentDocument::ExperimentDocument(SimulationController* controller, QWidget* dialogParent)
    : QObject(dialogParent), controller_(controller), parent_(dialogParent) {
    connect(controller, &SimulationController::edited, this, [this] { setModified(true); });
}

void ExperimentDocument::showError(const QString& what, const QString& message) const {
    QMessageBox::critical(parent_, what, message);
}

bool ExperimentDocument::open(const QString& nameOrPath, bool force) {
    if (!force && !maybeSave()) return false;
    Snapshot snapshot;
    bool isSnapshot = false;
    try {
        // The CLI's reader: regular files of bounded size and JSON of bounded depth (InputLimits.h).
        OpenedExperiment opened = openExperiment(nameOrPath.toStdString());
        snapshot = std::move(opened.snapshot);
        isSnapshot = opened.isSnapshot;
    } catch (const std::exception& e) {
        showError(tr("Cannot open preset"), QString::fromUtf8(e.what()));
        return false;
    }
    const Preset& preset = snapshot.preset;
    const bool isFile = QFileInfo::exists(nameOrPath) && !QFileInfo(nameOrPath).isDir();
    const QString label =
        preset.name.empty() ? QFileInfo(nameOrPath).completeBaseName() : QString::fromStdString(preset.name);
    if (!adopt(preset, isFile ? QFileInfo(nameOrPath).absoluteFilePath() : QString(), label,
               isSnapshot ? &snapshot.state : nullptr))
        return false;
    snapshotFile_ = isSnapshot;
    return true;
}

bool ExperimentDocument::restore(const Snapshot& snapshot) {
    const QString label =
        snapshot.preset.name.empty() ? tr("restored") : QString::fromStdString(snapshot.preset.name);
    if (!adopt(snapshot.preset, {}, label, &snapshot.state)) return false;
    setModified(true); // it lives in no file of the user's yet
    return true;
}

bool ExperimentDocument::saveSnapshotTo(const QString& path) {
    const Model* model = controller_->model();
    if (!model) return false;
    try {
        Snapshot snapshot = takeSnapshot(*model);
        snapshot.preset.name = QFileInfo(path).completeBaseName().toStdString();
        snapshot.preset.description = meta_.description;
        writeFileAtomically(path.toStdString(), serializeSnapshot(snapshot, model->paramSpecs()));
    } catch (const std::exception& e) {
        showError(tr("Cannot save snapshot"), QString::fromUtf8(e.what()));
        return false;
    }
    path_ = QFileInfo(path).absoluteFilePath();
    label_ = QFileInfo(path).completeBaseName();
    snapshotFile_ = true;
    modified_ = false;
    addRecent(path_);
    emit changed();
    return true;
}

bool ExperimentDocument::newExperiment(const std::string& kind) {
    if (!maybeSave()) return false;
    const ModelDescriptor* model = findModel(kind);
    if (!model) {
        showError(tr("Cannot create experiment"),
                  tr("Unknown scene '%1'.").arg(QString::fromStdString(kind)));
        return false;
    }
    Preset preset = defaultPreset(*model);
    preset.name = "untitled";
    return adopt(preset, {}, tr("untitled"));
}

bool ExperimentDocument::adopt(const Preset& preset, const QString& path, const QString& label,
                               const StateRecord* state) {
    const QString error = controller_->load(preset, state);
    if (!error.isEmpty()) {
        showError(tr("Cannot open preset"), error);
        return false;
    }
    meta_ = preset;
    path_ = path;
    label_ = label;
    modified_ = false;
    snapshotFile_ = false;
    if (!path.isEmpty()) addRecent(path);
    emit changed();
    return true;
}

void ExperimentDocument::adoptImported(const Preset& preset, const QString& label) {
    meta_ = preset;
    path_.clear();
    label_ = label;
    modified_ = false;
    snapshotFile_ = false;
    emit changed();
}

bool ExperimentDocument::save() {
    if (path_.isEmpty()) return saveAs();
    return snapshotFile_ ? saveSnapshotTo(path_) : saveTo(path_);
}

bool ExperimentDocument::saveAs() {
    QDir().mkpath(userPresetDirectory());
    // .particlelab: the experiment's own file type (resources/desktop/particlelab.xml), which opens in
    // ParticleLab from a file manager; the content is the same JSON as a .json preset's.
    const QString path =
        files::saveFileName(parent_, files::Place::Experiments, tr("Save preset"), label_ + ".particlelab",
                            tr("Experiments (*.particlelab);;Presets (*.json)"));
    return !path.isEmpty() && saveTo(path);
}

bool ExperimentDocument::saveTo(const QString& path) {
    const Model* model = controller_->model();
    if (!model) return false;
    Preset preset = controller_->experimentPreset(); // with the values that wait for Reset
    preset.name = QFileInfo(path).completeBaseName().toStdString();
    preset.description = meta_.description;
    try {
        writePresetFile(path.toStdString(), preset, model->paramSpecs());
    } catch (const std::exception& e) {
        showError(tr("Cannot save preset"), QString::fromUtf8(e.what()));
        return false;
    }
    meta_ = preset;
    path_ = QFileInfo(path).absoluteFilePath();
    label_ = QString::fromStdString(preset.name);
    snapshotFile_ = false;
    modified_ = false;
    addRecent(path_);
    emit changed();
    return true;
}

bool ExperimentDocument::maybeSave() {
    if (!modified_) return true;
    const auto answer = QMessageBox::warning(
        parent_, tr("Unsaved changes"),
        tr("The experiment '%1' has changes. Save them as a preset?").arg(label_),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void ExperimentDocument::setModified(bool modified) {
    if (modified_ == modified) return;
    modified_ = modified;
    emit changed();
}

QString ExperimentDocument::title() const {
    return label_;
}

QStringList ExperimentDocument::recentFiles() const {
    QStringList files = QSettings().value(kRecentKey).toStringList();
    files.erase(
        std::remove_if(files.begin(), files.end(), [](const QString& f) { return !QFileInfo::exists(f); }),
        files.end());
    return files;
}

void ExperimentDocument::addRecent(const QString& path) {
    QStringList files = QSettings().value(kRecentKey).toStringList();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    QSettings().setValue(kRecentKey, files);
}

QString ExperimentDocument::userPresetDirectory() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath("presets");
}

QStringList ExperimentDocument::userPresetFiles() {
    QStringList files;
    const QDir dir(userPresetDirectory());
    for (const QString& name : dir.entryList({"*.particlelab", "*.json"}, QDir::Files, QDir::Name))
        files << dir.filePath(name);
    return files;
}

} // namespace pl::ui
