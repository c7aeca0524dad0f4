// The experiment as a document: which preset it came from, whether the user changed it, where it is
// saved, the recent-files list, and the user's preset folder (XDG data directory). Saving writes the
// model's current parameters, seed and obstacles as a preset file, atomically; a document opened from a
// snapshot saves as a snapshot.
#pragma once

#include "common/Preset.h"
#include "common/Snapshot.h"

#include <QObject>
#include <QStringList>

class QWidget;

namespace pl::ui {

class SimulationController;

class ExperimentDocument : public QObject {
    Q_OBJECT
public:
    ExperimentDocument(SimulationController* controller, QWidget* dialogParent);

    // Loads a built-in preset name or a file path (a preset, or a snapshot that continues where it was
    // taken). On failure shows a dialog naming the problem and keeps the running experiment. Asks before
    // discarding unsaved changes unless force is set.
    bool open(const QString& nameOrPath, bool force = false);
    // Continues a snapshot that belongs to no file of the user's (an autosave): untitled and modified.
    bool restore(const Snapshot& snapshot);
    // Writes the experiment with its full state (File → Save snapshot); no dialogs but the error one.
    bool saveSnapshotTo(const QString& path);
    // Names a run read back from elsewhere, which the controller already shows (showImported): it
    // belongs to no file and holds nothing unsaved.
    void adoptImported(const Preset& preset, const QString& label);
    // A fresh experiment of a scene with its default parameters.
    bool newExperiment(const std::string& kind);
    bool save();                      // to the current file, or Save As when there is none
    bool saveAs();                    // asks for a file in the user's preset folder
    bool saveTo(const QString& path); // no dialogs except the error one; for tests and scripts

    // True when there is nothing unsaved or the user chose Save (and it worked) or Discard.
    bool maybeSave();

    bool isModified() const { return modified_; }
    void setModified(bool modified);
    QString title() const; // preset name, or the file name
    QString description() const { return QString::fromStdString(meta_.description); }
    QString filePath() const { return path_; }
    QStringList recentFiles() const;
    static QString userPresetDirectory();
    static QStringList userPresetFiles();

signals:
    void changed(); // title, modified flag or recent files changed

private:
    bool adopt(const Preset& preset, const QString& path, const QString& label,
               const StateRecord* state = nullptr);
    void addRecent(const QString& path);
    void showError(const QString& what, const QString& message) const;

    SimulationController* controller_;
    QWidget* parent_;
    Preset meta_; // name and description of what was loaded
    QString path_;
    QString label_;
    bool modified_ = false;
    bool snapshotFile_ = false; // path_ holds a snapshot: saving writes one there too
};

} // namespace pl::ui
