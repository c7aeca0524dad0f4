// Time reversal, measured: the Loschmidt echo in double, float and bit-reversible integers
// (gas/TimeReversal).
#pragma once

#include "LabPage.h"

#include <vector>

class QCustomPlot;

namespace pl::ui {

class EchoPage : public LabPage {
    Q_OBJECT
public:
    EchoPage(LabRunner* runner, SimulationController* controller, QWidget* parent);
    void setSteps(std::vector<long long> steps) { steps_ = std::move(steps); }
    QCustomPlot* plot() const { return plot_; }

public slots:
    void run() override;

private:
    std::vector<long long> steps_{10, 30, 100, 300, 1000, 3000};
    QCustomPlot* plot_ = nullptr;
};

} // namespace pl::ui
