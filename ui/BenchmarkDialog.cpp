// The machine benchmark dialog: queues the scene × backend × N jobs and plots each point as it finishes.
#include "BenchmarkDialog.h"

#include "catalog/ModelCatalog.h"
#include "i18n/Translations.h"
#include "plots/PlotExport.h"
#include "plots/PlotStyle.h"
#include "viewport/QtGlContext.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
constexpr double kSlowMicrosecondsPerStep = 2e5; // beyond 0.2 s per step a backend stops growing N

// Each kind's sizes from its registration (ModelDescriptor::benchmark), on the CPU and then the GPU.
std::vector<BenchmarkDialog::Job> defaultJobs() {
    std::vector<BenchmarkDialog::Job> jobs;
    for (gl::Backend b : {gl::Backend::Cpu, gl::Backend::Gl})
        for (const ModelDescriptor& kind : modelCatalog())
            if (kind.benchmark.scaledPreset)
                for (std::size_t n : kind.benchmark.dialogSizes) jobs.push_back({kind.kind, b, n});
    return jobs;
}

// The scene's name as its menus show it: "Gas (molecular dynamics)".
QString sceneTitle(const std::string& kind) {
    const ModelDescriptor* descriptor = findModel(kind);
    return descriptor ? coreText(descriptor->title) : QString::fromStdString(kind);
}
} // namespace

BenchmarkDialog::BenchmarkDialog(QWidget* parent) : QDialog(parent), jobs_(defaultJobs()) {
    setWindowTitle(tr("Benchmark this machine"));
    settings_.repeats = 3;
    settings_.targetSeconds = 0.15;
    settings_.minSteps = 3;
    settings_.warmupSteps = 3;
    plot_ = new QCustomPlot(this);
    plot_->setObjectName("benchmarkPlot");
    plot_->setMinimumSize(640, 400);
    applyPlotFont(plot_, font());
    for (QCPAxis* axis : {plot_->xAxis, plot_->yAxis}) {
        axis->setScaleType(QCPAxis::stLogarithmic);
        axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    }
    plot_->xAxis->setLabel(tr("particles N"));
    plot_->yAxis->setLabel(tr("particle-steps per second"));
    plot_->legend->setVisible(true);
    installPlotExportMenu(plot_);
    progress_ = new QProgressBar(this);
    status_ = new QLabel(tr("Times the scenes at growing N on the CPU and, where OpenGL 4.3 is available, on "
                            "the GPU. Right-click the plot to export it."),
                         this);
    status_->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(this);
    startButton_ = buttons->addButton(tr("Start"), QDialogButtonBox::ActionRole);
    stopButton_ = buttons->addButton(tr("Stop"), QDialogButtonBox::ActionRole);
    stopButton_->setEnabled(false);
    auto* exportButton = buttons->addButton(tr("Export…"), QDialogButtonBox::ActionRole);
    buttons->addButton(QDialogButtonBox::Close);
    connect(startButton_, &QPushButton::clicked, this, &BenchmarkDialog::start);
    connect(stopButton_, &QPushButton::clicked, this, &BenchmarkDialog::stop);
    connect(exportButton, &QPushButton::clicked, this, [this] { exportPlotImageInteractively(plot_, this); });
    connect(buttons, &QDialogButtonBox::rejected, this, [this] {
        stop();
        reject();
    });
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(plot_, 1);
    layout->addWidget(progress_);
    layout->addWidget(status_);
    layout->addWidget(buttons);
}

void BenchmarkDialog::setJobs(std::vector<Job> jobs) {
    jobs_ = std::move(jobs);
}

void BenchmarkDialog::start() {
    if (running_) return;
    results_.clear();
    tooSlow_.clear();
    plot_->clearGraphs();
    next_ = 0;
    running_ = true;
    progress_->setRange(0, static_cast<int>(jobs_.size()));
    progress_->setValue(0);
    startButton_->setEnabled(false);
    stopButton_->setEnabled(true);
    QTimer::singleShot(0, this, &BenchmarkDialog::runNext);
}

void BenchmarkDialog::stop() {
    if (!running_) return;
    running_ = false;
    startButton_->setEnabled(true);
    stopButton_->setEnabled(false);
    status_->setText(tr("Stopped after %1 of %2 measurements.").arg(next_).arg(jobs_.size()));
    emit finished();
}

void BenchmarkDialog::runNext() {
    if (!running_) return;
    if (next_ >= jobs_.size()) {
        running_ = false;
        startButton_->setEnabled(true);
        stopButton_->setEnabled(false);
        status_->setText(
            tr("Done: %1 measurements. Right-click the plot to save it or its data.").arg(results_.size()));
        emit finished();
        return;
    }
    const Job job = jobs_[next_++];
    progress_->setValue(static_cast<int>(next_));
    const std::string key = job.scene + "/" + gl::backendName(job.backend);
    if (std::find(tooSlow_.begin(), tooSlow_.end(), key) == tooSlow_.end()) {
        status_->setText(tr("Timing %1 with %2 particles on the %3…")
                             .arg(sceneTitle(job.scene))
                             .arg(job.particles)
                             .arg(job.backend == gl::Backend::Gl ? tr("GPU") : tr("CPU")));
        status_->repaint();
        try {
            const Preset preset = gl::scaledPreset(job.scene, job.particles);
            gl::BackendChoice choice = gl::createModel(job.scene, job.backend, &preset, appComputeContext());
            // A GPU job without a GPU is skipped, not timed twice on the CPU.
            if (choice.backend == job.backend) {
                const gl::BenchPoint point =
                    gl::timeModel(*choice.model, job.scene, choice.model->backend(), settings_);
                addPoint(point);
                if (point.microsecondsPerStep > kSlowMicrosecondsPerStep) tooSlow_.push_back(key);
            } else {
                tooSlow_.push_back(key);
                status_->setText(QString::fromStdString(choice.message));
            }
        } catch (const std::exception& e) {
            tooSlow_.push_back(key);
            status_->setText(
                tr("%1 failed: %2").arg(QString::fromStdString(key), QString::fromUtf8(e.what())));
        }
    }
    QTimer::singleShot(0, this, &BenchmarkDialog::runNext);
}

int BenchmarkDialog::graphFor(const std::string& scene, const std::string& backend) {
    const QString name = QString("%1, %2").arg(sceneTitle(scene), backend == "gl" ? tr("GPU") : tr("CPU"));
    for (int g = 0; g < plot_->graphCount(); ++g)
        if (plot_->graph(g)->name() == name) return g;
    QCPGraph* graph = plot_->addGraph();
    graph->setName(name);
    const ModelDescriptor* descriptor = findModel(scene);
    const PlotColour c = descriptor ? descriptor->benchmark.colour : PlotColour{};
    const QColor colour(c.red, c.green, c.blue);
    graph->setPen(QPen(colour, 2, backend == "gl" ? Qt::SolidLine : Qt::DashLine));
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 6));
    return plot_->graphCount() - 1;
}

void BenchmarkDialog::addPoint(const gl::BenchPoint& point) {
    results_.push_back(point);
    plot_->graph(graphFor(point.scene, point.backend))
        ->addData(double(point.particles), point.particleStepsPerSecond);
    plot_->rescaleAxes();
    plot_->xAxis->scaleRange(1.3);
    plot_->yAxis->scaleRange(1.3);
    plot_->replot();
}

} // namespace pl::ui
