#include "MethodsLab.h"

#include "md/MethodSweep.h"
#include "md/TimeReversal.h"
#include "plots/PlotExport.h"
#include "plots/PlotStyle.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTabWidget>
#include <QThread>
#include <QVBoxLayout>
#include <qcustomplot.h>

namespace pl::ui {

namespace {

void useLogAxes(QCustomPlot* plot) {
    for (QCPAxis* axis : {plot->xAxis, plot->yAxis}) {
        axis->setScaleType(QCPAxis::stLogarithmic);
        axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    }
}

QCPGraph* addCurve(QCustomPlot* plot, const QString& name, const QColor& colour) {
    QCPGraph* g = plot->addGraph();
    g->setName(name);
    g->setPen(QPen(colour, 2));
    g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 6));
    return g;
}

void rescale(QCustomPlot* plot) {
    plot->rescaleAxes();
    plot->xAxis->scaleRange(1.3);
    plot->yAxis->scaleRange(1.5);
    plot->replot();
}

const QColor kSchemeColours[] = {QColor(200, 70, 60), QColor(230, 150, 40), QColor(60, 110, 200),
                                 QColor(40, 150, 110), QColor(140, 80, 180)};
} // namespace

MethodsLab::MethodsLab(QWidget* parent) : QWidget(parent) {
    auto* tabs = new QTabWidget(this);
    tabs->addTab(
        makePage(echoPlot_, tr("steps out and back, n"), tr("rms return error [L]"), echoRun_, echoNote_),
        tr("Time reversal"));
    tabs->addTab(makePage(sweepPlot_, tr("force evaluations per unit time (cost)"),
                          tr("position error at the horizon [L]"), sweepRun_, sweepNote_),
                 tr("Accuracy vs cost"));
    echoPlot_->setObjectName("echoPlot");
    sweepPlot_->setObjectName("sweepPlot");
    echoNote_->setText(
        tr("64 disks in a periodic box run n steps forward, reverse and run n steps back. "
           "Chaos amplifies round-off exponentially; bit-reversible integers return exactly."));
    sweepNote_->setText(tr("Two disks pressed together and released: one smooth contact with a known exact "
                           "solution. Lower and further left is better; the legend gives each scheme's "
                           "measured order."));
    connect(echoRun_, &QPushButton::clicked, this, &MethodsLab::runEcho);
    connect(sweepRun_, &QPushButton::clicked, this, &MethodsLab::runSweep);
    progress_ = new QProgressBar(this);
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setEnabled(false);
    connect(cancel_, &QPushButton::clicked, this, &MethodsLab::cancel);
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(progress_, 1);
    bottom->addWidget(cancel_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(tabs, 1);
    layout->addLayout(bottom);
    layout->addWidget(status_);
}

MethodsLab::~MethodsLab() {
    stop_ = true;
    if (!worker_) return;
    worker_->wait(); // the current point finishes; its result is dropped with this widget
    delete worker_;
}

QWidget* MethodsLab::makePage(QCustomPlot*& plot, const QString& xLabel, const QString& yLabel,
                              QPushButton*& run, QLabel*& note) {
    auto* page = new QWidget(this);
    plot = new QCustomPlot(page);
    plot->setMinimumSize(360, 260);
    applyPlotFont(plot, font());
    useLogAxes(plot);
    plot->xAxis->setLabel(xLabel);
    plot->yAxis->setLabel(yLabel);
    plot->legend->setVisible(true);
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignLeft);
    installPlotExportMenu(plot);
    run = new QPushButton(tr("Run"), page);
    note = new QLabel(page);
    note->setWordWrap(true);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(note);
    layout->addWidget(plot, 1);
    layout->addWidget(run, 0, Qt::AlignLeft);
    return page;
}

