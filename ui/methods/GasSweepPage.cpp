// The gas integrators page: runs the accuracy sweep per scheme and plots error against cost with fits.
#include "GasSweepPage.h"

#include "LabPlots.h"
#include "LabRunner.h"
#include "RecommendBar.h"
#include "SimulationController.h"
#include "gas/GasModel.h"

#include <QComboBox>
#include <QLabel>
#include <memory>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
const std::vector<std::string> kSchemes = gasIntegratorNamesByOrder();
// From the gas: the horizon is 64 of its steps, swept at 8 … 128 steps, the reference at 1024.
constexpr double kHorizonSteps = 64;
const std::vector<int> kGasSteps{8, 16, 32, 64, 128};
constexpr double kReferenceSteps = 1024;
} // namespace

GasSweepPage::GasSweepPage(LabRunner* runner, SimulationController* controller, QWidget* parent)
    : LabPage(
          runner, controller,
          tr("Each integrator over a range of dt for the same simulated time. The harmonic pair (two disks "
             "pressed together and released) has an exact solution; the current gas is compared with a "
             "Forest–Ruth run at 1/16 of its step over 64 of its steps. Lower and further left is better; "
             "the legend gives each scheme's measured order."),
          parent) {
    source_ = new QComboBox(this);
    source_->addItem(tr("Harmonic pair (exact)"));
    source_->addItem(tr("Current gas (reference run)"));
    errorAxis_ = new QComboBox(this);
    errorAxis_->addItems({tr("position error"), tr("energy error")});
    costAxis_ = new QComboBox(this);
    costAxis_->addItems({tr("force evaluations per unit time"), tr("wall time per unit time")});
    for (QComboBox* box : {errorAxis_, costAxis_})
        connect(box, &QComboBox::currentIndexChanged, this, [this] {
            replot();
            recommend_->clear();
        });
    controls_->addWidget(new QLabel(tr("Start from:"), this));
    controls_->addWidget(source_);
    controls_->addWidget(new QLabel(tr("Error:"), this));
    controls_->addWidget(errorAxis_);
    controls_->addWidget(new QLabel(tr("Cost:"), this));
    controls_->addWidget(costAxis_);
    controls_->addStretch(1);
    plot_ = lab::makePlot(this, costAxis_->currentText(), errorAxis_->currentText(), true, true);
    plot_->setObjectName("sweepPlot");
    addContent(plot_);
    recommend_ = new RecommendBar(tr("error"), 1e-4, this);
    recommend_->setProvider([this] { return candidates(); });
    recommend_->setApplier(
        [this](const methods::Candidate& c) {
            return controller_ ? controller_->setParameters(c.setting) : tr("no experiment is open");
        },
        [this]() -> QString {
            if (ranSource_ == Source::HarmonicPair)
                return tr("the pair's dt belongs to its own stiffness: sweep the current gas to apply");
            if (!currentModel("gas")) return tr("load a gas experiment to apply");
            return {};
        });
    addContent(recommend_, 0);
}

void GasSweepPage::setSource(Source source) {
    source_->setCurrentIndex(source == Source::HarmonicPair ? 0 : 1);
}

double GasSweepPage::error(const gas::SweepPoint& p) const {
    return errorAxis_->currentIndex() == 0 ? p.trajectoryError : p.energyError;
}

double GasSweepPage::cost(const gas::SweepPoint& p) const {
    return costAxis_->currentIndex() == 0 ? p.forcesPerTime : p.secondsPerTime;
}

