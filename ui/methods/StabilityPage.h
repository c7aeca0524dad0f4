// The gas's stability map (gas/StabilityMap): dt × stiffness for one integrator, each cell stable,
// inaccurate or unstable, with the linear limit ω dt = L drawn over it and the current gas marked.
#pragma once

#include "LabPage.h"
#include "gas/StabilityMap.h"

class QComboBox;
class QCustomPlot;

namespace pl::ui {

class StabilityPage : public LabPage {
    Q_OBJECT
public:
    StabilityPage(LabRunner* runner, SimulationController* controller, QWidget* parent);
    void setIntegrator(const QString& name);
    // The grid: stiffness rows and dt columns (log-spaced); tests use small ones.
    void setGrid(std::vector<double> stiffness, std::vector<double> dts);
    QCustomPlot* plot() const { return plot_; }
    const std::vector<gas::StabilityCell>& cells() const { return cells_; }

public slots:
    void run() override;

private:
    void drawFrame(const std::string& integrator);

    QComboBox* integrator_ = nullptr;
    QCustomPlot* plot_ = nullptr;
    std::vector<double> stiffness_, dts_;
    std::vector<gas::StabilityCell> cells_;
};

} // namespace pl::ui
