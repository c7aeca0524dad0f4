// The few large controls a lesson needs in present mode, as the scene's kind lists them in its
// registration (ModelDescriptor::present; PresentBoard.h builds a list from the model's capabilities where
// it gives none): temperature (hold to heat or cool), number of particles, the piston (compress / stop /
// expand), gravity, pouring and the spawn tool, the pace, and what the viewport shows (particles or a
// field). Run and Reset are always there. Every change goes through the SimulationController.
#pragma once

#include "catalog/ModelDescriptor.h"
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
    // The grid's next free cell (two columns), or a whole row of its own.
    QVBoxLayout* addCell();
    QVBoxLayout* addRow();
    void addControl(LessonControl control);
    void addRunRow();
    void addHeatSlider(QVBoxLayout* group);
    void addParticleCount(QVBoxLayout* group);
    void addPistonGroup(QVBoxLayout* drive, QVBoxLayout* toggle);
    // The downward acceleration "gravity", the same key in every scene, from 0 to maximum.
    void addGravitySlider(QVBoxLayout* group, double maximum);
    void addGravitySwitch(QVBoxLayout* group);
    void addPourButton(QVBoxLayout* group);
    void addSpawnToolButton(QVBoxLayout* group);
    void addPaceSlider(QVBoxLayout* group);
    void addFieldButtons(); // a row: one button per choice of the `view` parameter
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
    int row_ = 0, column_ = 0; // the grid's next free cell
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
