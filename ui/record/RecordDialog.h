// The Record dialog: what a clip shows and how, chosen before the file. The format (MP4, WebM, GIF), the
// scene alone or beside one of its plots, the frame size (720p by default, a few presets or any size the
// format takes), the frame rate, the steps per frame (by default the scene's watchable pace, shown as
// simulated time per frame) and the title and time overlay. The choices are remembered (QSettings
// "record/…"; the steps per frame per kind, and only when they are not the watchable pace).
#pragma once

#include "AppRecorder.h"
#include "media/ClipFormat.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace pl::ui {

class SimulationController;

// The file to write: the chosen path when its suffix names a clip format (the format follows the file),
// else the path with the suffix of `format` added.
QString clipPathFor(const QString& chosen, ClipFormat format);

// The file name suffix of a format, without the dot ("mp4").
QString clipSuffix(ClipFormat format);

class RecordDialog : public QDialog {
    Q_OBJECT
public:
    explicit RecordDialog(SimulationController* controller, QWidget* parent = nullptr);

    AppClipOptions options() const;
    ClipFormat format() const;
    // Stores the choices for the next clip.
    void remember() const;

    void accept() override;

private:
    void readSettings();
    void updateSize();
    void updatePace();
    void check();

    SimulationController* controller_;
    QString kind_;
    QComboBox* formatChooser_;
    QComboBox* contentChooser_;
    QComboBox* sizeChooser_;
    QSpinBox* widthSpin_;
    QSpinBox* heightSpin_;
    QSpinBox* fpsSpin_;
    QSpinBox* stepsSpin_;
    QPushButton* watchableButton_;
    QLabel* paceLabel_;
    QCheckBox* captionsCheck_;
    QLabel* refusalLabel_;
    QDialogButtonBox* buttons_;
    bool followsPace_ = true; // the steps per frame follow the frame rate at the watchable pace
};

} // namespace pl::ui
