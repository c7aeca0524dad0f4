// Live speed histogram with the 2D Maxwell–Boltzmann curve at the measured kT overlaid.
#pragma once

#include <QWidget>

class QCustomPlot;
class QCPBars;
class QCPGraph;
class QCPTextElement;

namespace pl::ui {

class SimulationController;

class SpeedHistogramPlot : public QWidget {
    Q_OBJECT
public:
    explicit SpeedHistogramPlot(SimulationController* controller, QWidget* parent = nullptr);
    // Rebuilds the plot from the model's current histograms.
    void refresh();
    QCustomPlot* plot() const { return plot_; }

private:
    SimulationController* controller_;
    QCustomPlot* plot_;
    QCPBars* bars_;
    QCPGraph* theory_;
    QCPTextElement* title_;
    int framesSinceRefresh_ = 0;
};

} // namespace pl::ui
