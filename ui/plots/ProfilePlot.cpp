// ProfilePlot: profileAlong() (core/common/SampledFields.h) does the reading; cells without samples (a
// body on the line) come back as NaN, which QCustomPlot leaves as a gap in the curve.
#include "ProfilePlot.h"

#include "LiveReplot.h"
#include "PlotExport.h"
#include "PlotStyle.h"
#include "ReadablePlot.h"
#include "SimulationController.h"
#include "i18n/Translations.h"
#include "viewport/ViewportCore.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
const QColor kCurve(40, 90, 170);
} // namespace

int ProfilePlot::samplesAlong(double length, double dx, double dy) {
    const double cell = std::min(dx, dy);
    if (!(length > 0) || !(cell > 0)) return 2;
    return static_cast<int>(std::clamp(std::ceil(2.0 * length / cell) + 1.0, 2.0, double(kMaxSamples)));
}

ProfilePlot::ProfilePlot(SimulationController* controller, ViewportCore* viewport, QWidget* parent)
    : QWidget(parent), controller_(controller), viewport_(viewport), fields_(new QComboBox(this)),
      plot_(new QCustomPlot(this)) {
    plot_->setObjectName("profilePlot");
    fields_->setObjectName("profileField");
    fields_->setToolTip(tr("The sampled field plotted along the profile line"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* controls = new QHBoxLayout;
    controls->setContentsMargins(6, 2, 6, 0);
    controls->addWidget(new QLabel(tr("Field"), this));
    controls->addWidget(fields_);
    controls->addStretch(1);
    layout->addLayout(controls);
    layout->addWidget(plot_);
    plot_->setAutoAddPlottableToLegend(false);
    plot_->xAxis->setLabel(tr("distance along the line [m]"));
    plot_->plotLayout()->insertRow(0);
    title_ = new QCPTextElement(plot_, "", QFont(font().family(), font().pointSize()));
    plot_->plotLayout()->addElement(0, 0, title_);
    QCPGraph* graph = plot_->addGraph();
    graph->setPen(QPen(kCurve, 1.8));
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 3));
    installPlotExportMenu(plot_);
    keepDataReadable(plot_);
    connect(fields_, &QComboBox::activated, this, &ProfilePlot::refresh);
    connect(viewport_, &ViewportCore::profileLineChanged, this, &ProfilePlot::refresh);
    connect(controller_->series(), &SeriesStore::appended, this, &ProfilePlot::refresh);
    connect(controller_->series(), &SeriesStore::restarted, this, &ProfilePlot::refresh);
    connect(controller_, &SimulationController::modelReplaced, this, [this] {
        fillChoices();
        refresh();
    });
    fillChoices();
}

void ProfilePlot::fillChoices() {
    const QString kept = fields_->currentData().toString();
    const QSignalBlocker block(fields_);
    fields_->clear();
    const Model* model = controller_->model();
    const SampledFields* sampled = model ? model->sampledFields() : nullptr;
    if (!sampled) return;
    for (const FieldChoice& choice : sampled->fieldChoices())
        fields_->addItem(coreText(choice.label), QString::fromStdString(choice.name));
    const int index = fields_->findData(kept);
    fields_->setCurrentIndex(index >= 0 ? index : 0);
}

void ProfilePlot::refresh() {
    if (!isVisible()) return; // reading a field copies the grid: only for a plot someone sees
    const Model* model = controller_->model();
    const SampledFields* sampled = model ? model->sampledFields() : nullptr;
    const std::optional<QLineF> line = viewport_->profileLine();
    QCPGraph* graph = plot_->graph(0);
    const QString name = fields_->currentData().toString();
    if (!sampled || !line || name.isEmpty()) {
        graph->data()->clear();
        title_->setText(sampled ? tr("Draw a line across the flow with the Profile line tool")
                                : tr("This experiment samples no fields"));
        replotLive(plot_);
        return;
    }
    const FieldGrid grid = sampled->field(name.toStdString());
    const int samples = samplesAlong(line->length(), grid.dx(), grid.dy());
    const FieldProfile profile = profileAlong(grid, line->x1(), line->y1(), line->x2(), line->y2(), samples);
    const QVector<double> distance(profile.distance.begin(), profile.distance.end());
    const QVector<double> values(profile.values.begin(), profile.values.end());
    graph->setData(distance, values, true);
    const QString label = coreText(profile.choice.label);
    graph->setName(label); // the CSV export's series column
    plot_->yAxis->setLabel(
        profile.choice.unit.empty()
            ? label
            : QStringLiteral("%1 [%2]").arg(label, QString::fromStdString(profile.choice.unit)));
    title_->setText(tr("%1 along the line (%2 m)").arg(label).arg(line->length(), 0, 'g', 3));
    plot_->xAxis->setRange(0, std::max(line->length(), 1e-12));
    bool found = false;
    const QCPRange range = graph->getValueRange(found);
    if (found) {
        const double pad =
            range.size() > 0 ? 0.05 * range.size() : std::max(0.05 * std::abs(range.upper), 1.0);
        plot_->yAxis->setRange(range.lower - pad, range.upper + pad);
    }
    replotLive(plot_);
}

void ProfilePlot::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    refresh();
}

void ProfilePlot::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) applyPlotFont(plot_, font());
}

} // namespace pl::ui
