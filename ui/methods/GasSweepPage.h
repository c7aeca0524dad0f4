// Accuracy against cost for the gas's integrators (gas/MethodSweep): on the harmonic pair with its exact
// solution, or from the current gas against a Forest–Ruth reference at 1/16 of its step. Error and cost
// axes are chosen from the measured columns; the current setting is marked; Recommend picks the cheapest
// scheme and dt for an error target and applies it to the gas.
#pragma once

#include "LabPage.h"
#include "common/sweep/Recommend.h"
#include "gas/MethodSweep.h"

class QComboBox;
class QCustomPlot;

namespace pl::ui {

class RecommendBar;

class GasSweepPage : public LabPage {
    Q_OBJECT
public:
    enum class Source { HarmonicPair, CurrentGas };
    GasSweepPage(LabRunner* runner, SimulationController* controller, QWidget* parent);
    void setSource(Source source);
    void setPairSteps(std::vector<int> steps) { pairSteps_ = std::move(steps); }
    QCustomPlot* plot() const { return plot_; }
    RecommendBar* recommendBar() const { return recommend_; }
    const std::vector<gas::SweepPoint>& points() const { return points_; }

public slots:
    void run() override;

private:
    void replot();
    std::vector<methods::Candidate> candidates() const;
    double error(const gas::SweepPoint& p) const;
    double cost(const gas::SweepPoint& p) const;

    std::vector<int> pairSteps_{16, 32, 64, 128, 256};
    QComboBox* source_ = nullptr;
    QComboBox* errorAxis_ = nullptr;
    QComboBox* costAxis_ = nullptr;
    QCustomPlot* plot_ = nullptr;
    RecommendBar* recommend_ = nullptr;
    std::vector<gas::SweepPoint> points_;
    std::vector<gas::SweepOrder> orders_;
    Source ranSource_ = Source::HarmonicPair;
    std::string currentIntegrator_;
    double currentDt_ = 0; // signed, of the gas the last run started from
};

} // namespace pl::ui
