// SpeedHistogramPlot: bars of the measured density, the Rayleigh curve at the measured kT, KS distance.
#include "SpeedHistogramPlot.h"

#include "SimulationController.h"

#include <QVBoxLayout>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
constexpr int kFramesPerRefresh = 6; // ~10 Hz at 60 frames per second
constexpr int kTheoryPoints = 200;
} // namespace

SpeedHistogramPlot::SpeedHistogramPlot(SimulationController* controller, QWidget* parent)
    : QWidget(parent), controller_(controller), plot_(new QCustomPlot(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(plot_);
    bars_ = new QCPBars(plot_->xAxis, plot_->yAxis);
    bars_->setName(tr("measured"));
    bars_->setPen(Qt::NoPen);
    bars_->setBrush(QColor(110, 135, 176, 200));
    theory_ = plot_->addGraph();
    theory_->setName(tr("2D Maxwell–Boltzmann at measured kT"));
    theory_->setPen(QPen(QColor(200, 60, 60), 2));
    plot_->xAxis->setLabel(tr("speed"));
    plot_->yAxis->setLabel(tr("probability density"));
    plot_->legend->setVisible(true);
    plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    plot_->plotLayout()->insertRow(0);
    title_ = new QCPTextElement(plot_, "", QFont(font().family(), 10));
    plot_->plotLayout()->addElement(0, 0, title_);
    connect(controller, &SimulationController::frameAdvanced, this, [this] {
        if (++framesSinceRefresh_ >= kFramesPerRefresh) refresh();
    });
    connect(controller, &SimulationController::modelReplaced, this, &SpeedHistogramPlot::refresh);
}

void SpeedHistogramPlot::refresh() {
    framesSinceRefresh_ = 0;
    Model* model = controller_->model();
    if (!model) return;
    const auto histograms = model->histograms();
    if (histograms.empty()) return;
    const NamedHistogram& h = histograms.front();
    QVector<double> centres, densities;
    double top = 0;
    for (std::size_t b = 0; b < h.counts.bins(); ++b) {
        centres << h.counts.binCentre(b);
        densities << h.counts.density(b);
        top = std::max(top, densities.back());
    }
    bars_->setWidth(h.counts.binWidth());
    bars_->setData(centres, densities, true);
    QVector<double> vs, fs;
    if (h.theoryDensity) {
        for (int i = 0; i <= kTheoryPoints; ++i) {
            vs << h.counts.hi() * i / kTheoryPoints;
            fs << h.theoryDensity(vs.back());
            top = std::max(top, fs.back());
        }
    }
    theory_->setData(vs, fs, true);
    plot_->xAxis->setRange(0, h.counts.hi());
    plot_->yAxis->setRange(0, 1.15 * top);
    title_->setText(QString::fromStdString(h.summary));
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace pl::ui
