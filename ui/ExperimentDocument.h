// The experiment as a document: which preset it came from, whether the user changed it, where it is
// saved, the recent-files list, and the user's preset folder (XDG data directory). Saving writes the
// model's current parameters, seed and obstacles as a preset file, atomically.
#pragma once

#include "common/Preset.h"

#include <QObject>
#include <QStringList>

class QWidget;

namespace pl::ui {

class SimulationController;

class ExperimentDocument : public QObject {
    Q_OBJECT
public:
    ExperimentDocument(SimulationController* controller, QWidget* dialogParent);

    // Loads a built-in preset name or a file path. On failure shows a dialog naming the problem and
    // keeps the running experiment. Asks before discarding unsaved changes unless force is set.
    bool open(const QString& nameOrPath, bool force = false);
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
    QString filePath() const { return path_; }
    QStringList recentFiles() const;
    static QString userPresetDirectory();
    static QStringList userPresetFiles();

signals:
    void changed(); // title, modified flag or recent files changed

private:
    bool adopt(const Preset& preset, const QString& path, const QString& label);
    void addRecent(const QString& path);
    void showError(const QString& what, const QString& message) const;

    SimulationController* controller_;
    QWidget* parent_;
    Preset meta_; // name and description of what was loaded
    QString path_;
    QString label_;
    bool modified_ = false;
};

} // namespace pl::ui
