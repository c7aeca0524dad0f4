// The few large controls a lesson needs in present mode, per scene. Gas: temperature (hold to heat or
// cool), number of particles, the piston (compress / stop / expand) and gravity; fluid: gravity and
// pouring; DSMC: run, reset and speed; a scene with sampled fields (the wind tunnel): speed and what the
// viewport shows, the particles or a field. Every change goes through the SimulationController.
#pragma once

#include "viewport/ViewportCore.h"

#include <QWidget>
#include <vector>

class QLabel;
class QPushButton;
class QSlider;
class QTimer;
class QGridLayout;
class QVBoxLayout;

namespace pl::ui {

class SimulationController;

class LessonControls : public QWidget {
    Q_OBJECT
public:
    explicit LessonControls(SimulationController* controller, QWidget* parent = nullptr);

signals:
    // "Pour with the mouse" asks the window to switch the viewport to this tool.
    void toolRequested(ViewportTool tool);

private:
    void rebuild(); // a new scene: its controls
    // A cell of the two-column grid (span 2: a whole row) holding one control group.
    QVBoxLayout* addGroup(int row, int column, int span = 1);
    void addRunRow();
    void addGasControls();
    void addFluidControls();
    void addDsmcControls();
    void addFieldControls();
    void addPistonGroup(QVBoxLayout* drive, QVBoxLayout* toggle);
    // The downward acceleration "gravity", the same key in every scene, from 0 to maximum [L/T²].
    void addGravitySlider(QVBoxLayout* group, double maximum);
    QSlider* addSlider(QVBoxLayout* group, const QString& title, QLabel** valueLabel);
    QPushButton* addButton(QLayout* row, const QString& text, const QString& objectName);
    void applyParticleCount(int total);
    void pourOnce();
    void syncState(); // what the model does now: piston state, running, parameter values
    void say(const QString& sentence);

    SimulationController* controller_;
    QVBoxLayout* layout_;
    QWidget* body_ = nullptr; // rebuilt per scene
    QGridLayout* grid_ = nullptr;
    QPushButton* run_ = nullptr;
    QPushButton* pistonButtons_[3] = {nullptr, nullptr, nullptr}; // compress, stop, expand
    QPushButton* pistonSwitch_ = nullptr;
    QSlider* count_ = nullptr;
    QLabel* countLabel_ = nullptr;
    QLabel* message_ = nullptr;
    std::vector<QPushButton*> viewButtons_; // one per choice of the `view` parameter
    QTimer* pour_;
};

} // namespace pl::ui
