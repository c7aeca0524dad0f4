// DSMC's accuracy against cost (dsmc/DsmcSweep): Maxwell molecules from the BKW start at several
// particle counts and ν dt, the moment error against the exact BKW curves against the wall time;
// Recommend applies the cheapest particle count and step to a BKW experiment.
#pragma once

#include "LabPage.h"
#include "common/sweep/Recommend.h"
#include "dsmc/DsmcSweep.h"

class QCustomPlot;

namespace pl::ui {

class RecommendBar;

class DsmcPage : public LabPage {
    Q_OBJECT
public:
    DsmcPage(LabRunner* runner, SimulationController* controller, QWidget* parent);
    void setGrid(std::vector<long long> particles, std::vector<double> nuDts);
    QCustomPlot* plot() const { return plot_; }
    RecommendBar* recommendBar() const { return recommend_; }
    const std::vector<dsmc::DsmcCell>& cells() const { return cells_; }

public slots:
    void run() override;

private:
    std::vector<methods::Candidate> candidates() const;
    QString applyCandidate(const methods::Candidate& c);
    QString whyNotApplicable() const;

    QCustomPlot* plot_ = nullptr;
    RecommendBar* recommend_ = nullptr;
    std::vector<long long> particles_{1000, 4000, 16000, 64000};
    std::vector<double> nuDts_{0.03, 0.1, 0.3, 1.0};
    std::vector<dsmc::DsmcCell> cells_;
};

} // namespace pl::ui
