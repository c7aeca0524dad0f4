// The time-reversal page: runs the Loschmidt echo in each arithmetic and plots the return error.
#include "EchoPage.h"

#include "LabPlots.h"
#include "LabRunner.h"
#include "gas/TimeReversal.h"

#include <qcustomplot.h>

namespace pl::ui {

EchoPage::EchoPage(LabRunner* runner, SimulationController* controller, QWidget* parent)
    : LabPage(runner, controller,
              tr("64 disks in a periodic box run n steps forward, reverse and run n steps back. Chaos "
                 "amplifies round-off exponentially; bit-reversible integers return exactly."),
              parent) {
    plot_ = lab::makePlot(this, tr("steps out and back, n"), tr("rms return error [L]"), true, true);
    plot_->setObjectName("echoPlot");
    addContent(plot_);
}

void EchoPage::run() {
    if (runner_->isRunning()) return; // its queued points still draw into this page
    plot_->clearGraphs();
    QCPGraph* doubles = lab::addCurve(plot_, tr("double"), QColor(60, 110, 200));
    QCPGraph* floats = lab::addCurve(plot_, tr("float"), QColor(230, 150, 40));
    std::vector<LabRunner::Job> jobs;
    for (long long n : steps_)
        jobs.push_back([this, n, doubles, floats]() -> LabRunner::Show {
            const gas::EchoPoint p = gas::loschmidtEcho(gas::EchoSetup{}, {n}).front();
            return [this, p, doubles, floats] {
                // Log axes: an exact return (0) has no place on them; the status line reports it.
                if (p.rmsDouble > 0) doubles->addData(double(p.steps), p.rmsDouble);
                if (p.rmsFloat > 0) floats->addData(double(p.steps), p.rmsFloat);
                runner_->setStatus(
                    tr("n = %1: double %2, float %3, integers %4")
                        .arg(p.steps)
                        .arg(p.rmsDouble, 0, 'g', 3)
                        .arg(p.rmsFloat, 0, 'g', 3)
                        .arg(p.rmsInteger == 0 ? tr("exactly 0") : QString::number(p.rmsInteger)));
                lab::rescale(plot_);
            };
        });
    runner_->start(std::move(jobs), tr("Loschmidt echo"));
}

} // namespace pl::ui
