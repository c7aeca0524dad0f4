// One tab of the methods lab: an explanation, its plots, a row of controls with Run. Pages share one
// LabRunner (one run at a time) and read the current experiment through the controller, which may be
// absent (the lab then only runs its own test problems).
#pragma once

#include <QWidget>

class QHBoxLayout;
class QLabel;
class QPushButton;
class QVBoxLayout;

namespace pl {
class Model;
}

namespace pl::ui {

class LabRunner;
class SimulationController;

class LabPage : public QWidget {
    Q_OBJECT
public:
    LabPage(LabRunner* runner, SimulationController* controller, const QString& note, QWidget* parent);

public slots:
    virtual void run() = 0;

protected:
    // The current experiment's model when it is of this kind ("gas", "fluid", "dsmc"), else null.
    Model* currentModel(const char* kind) const;
    void addContent(QWidget* widget, int stretch = 1);
    void addContent(QLayout* layout, int stretch = 1);

    LabRunner* runner_;
    SimulationController* controller_;
    QHBoxLayout* controls_ = nullptr; // Run first, then the page's options
    QPushButton* runButton_ = nullptr;

private:
    QVBoxLayout* layout_ = nullptr;
};

} // namespace pl::ui
