// The fluid's stability and accuracy against cost (fluid/FluidSweep): a small dam break over dt ×
// solver iterations, mapped as stable / over-compressed / exploded, and its density error against
// the wall time it cost, one curve per dt; Recommend applies the cheapest dt and iteration count.
#pragma once

#include "LabPage.h"
#include "common/sweep/Recommend.h"
#include "fluid/FluidSweep.h"

class QComboBox;
class QCustomPlot;

namespace pl::ui {

class RecommendBar;

class FluidPage : public LabPage {
    Q_OBJECT
public:
    FluidPage(LabRunner* runner, SimulationController* controller, QWidget* parent);
    void setGrid(std::vector<double> dts, std::vector<int> iterations, double duration);
    QCustomPlot* mapPlot() const { return map_; }
    QCustomPlot* costPlot() const { return cost_; }
    RecommendBar* recommendBar() const { return recommend_; }
    const std::vector<fluid::FluidCell>& cells() const { return cells_; }

public slots:
    void run() override;

private:
    std::vector<methods::Candidate> candidates() const;
    double error(const fluid::FluidCell& c) const;
    void replotCost();

    QCustomPlot* map_ = nullptr;
    QCustomPlot* cost_ = nullptr;
    QComboBox* errorKind_ = nullptr;
    RecommendBar* recommend_ = nullptr;
    std::vector<double> dts_{0.00125, 0.0025, 0.005, 0.01, 0.02, 0.04, 0.08};
    std::vector<int> iterations_{1, 2, 3, 5, 8, 12};
    fluid::FluidSweepSetup setup_;
    std::vector<fluid::FluidCell> cells_;
};

} // namespace pl::ui
