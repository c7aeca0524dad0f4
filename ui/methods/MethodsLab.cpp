// The methods lab window: builds its pages around one shared runner, with entry points for tests.
#include "MethodsLab.h"

#include "DsmcPage.h"
#include "EchoPage.h"
#include "FluidPage.h"
#include "GasSweepPage.h"
#include "LabRunner.h"
#include "RelaxPage.h"
#include "StabilityPage.h"

#include <QTabWidget>
#include <QVBoxLayout>

namespace pl::ui {

MethodsLab::MethodsLab(QWidget* parent, SimulationController* controller) : QWidget(parent) {
    runner_ = new LabRunner(this);
    connect(runner_, &LabRunner::finished, this, &MethodsLab::finished);
    tabs_ = new QTabWidget(this);
    echo_ = new EchoPage(runner_, controller, this);
    gasSweep_ = new GasSweepPage(runner_, controller, this);
    stability_ = new StabilityPage(runner_, controller, this);
    fluid_ = new FluidPage(runner_, controller, this);
    dsmc_ = new DsmcPage(runner_, controller, this);
    relax_ = new RelaxPage(runner_, controller, this);
    tabs_->addTab(echo_, tr("Time reversal"));
    tabs_->addTab(gasSweep_, tr("Accuracy vs cost"));
    tabs_->addTab(stability_, tr("Stability map"));
    tabs_->addTab(fluid_, tr("Fluid"));
    tabs_->addTab(dsmc_, tr("DSMC"));
    tabs_->addTab(relax_, tr("MD vs DSMC"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(tabs_, 1);
    layout->addWidget(runner_);
}

MethodsLab::~MethodsLab() {
    // The worker's pending results refer to the pages: stop it before they go.
    delete runner_;
}

void MethodsLab::setEchoSteps(std::vector<long long> steps) {
    echo_->setSteps(std::move(steps));
}

void MethodsLab::setSweepSteps(std::vector<int> steps) {
    gasSweep_->setPairSteps(std::move(steps));
}

QCustomPlot* MethodsLab::echoPlot() const {
    return echo_->plot();
}

QCustomPlot* MethodsLab::sweepPlot() const {
    return gasSweep_->plot();
}

bool MethodsLab::isRunning() const {
    return runner_->isRunning();
}

void MethodsLab::runEcho() {
    echo_->run();
}

void MethodsLab::runSweep() {
    gasSweep_->run();
}

void MethodsLab::cancel() {
    runner_->cancel();
}

} // namespace pl::ui
