// The Profile dock: one sampled field (a choice over the model's fieldChoices()) along the line the user
// drew with the Profile line tool, e.g. the stagnation line ahead of a body, against the distance from
// the line's start. Refreshed with the other plots' cadence (every new series row), exported like them.
#pragma once

#include <QWidget>

class QComboBox;
class QCustomPlot;
class QCPTextElement;

namespace pl::ui {

class SimulationController;
class ViewportCore;

class ProfilePlot : public QWidget {
    Q_OBJECT
public:
    ProfilePlot(SimulationController* controller, ViewportCore* viewport, QWidget* parent = nullptr);
    QCustomPlot* plot() const { return plot_; }
    QComboBox* fieldChooser() const { return fields_; }
    // Reads the chosen field along the viewport's profile line and redraws (when shown).
    void refresh();

    // Points along a line of `length` over cells dx × dy: two per cell it crosses, ends included, so
    // every cell on the line is read at least once (at most kMaxSamples).
    static int samplesAlong(double length, double dx, double dy);
    static constexpr int kMaxSamples = 4000;

protected:
    void changeEvent(QEvent* event) override;   // the projector mode changes the application font
    void showEvent(QShowEvent* event) override; // a hidden or tabbed-away plot catches up when shown

private:
    void fillChoices(); // a new model: its fields, keeping the chosen one where it has it

    SimulationController* controller_;
    ViewportCore* viewport_;
    QComboBox* fields_;
    QCustomPlot* plot_;
    QCPTextElement* title_;
};

} // namespace pl::ui
