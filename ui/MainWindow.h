// The application's composition root: actions, docks and the central view, wired to one controller.
#pragma once

#include <QMainWindow>

class QComboBox;
class QLabel;
class QSpinBox;

namespace pl {
struct Preset;
}

namespace pl::ui {

class SimulationController;
class SpeedHistogramPlot;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    // Loads a built-in preset by name or a preset file; shows a dialog naming the problem on failure
    // (the running experiment is kept). Returns whether it loaded.
    bool openPreset(const QString& nameOrPath);
    SimulationController* controller() const { return controller_; }
    SpeedHistogramPlot* histogram() const { return histogram_; }

private:
    void createActions();
    void createDocks();
    void updateStatus();
    bool loadPreset(const Preset& preset, const QString& label);

    SimulationController* controller_;
    SpeedHistogramPlot* histogram_ = nullptr;
    QComboBox* presetPicker_ = nullptr;
    QSpinBox* speed_ = nullptr;
    QLabel* status_ = nullptr;
    QAction* playAction_ = nullptr;
};

} // namespace pl::ui