void MethodsLab::runEcho() {
    if (worker_) return;
    echoPlot_->clearGraphs();
    QCPGraph* doubles = addCurve(echoPlot_, tr("double"), QColor(60, 110, 200));
    QCPGraph* floats = addCurve(echoPlot_, tr("float"), QColor(230, 150, 40));
    std::vector<Job> jobs;
    for (long long n : echoSteps_)
        jobs.push_back([this, n, doubles, floats]() -> std::function<void()> {
            const md::EchoPoint p = md::loschmidtEcho(md::EchoSetup{}, {n}).front();
            return [this, p, doubles, floats] {
                // Log axes: an exact return (0) has no place on them; the status line reports it.
                if (p.rmsDouble > 0) doubles->addData(double(p.steps), p.rmsDouble);
                if (p.rmsFloat > 0) floats->addData(double(p.steps), p.rmsFloat);
                status_->setText(
                    tr("n = %1: double %2, float %3, integers %4")
                        .arg(p.steps)
                        .arg(p.rmsDouble, 0, 'g', 3)
                        .arg(p.rmsFloat, 0, 'g', 3)
                        .arg(p.rmsInteger == 0 ? tr("exactly 0") : QString::number(p.rmsInteger)));
                rescale(echoPlot_);
            };
        });
    start(std::move(jobs), tr("Loschmidt echo"));
}

void MethodsLab::runSweep() {
    if (worker_) return;
    sweepPlot_->clearGraphs();
    const std::vector<std::string> schemes{"explicit-euler", "symplectic-euler", "velocity-verlet", "rk4",
                                           "forest-ruth"};
    std::vector<Job> jobs;
    for (std::size_t k = 0; k < schemes.size(); ++k) {
        QCPGraph* curve = addCurve(sweepPlot_, QString::fromStdString(schemes[k]), kSchemeColours[k]);
        jobs.push_back([this, name = schemes[k], curve, steps = sweepSteps_]() -> std::function<void()> {
            const md::SweepResult r = md::sweepHarmonicPair({name}, steps);
            return [this, r, curve] {
                for (const auto& p : r.points) curve->addData(p.forcesPerTime, p.trajectoryError);
                const md::SweepOrder& o = r.orders.front();
                status_->setText(tr("%1: measured order %2 (theory %3)")
                                     .arg(QString::fromStdString(o.integrator))
                                     .arg(o.measured, 0, 'f', 2)
                                     .arg(o.theory));
                curve->setName(tr("%1 (order %2, theory %3)")
                                   .arg(QString::fromStdString(o.integrator))
                                   .arg(o.measured, 0, 'f', 2)
                                   .arg(o.theory));
                rescale(sweepPlot_);
            };
        });
    }
    start(std::move(jobs), tr("Integrator sweep"));
}

void MethodsLab::start(std::vector<Job> jobs, const QString& what) {
    stop_ = false;
    done_ = 0;
    const int total = static_cast<int>(jobs.size());
    progress_->setRange(0, total);
    progress_->setValue(0);
    cancel_->setEnabled(true);
    echoRun_->setEnabled(false);
    sweepRun_->setEnabled(false);
    status_->setText(tr("%1: running…").arg(what));
    worker_ = QThread::create([this, jobs = std::move(jobs)] {
        for (const Job& job : jobs) {
            if (stop_) return;
            std::function<void()> show = job();
            QMetaObject::invokeMethod(this, [this, show] {
                show();
                progress_->setValue(++done_);
            });
        }
    });
    connect(worker_, &QThread::finished, this, &MethodsLab::workerDone);
    worker_->start();
}

void MethodsLab::cancel() {
    stop_ = true;
    status_->setText(tr("Cancelling after the current point…"));
}

void MethodsLab::workerDone() {
    // Points still queued behind this signal are drawn first: the queue is in order.
    QCoreApplication::sendPostedEvents(this);
    worker_->deleteLater();
    worker_ = nullptr;
    cancel_->setEnabled(false);
    echoRun_->setEnabled(true);
    sweepRun_->setEnabled(true);
    if (stop_) status_->setText(tr("Cancelled after %1 of %2 points.").arg(done_).arg(progress_->maximum()));
    emit finished();
}

} // namespace pl::ui
