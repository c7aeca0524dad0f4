// DistributionPlot: the histogram range follows the measured temperature, so averaged samples are
// resampled onto the newest bins before they are averaged.
#include "DistributionPlot.h"
#include "i18n/Translations.h"

#include "LiveReplot.h"
#include "PlotExport.h"
#include "PlotStyle.h"
#include "ReadablePlot.h"
#include "SimulationController.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>
#include <cmath>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
constexpr int kTheoryPoints = 200;
const QColor kBarColours[] = {QColor(110, 135, 176, 190), QColor(214, 150, 60, 170),
                              QColor(90, 170, 110, 170)};
const QColor kTheoryColours[] = {QColor(200, 50, 50), QColor(120, 60, 20), QColor(30, 110, 50)};
} // namespace

double DistributionPlot::Sample::at(double x) const {
    const double f = (x - lo) / width;
    if (f < 0) return 0.0;
    const auto i = static_cast<std::size_t>(f);
    return i < density.size() ? density[i] : 0.0;
}

DistributionPlot::DistributionPlot(SimulationController* controller, const QString& objectName,
                                   const QString& namePrefix, QWidget* parent)
    : QWidget(parent), controller_(controller), prefix_(namePrefix.toStdString()),
      plot_(new QCustomPlot(this)), window_(new QSpinBox(this)) {
    plot_->setObjectName(objectName);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* controls = new QHBoxLayout;
    controls->setContentsMargins(6, 2, 6, 0);
    controls->addWidget(new QLabel(tr("Average over"), this));
    window_->setRange(1, 200);
    // "1 sample", "2 samples"; German "1 Stichprobe", "2 Stichproben": the plural sentence without its
    // number.
    const auto suffix = [this](int n) {
        const QString text = tr("%n sample(s)", "a spin box's value and unit", n),
                      number = QString::number(n);
        window_->setSuffix(text.startsWith(number) ? text.mid(number.size()) : " " + text);
    };
    connect(window_, &QSpinBox::valueChanged, this, suffix);
    suffix(window_->value());
    window_->setToolTip(tr("Time-averages the bars over the last samples (about 20 per second of running)"));
    controls->addWidget(window_);
    controls->addStretch(1);
    layout->addLayout(controls);
    layout->addWidget(plot_);
    plot_->yAxis->setLabel(tr("probability density"));
    // From the top: the summary as the title, the legend, the bars; nothing is drawn over the bars.
    plot_->plotLayout()->insertRow(0);
    title_ = new QCPTextElement(plot_, "", QFont(font().family(), font().pointSize()));
    plot_->plotLayout()->addElement(0, 0, title_);
    placeLegendRow(plot_, plot_->legend, 1);
    installPlotExportMenu(plot_);
    keepDataReadable(plot_);
    connect(window_, &QSpinBox::valueChanged, this, &DistributionPlot::redraw);
    connect(controller->series(), &SeriesStore::appended, this, &DistributionPlot::refresh);
    connect(controller->series(), &SeriesStore::restarted, this, [this] {
        history_.clear();
        refresh();
    });
}

void DistributionPlot::refresh() {
    Model* model = controller_->model();
    if (!model || !isVisible()) return; // histograms cost a pass (and a sort) over all particles
    latest_.clear();
    for (auto& h : model->histograms())
        if (h.name.starts_with(prefix_)) latest_.push_back(std::move(h));
    history_.resize(latest_.size());
    for (std::size_t h = 0; h < latest_.size(); ++h) {
        const Histogram& counts = latest_[h].counts;
        Sample now{counts.lo(), counts.binWidth(), {}};
        for (std::size_t b = 0; b < counts.bins(); ++b) now.density.push_back(counts.density(b));
        history_[h].push_back(std::move(now));
    }
    redraw();
}

void DistributionPlot::redraw() {
    plot_->clearPlottables();
    const auto keep = static_cast<std::size_t>(window_->value());
    double top = 0, right = 0;
    QStringList summaries;
    for (std::size_t h = 0; h < latest_.size(); ++h) {
        const NamedHistogram& named = latest_[h];
        const Histogram& counts = named.counts;
        auto& past = history_[h];
        while (past.size() > keep) past.pop_front();

        QVector<double> centres, densities;
        for (std::size_t b = 0; b < counts.bins(); ++b) {
            const double x = counts.binCentre(b);
            double sum = 0;
            for (const auto& s : past) sum += s.at(x);
            centres << x;
            densities << sum / static_cast<double>(past.size());
            top = std::max(top, densities.back());
        }
        const std::size_t colour = std::min<std::size_t>(h, std::size(kBarColours) - 1);
        auto* bars = new QCPBars(plot_->xAxis, plot_->yAxis);
        const QString label = coreText(named.label);
        bars->setName(latest_.size() > 1 ? label : tr("measured"));
        bars->setPen(Qt::NoPen);
        bars->setBrush(kBarColours[colour]);
        bars->setWidth(counts.binWidth());
        bars->setData(centres, densities, true);
        right = std::max(right, counts.hi());
        if (named.theoryDensity) {
            QCPGraph* theory = plot_->addGraph();
            // With several species the bars name the species and each curve says only that it is theory.
            theory->setName(latest_.size() > 1 ? tr("%1 (theory)").arg(label) : tr("Maxwell–Boltzmann"));
            theory->setPen(QPen(kTheoryColours[colour], 2));
            QVector<double> xs, fs;
            for (int i = 0; i <= kTheoryPoints; ++i) {
                xs << counts.lo() + (counts.hi() - counts.lo()) * i / kTheoryPoints;
                fs << named.theoryDensity(xs.back());
                if (std::isfinite(fs.back())) top = std::max(top, fs.back());
            }
            theory->setData(xs, fs, true);
        }
        summaries << coreSentence(named.summary);
        plot_->xAxis->setLabel(coreText(named.axis));
        plot_->xAxis->setRangeLower(counts.lo());
    }
    if (right > 0) plot_->xAxis->setRangeUpper(right);
    plot_->yAxis->setRange(0, top > 0 ? 1.15 * top : 1.0);
    setFittedTitle(title_, summaries.join("\n"));
    replotLive(plot_);
}

void DistributionPlot::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    refresh();
}

void DistributionPlot::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) applyPlotFont(plot_, font());
}

} // namespace pl::ui
