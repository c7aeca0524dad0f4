// The MD-against-DSMC page: relaxes the same two beams in both models and plots kurtosis and wall time.
#include "RelaxPage.h"

#include "LabPlots.h"
#include "LabRunner.h"

#include <QLabel>
#include <QSpinBox>
#include <memory>
#include <qcustomplot.h>

namespace pl::ui {

RelaxPage::RelaxPage(LabRunner* runner, SimulationController* controller, QWidget* parent)
    : LabPage(
          runner, controller,
          tr("Two beams at ±u relax to one Maxwellian. Molecular dynamics resolves every contact of "
             "soft disks (about 30 steps each); DSMC with two velocity components only samples which "
             "pairs collide. Both reach the same Maxwellian in the same number of collisions: for a dilute "
             "gas's velocities DSMC is enough. It is not for a dense gas (collisions stop being binary and "
             "the finite size of the disks changes the pressure) or anything about structure (g(r), "
             "crystals, flow around an obstacle at the scale of a disk)."),
          parent) {
    particles_ = new QSpinBox(this);
    particles_->setRange(16, 16384);
    particles_->setValue(static_cast<int>(setup_.particles));
    collisions_ = new QSpinBox(this);
    collisions_->setRange(1, 100);
    collisions_->setValue(static_cast<int>(setup_.collisionsPerParticle));
    controls_->addWidget(new QLabel(tr("Particles:"), this));
    controls_->addWidget(particles_);
    controls_->addWidget(new QLabel(tr("Collisions each:"), this));
    controls_->addWidget(collisions_);
    controls_->addStretch(1);
    plot_ = lab::makePlot(this, tr("collisions per particle"), tr("kurtosis of v_x (Maxwellian: 3)"), false,
                          false);
    plot_->setObjectName("relaxPlot");
    plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignRight);
    addContent(plot_);
    verdict_ = new QLabel(this);
    verdict_->setWordWrap(true);
    verdict_->setObjectName("relaxVerdict");
    addContent(verdict_, 0);
}

void RelaxPage::setSetup(const methods::TwoBeamSetup& setup) {
    setup_ = setup;
    particles_->setValue(static_cast<int>(setup.particles));
    collisions_->setValue(static_cast<int>(setup.collisionsPerParticle));
}

QString RelaxPage::verdict() const {
    return verdict_->text();
}

void RelaxPage::run() {
    if (runner_->isRunning()) return;
    setup_.particles = particles_->value();
    setup_.collisionsPerParticle = collisions_->value();
    plot_->clearGraphs();
    verdict_->clear();
    QCPGraph* md = lab::addCurve(plot_, tr("molecular dynamics"), QColor(60, 110, 200));
    QCPGraph* dsmc = lab::addCurve(plot_, tr("DSMC (in the plane)"), QColor(200, 70, 60));
    for (QCPGraph* g : {md, dsmc}) g->setScatterStyle(QCPScatterStyle::ssNone);
    QCPGraph* maxwell = plot_->addGraph();
    maxwell->setName(tr("Maxwellian"));
    maxwell->setPen(QPen(Qt::black, 1, Qt::DashLine));
    maxwell->addData(0, 3);
    maxwell->addData(setup_.collisionsPerParticle, 3);
    plot_->xAxis->setRange(0, setup_.collisionsPerParticle * 1.05);
    plot_->yAxis->setRange(0.8, 3.6);
    plot_->replot();
    auto runs = std::make_shared<std::pair<methods::RelaxationRun, methods::RelaxationRun>>();
    const auto plotAsItGoes = [this](QCPGraph* curve) {
        return [this, curve](const methods::RelaxationSample& s) {
            QMetaObject::invokeMethod(this, [this, curve, s] {
                curve->addData(s.collisionsPerParticle, s.kurtosisVx);
                plot_->replot(QCustomPlot::rpQueuedReplot);
            });
        };
    };
    std::vector<LabRunner::Job> jobs;
    jobs.push_back([this, runs, setup = setup_, onSample = plotAsItGoes(md)]() -> LabRunner::Show {
        runs->first = methods::relaxWithMd(setup, onSample, runner_->stopFlag());
        return [this, runs] {
            runner_->setStatus(tr("MD: %1 s for %2 particle-steps")
                                   .arg(runs->first.seconds, 0, 'g', 3)
                                   .arg(runs->first.particleSteps));
        };
    });
    jobs.push_back([this, runs, setup = setup_, onSample = plotAsItGoes(dsmc)]() -> LabRunner::Show {
        runs->second = methods::relaxWithDsmc(setup, onSample, runner_->stopFlag());
        const methods::GasVsDsmcResult r = methods::compareRelaxations(runs->first, runs->second);
        return [this, r] {
            runner_->setStatus(tr("Both relaxed: %1 and %2 collisions per particle")
                                   .arg(r.md.curve.back().collisionsPerParticle, 0, 'f', 1)
                                   .arg(r.dsmc.curve.back().collisionsPerParticle, 0, 'f', 1));
            verdict_->setText(
                tr("MD took %1 s, DSMC %2 s: DSMC was %3× cheaper for the same relaxation. Final v_x "
                   "distributions: KS distance %4, p = %5 (%6).")
                    .arg(r.md.seconds, 0, 'g', 3)
                    .arg(r.dsmc.seconds, 0, 'g', 3)
                    .arg(r.costRatio, 0, 'f', 0)
                    .arg(r.ksDistance, 0, 'f', 3)
                    .arg(r.ksPValue, 0, 'g', 2)
                    .arg(r.ksPValue > 0.01 ? tr("one Maxwellian") : tr("they differ")));
            lab::rescale(plot_);
        };
    });
    runner_->start(std::move(jobs), tr("MD against DSMC"));
}

} // namespace pl::ui
