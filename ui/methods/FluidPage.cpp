// The fluid page: runs the dt × iterations sweep, draws its stability map and the error-against-cost plot.
#include "FluidPage.h"

#include "LabPlots.h"
#include "LabRunner.h"
#include "RecommendBar.h"
#include "SimulationController.h"
#include "fluid/FluidModel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
const std::vector<methods::CellOutcome> kClasses{
    methods::CellOutcome::Stable, methods::CellOutcome::OverCompressed, methods::CellOutcome::Exploded,
    methods::CellOutcome::Rejected};
bool ranThrough(const fluid::FluidCell& c) {
    return c.status.outcome == methods::CellOutcome::Stable ||
           c.status.outcome == methods::CellOutcome::OverCompressed;
}
} // namespace

FluidPage::FluidPage(LabRunner* runner, SimulationController* controller, QWidget* parent)
    : LabPage(
          runner, controller,
          tr("A 5 × 10 dam break (about 300 particles) for 1 s of simulated time at each dt and number of "
             "solver iterations. Over-compressed: the mean density error stayed above 1 %. Exploded: the "
             "solver diverged, or after half the run the fluid still held more kinetic energy than the "
             "fall through the box can release. Right: the density error against what it cost."),
          parent) {
    map_ = lab::makePlot(this, tr("time step dt [s]"), tr("solver iterations"), true, false);
    map_->setObjectName("fluidMapPlot");
    lab::legendBelow(map_);
    cost_ =
        lab::makePlot(this, tr("wall time per simulated second [s]"), tr("mean density error"), true, true);
    cost_->setObjectName("fluidCostPlot");
    errorKind_ = new QComboBox(this);
    errorKind_->addItems({tr("mean density error"), tr("max density error")});
    connect(errorKind_, &QComboBox::currentIndexChanged, this, [this] {
        replotCost();
        recommend_->clear();
    });
    controls_->addWidget(new QLabel(tr("Error:"), this));
    controls_->addWidget(errorKind_);
    controls_->addStretch(1);
    auto* plots = new QHBoxLayout;
    plots->addWidget(map_);
    plots->addWidget(cost_);
    addContent(plots);
    recommend_ = new RecommendBar(tr("density error"), 0.005, this);
    recommend_->setProvider([this] { return candidates(); });
    recommend_->setApplier(
        [this](const methods::Candidate& c) {
            return controller_ ? controller_->setParameters(c.setting) : tr("no experiment is open");
        },
        [this]() -> QString {
            return currentModel("fluid") ? QString() : tr("load a fluid experiment to apply");
        });
    addContent(recommend_, 0);
}

void FluidPage::setGrid(std::vector<double> dts, std::vector<int> iterations, double duration) {
    dts_ = std::move(dts);
    iterations_ = std::move(iterations);
    setup_.duration = duration;
}

void FluidPage::run() {
    if (runner_->isRunning()) return; // its queued points still draw into this page
    cells_.clear();
    recommend_->clear();
    map_->clearGraphs();
    replotCost();
    lab::addOutcomeGraphs(map_, kClasses);
    if (const auto* fluid = dynamic_cast<const FluidModel*>(currentModel("fluid")))
        lab::markCurrent(map_, fluid->parameters().dt, static_cast<double>(fluid->parameters().iterations),
                         tr("current fluid"));
    map_->xAxis->setRange(dts_.front() / 1.6, dts_.back() * 1.6);
    map_->yAxis->setRange(0, *std::max_element(iterations_.begin(), iterations_.end()) + 1);
    map_->replot();
    std::vector<LabRunner::Job> jobs;
    const Preset base = fluid::smallDamBreak();
    for (double dt : dts_)
        jobs.push_back([this, dt, base]() -> LabRunner::Show {
            std::vector<fluid::FluidCell> row;
            for (int n : iterations_) {
                if (*runner_->stopFlag()) break;
                row.push_back(fluid::runFluidCell(base, dt, n, setup_));
            }
            return [this, row, dt] {
                int failed = 0;
                for (const auto& c : row) {
                    lab::addCell(map_, kClasses, c.status.outcome, c.dt, c.iterations);
                    failed += !ranThrough(c);
                }
                cells_.insert(cells_.end(), row.begin(), row.end());
                runner_->setStatus(tr("dt = %1: %2 of %3 settings ran through")
                                       .arg(dt)
                                       .arg(static_cast<int>(row.size()) - failed)
                                       .arg(row.size()));
                map_->replot();
                replotCost();
            };
        });
    runner_->start(std::move(jobs), tr("Fluid sweep"));
}

double FluidPage::error(const fluid::FluidCell& c) const {
    return errorKind_->currentIndex() == 0 ? c.densityErrorMean : c.densityErrorMax;
}

void FluidPage::replotCost() {
    cost_->clearGraphs();
    cost_->yAxis->setLabel(errorKind_->currentText());
    for (std::size_t k = 0; k < dts_.size(); ++k) {
        QCPGraph* curve =
            lab::addCurve(cost_, tr("dt = %1").arg(dts_[k]), lab::schemeColour(static_cast<int>(k)));
        for (const auto& c : cells_)
            if (c.dt == dts_[k] && ranThrough(c) && error(c) > 0) curve->addData(c.secondsPerTime, error(c));
    }
    lab::rescale(cost_);
}

std::vector<methods::Candidate> FluidPage::candidates() const {
    std::vector<methods::Candidate> list;
    for (const auto& c : cells_) {
        if (!ranThrough(c)) continue;
        methods::Candidate candidate;
        candidate.label = "dt = " + QString::number(c.dt).toStdString() + ", " +
                          std::to_string(c.iterations) + " iterations";
        candidate.setting = {{"dt", c.dt}, {"iterations", static_cast<double>(c.iterations)}};
        candidate.error = error(c);
        candidate.cost = c.secondsPerTime;
        list.push_back(candidate);
    }
    return list;
}

} // namespace pl::ui
