// A live distribution: the model's histograms as bars (one colour per species or beam), each with the
// density theory predicts at the measured temperature, the summary (kT, KS distance) as the title, and an
// optional time-averaging window that smooths the bars over the last samples.
#pragma once

#include "common/Model.h"

#include <QWidget>
#include <deque>
#include <functional>
#include <vector>

class QCustomPlot;
class QCPTextElement;
class QSpinBox;

namespace pl::ui {

class SimulationController;

class DistributionPlot : public QWidget {
    Q_OBJECT
public:
    // Shows the model's histograms whose name starts with namePrefix ("speed", "vx").
    DistributionPlot(SimulationController* controller, const QString& objectName, const QString& namePrefix,
                     QWidget* parent = nullptr);
    // Takes the model's current histograms as the newest sample and redraws.
    void refresh();
    QCustomPlot* plot() const { return plot_; }

protected:
    void changeEvent(QEvent* event) override;   // the projector mode changes the application font
    void showEvent(QShowEvent* event) override; // a hidden or tabbed-away plot catches up when shown

private:
    void redraw();

    struct Sample {
        double lo, width;
        std::vector<double> density;
        double at(double x) const; // piecewise-constant density; 0 outside the bins
    };

    SimulationController* controller_;
    std::string prefix_;
    QCustomPlot* plot_;
    QCPTextElement* title_;
    QSpinBox* window_;
    std::vector<NamedHistogram> latest_;
    std::vector<std::deque<Sample>> history_; // per histogram, newest last
};

} // namespace pl::ui