void GasSweepPage::run() {
    if (runner_->isRunning()) return; // its queued points still draw into this page
    const Source source = source_->currentIndex() == 0 ? Source::HarmonicPair : Source::CurrentGas;
    auto reference = std::make_shared<gas::GasReference>();
    if (source == Source::CurrentGas) {
        const auto* gas = dynamic_cast<const GasModel*>(currentModel("gas"));
        if (!gas || gas->particleCount() == 0) {
            runner_->setStatus(tr("Load a gas experiment with disks first, or sweep the harmonic pair."));
            return;
        }
        // The gas runs on in this thread: the worker gets its state as it is now.
        *reference = gas::captureGas(*gas);
        currentIntegrator_ = nameOf(gas->parameters().integrator);
        currentDt_ = gas->parameters().dt;
    }
    ranSource_ = source;
    points_.clear();
    orders_.clear();
    recommend_->clear();
    replot();
    std::vector<LabRunner::Job> jobs;
    if (source == Source::CurrentGas) {
        const double horizon = kHorizonSteps * std::abs(currentDt_);
        jobs.push_back([reference, horizon, this]() -> LabRunner::Show {
            gas::runReference(*reference, horizon, horizon / kReferenceSteps);
            return [this] { runner_->setStatus(tr("Reference run done; sweeping the integrators…")); };
        });
    }
    for (const std::string& name : kSchemes)
        jobs.push_back([this, name, reference, source, steps = pairSteps_]() -> LabRunner::Show {
            const gas::SweepResult r = source == Source::HarmonicPair
                                           ? gas::sweepHarmonicPair({name}, steps)
                                           : gas::sweepFromReference(*reference, {name}, kGasSteps);
            return [this, r] {
                points_.insert(points_.end(), r.points.begin(), r.points.end());
                orders_.insert(orders_.end(), r.orders.begin(), r.orders.end());
                int failed = 0;
                for (const auto& p : r.points) failed += !p.failure.empty();
                const gas::SweepOrder& o = r.orders.front();
                runner_->setStatus(
                    tr("%1: measured order %2 (theory %3)%4")
                        .arg(QString::fromStdString(o.integrator))
                        .arg(o.measured, 0, 'f', 2)
                        .arg(o.theory)
                        .arg(failed ? tr("; %1 dt blew up and is not drawn").arg(failed) : QString()));
                replot();
            };
        });
    runner_->start(std::move(jobs), tr("Integrator sweep"));
}

void GasSweepPage::replot() {
    plot_->clearGraphs();
    plot_->xAxis->setLabel(costAxis_->currentText());
    plot_->yAxis->setLabel(errorAxis_->currentText());
    for (std::size_t k = 0; k < orders_.size(); ++k) {
        const gas::SweepOrder& o = orders_[k];
        QCPGraph* curve =
            lab::addCurve(plot_,
                          tr("%1 (order %2, theory %3)")
                              .arg(QString::fromStdString(o.integrator))
                              .arg(o.measured, 0, 'f', 2)
                              .arg(o.theory),
                          lab::schemeColour(static_cast<int>(
                              std::find(kSchemes.begin(), kSchemes.end(), o.integrator) - kSchemes.begin())));
        for (const auto& p : points_)
            if (p.integrator == o.integrator && p.failure.empty() && error(p) > 0 && cost(p) > 0)
                curve->addData(cost(p), error(p));
    }
    if (ranSource_ == Source::CurrentGas)
        for (const auto& p : points_)
            if (p.integrator == currentIntegrator_ && std::abs(p.dt / std::abs(currentDt_) - 1) < 1e-9 &&
                p.failure.empty() && error(p) > 0)
                lab::markCurrent(plot_, cost(p), error(p), tr("current setting"));
    lab::rescale(plot_);
}

std::vector<methods::Candidate> GasSweepPage::candidates() const {
    std::vector<methods::Candidate> list;
    const double sign = currentDt_ < 0 ? -1.0 : 1.0;
    for (const auto& p : points_) {
        if (!p.failure.empty()) continue;
        methods::Candidate c;
        c.label = p.integrator + ", dt = " + QString::number(sign * p.dt, 'g', 3).toStdString();
        c.setting = {{"integrator", p.integrator}, {"dt", sign * p.dt}};
        c.error = error(p);
        c.cost = p.secondsPerTime;
        list.push_back(c);
    }
    return list;
}

} // namespace pl::ui
