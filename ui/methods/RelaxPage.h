// Model no more than the scene needs (comparison/GasVsDsmc): the disk gas and planar DSMC relax from the
// same two beams; the kurtosis of v_x against collisions per particle for both, the wall time each
// took, and whether they ended at one Maxwellian.
#pragma once

#include "LabPage.h"
#include "comparison/GasVsDsmc.h"

class QCustomPlot;
class QLabel;
class QSpinBox;

namespace pl::ui {

class RelaxPage : public LabPage {
    Q_OBJECT
public:
    RelaxPage(LabRunner* runner, SimulationController* controller, QWidget* parent);
    void setSetup(const methods::TwoBeamSetup& setup);
    QCustomPlot* plot() const { return plot_; }
    QString verdict() const;

public slots:
    void run() override;

private:
    QCustomPlot* plot_ = nullptr;
    QLabel* verdict_ = nullptr;
    QSpinBox* particles_ = nullptr;
    QSpinBox* collisions_ = nullptr;
    methods::TwoBeamSetup setup_;
};

} // namespace pl::ui
