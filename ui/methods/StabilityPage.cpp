// The gas stability-map page: runs the dt × stiffness map, draws its cells, the limit line and the gas.
#include "StabilityPage.h"

#include "LabPlots.h"
#include "LabRunner.h"
#include "common/sweep/SweepGrid.h"
#include "gas/GasModel.h"
#include "i18n/Translations.h"

#include <QComboBox>
#include <QLabel>
#include <cmath>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
const std::vector<methods::CellOutcome> kClasses{
    methods::CellOutcome::Stable, methods::CellOutcome::Inaccurate, methods::CellOutcome::Unstable,
    methods::CellOutcome::Rejected};

} // namespace

StabilityPage::StabilityPage(LabRunner* runner, SimulationController* controller, QWidget* parent)
    : LabPage(
          runner, controller,
          tr("Where each integrator fails. A light disk caged between two heavy ones oscillates at ω = √(2k) "
             "(the contact of two unit-mass disks) for 2000 steps: stable, inaccurate (energy error above "
             "1 %) or unstable (its energy grew 50×). The line is the linear theory's limit: ω dt = 2 for "
             "Verlet and symplectic Euler, 2√2 for RK4, 1.57 for Forest–Ruth; explicit Euler has none."),
          parent),
      stiffness_(methods::logSpaced(std::pow(10.0, 1.5), std::pow(10.0, 5.5), 9)),
      dts_(methods::logSpaced(6e-5, 0.6, 26)) {
    integrator_ = new QComboBox(this);
    for (const GasIntegratorInfo& scheme : gasIntegrators()) {
        integrator_->addItem(QString::fromStdString(scheme.name));
        integrator_->setItemData(integrator_->count() - 1, coreText(scheme.description), Qt::ToolTipRole);
    }
    controls_->addWidget(new QLabel(tr("Integrator:"), this));
    controls_->addWidget(integrator_);
    controls_->addStretch(1);
    plot_ = lab::makePlot(this, tr("time step dt [T]"), tr("stiffness k [M/T²] (unit masses)"), true, true);
    plot_->setObjectName("stabilityPlot");
    lab::legendBelow(plot_);
    addContent(plot_);
}

void StabilityPage::setIntegrator(const QString& name) {
    integrator_->setCurrentText(name);
}

void StabilityPage::setGrid(std::vector<double> stiffness, std::vector<double> dts) {
    stiffness_ = std::move(stiffness);
    dts_ = std::move(dts);
}

void StabilityPage::drawFrame(const std::string& integrator) {
    plot_->clearGraphs();
    lab::addOutcomeGraphs(plot_, kClasses);
    const double limit = gasIntegrator(integrator).stabilityLimit;
    if (limit > 0) {
        QCPGraph* line = plot_->addGraph();
        line->setName(tr("linear limit ω dt = %1").arg(limit, 0, 'g', 4));
        line->setPen(QPen(Qt::black, 2, Qt::DashLine));
        for (double k : methods::logSpaced(stiffness_.front(), stiffness_.back(), 20))
            line->addData(limit / gas::cagedOmega(k), k);
    }
    if (const auto* gas = dynamic_cast<const GasModel*>(currentModel("gas"))) {
        // A gas of mass m has the contact frequency of unit masses at k/m.
        const GasParams& p = gas->parameters();
        lab::markCurrent(plot_, std::abs(p.dt), p.stiffness / p.a.mass, tr("current gas"));
    }
    plot_->xAxis->setRange(dts_.front() / 1.5, dts_.back() * 1.5);
    plot_->yAxis->setRange(stiffness_.front() / 1.5, stiffness_.back() * 1.5);
    plot_->replot();
}

void StabilityPage::run() {
    if (runner_->isRunning()) return; // its queued points still draw into this page
    const std::string integrator = integrator_->currentText().toStdString();
    cells_.clear();
    drawFrame(integrator);
    gas::StabilitySetup setup;
    setup.steps = 2000;
    std::vector<LabRunner::Job> jobs;
    for (double k : stiffness_)
        jobs.push_back([this, k, integrator, setup, dts = dts_]() -> LabRunner::Show {
            std::vector<gas::StabilityCell> row;
            for (double dt : dts) {
                if (*runner_->stopFlag()) break;
                row.push_back(gas::runStabilityCell(integrator, dt, k, setup));
            }
            return [this, row, k] {
                for (const auto& c : row) lab::addCell(plot_, kClasses, c.status.outcome, c.dt, c.stiffness);
                cells_.insert(cells_.end(), row.begin(), row.end());
                const double limit = gas::measuredLimit(row);
                runner_->setStatus(
                    std::isnan(limit)
                        ? tr("k = %1: no cell blew up").arg(k, 0, 'g', 3)
                        : tr("k = %1: stable up to ω dt = %2").arg(k, 0, 'g', 3).arg(limit, 0, 'f', 2));
                plot_->replot();
            };
        });
    runner_->start(std::move(jobs), tr("Stability map"));
}

} // namespace pl::ui
