// The DSMC accuracy-against-cost page: runs the BKW sweep per particle count and plots error against time.
#include "DsmcPage.h"

#include "LabPlots.h"
#include "LabRunner.h"
#include "RecommendBar.h"
#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "dsmc/DsmcModel.h"

#include <qcustomplot.h>

namespace pl::ui {

DsmcPage::DsmcPage(LabRunner* runner, SimulationController* controller, QWidget* parent)
    : LabPage(
          runner, controller,
          tr("Maxwell molecules relaxing from the BKW start for 6 mean collision times, at each number of "
             "particles in the cell and collision probability ν dt per step. The error is the rms distance "
             "of the 4th and 6th moments from the exact BKW curves. In one homogeneous cell the noise of N "
             "particles (∝ 1/√N) outweighs the time step, and the cost is the number of collisions."),
          parent) {
    plot_ = lab::makePlot(this, tr("wall time of the run [s]"), tr("rms moment error"), true, true);
    plot_->setObjectName("dsmcSweepPlot");
    plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    addContent(plot_);
    recommend_ = new RecommendBar(tr("moment error"), 0.01, this);
    recommend_->setProvider([this] { return candidates(); });
    recommend_->setCostUnit(tr("s per run"));
    recommend_->setApplier([this](const methods::Candidate& c) { return applyCandidate(c); },
                           [this] { return whyNotApplicable(); });
    addContent(recommend_, 0);
}

void DsmcPage::setGrid(std::vector<long long> particles, std::vector<double> nuDts) {
    particles_ = std::move(particles);
    nuDts_ = std::move(nuDts);
}

void DsmcPage::run() {
    if (runner_->isRunning()) return;
    cells_.clear();
    recommend_->clear();
    plot_->clearGraphs();
    const Preset base = loadPreset("dsmc-bkw");
    std::vector<LabRunner::Job> jobs;
    for (std::size_t k = 0; k < nuDts_.size(); ++k) {
        QCPGraph* curve =
            lab::addCurve(plot_, tr("ν dt = %1").arg(nuDts_[k]), lab::schemeColour(static_cast<int>(k)));
        jobs.push_back([this, k, base, curve]() -> LabRunner::Show {
            std::vector<dsmc::DsmcCell> row;
            for (long long n : particles_) {
                if (*runner_->stopFlag()) break;
                row.push_back(dsmc::runDsmcCell(base, n, nuDts_[k]));
            }
            return [this, row, curve] {
                for (const auto& c : row)
                    if (c.status.outcome == methods::CellOutcome::Stable && c.momentError > 0 &&
                        c.seconds > 0)
                        curve->addData(c.seconds, c.momentError);
                cells_.insert(cells_.end(), row.begin(), row.end());
                if (!row.empty())
                    runner_->setStatus(tr("ν dt = %1: error %2 at %3 particles, %4 at %5")
                                           .arg(row.front().nuDt)
                                           .arg(row.front().momentError, 0, 'g', 3)
                                           .arg(row.front().particles)
                                           .arg(row.back().momentError, 0, 'g', 3)
                                           .arg(row.back().particles));
                lab::rescale(plot_);
            };
        });
    }
    runner_->start(std::move(jobs), tr("DSMC sweep"));
}

std::vector<methods::Candidate> DsmcPage::candidates() const {
    std::vector<methods::Candidate> list;
    for (const auto& c : cells_) {
        if (c.status.outcome != methods::CellOutcome::Stable) continue;
        methods::Candidate candidate;
        candidate.label =
            std::to_string(c.particles) + " particles, ν dt = " + QString::number(c.nuDt).toStdString();
        candidate.setting = {{"count_a", static_cast<double>(c.particles)}, {"nu_dt", c.nuDt}};
        candidate.error = c.momentError;
        candidate.cost = c.seconds;
        list.push_back(candidate);
    }
    return list;
}

QString DsmcPage::whyNotApplicable() const {
    const auto* cell = dynamic_cast<const DsmcModel*>(currentModel("dsmc"));
    if (!cell) return tr("load a DSMC experiment to apply");
    if (cell->parameters().crossSection != DsmcCrossSection::Maxwell)
        return tr("measured for Maxwell molecules: the current cell uses %1")
            .arg(QString::fromStdString(nameOf(cell->parameters().crossSection)));
    if (cell->parameters().initial == DsmcInitialState::TwoBeams)
        return tr("the sweep counts one population of particles; the current cell has two beams");
    return {};
}

QString DsmcPage::applyCandidate(const methods::Candidate& c) {
    const auto* cell = dynamic_cast<const DsmcModel*>(currentModel("dsmc"));
    if (!cell || !controller_) return tr("no DSMC experiment is open");
    // Same number density with N particles: F_N = n V / N; the step from ν dt at this density.
    const double particles = std::get<double>(c.setting.at("count_a"));
    const double density = cell->numberDensity();
    const double nu = density * cell->collisionModel().prefactor;
    return controller_->setParameters({{"count_a", particles},
                                       {"fn", density * cell->parameters().cellVolume / particles},
                                       {"dt", std::get<double>(c.setting.at("nu_dt")) / nu}});
}

} // namespace pl::ui
