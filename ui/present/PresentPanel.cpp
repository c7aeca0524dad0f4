// PresentPanel: its plots are separate instances of the docks' plot classes (they read the same series
// store), so entering and leaving present mode never moves a dock's widgets around.
#include "PresentPanel.h"

#include "LessonControls.h"
#include "PresentBoard.h"
#include "PresentReadouts.h"
#include "SimulationController.h"
#include "plots/DistributionPlot.h"
#include "plots/SeriesPlotSpecs.h"

#include <QAction>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QToolButton>
#include <QVBoxLayout>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
constexpr int kPlotMinimumHeight = 170;  // readable; a taller window gives the plot the rest
constexpr int kPanelMinimumHeight = 150; // per panel of a plot of several (the density error's two)
constexpr int kChooserCharacters = 12;   // the chooser may be narrower than its longest title
constexpr int kAxisGap = 2;              // px between an axis, its tick values and its label
const char* kRecordStyle = "QToolButton { padding: 6px 8px; }"
                           "QToolButton:checked { background: #c0392b; color: white; font-weight: bold; }";
} // namespace

PresentPanel::PresentPanel(SimulationController* controller, QAction* record, const QFont& font,
                           QWidget* parent)
    : QWidget(parent), controller_(controller), plotBox_(new QVBoxLayout) {
    setObjectName("presentPanel");
    setFont(font); // before the children exist: styled widgets keep the font they were made with
    auto* layout = new QVBoxLayout(this);
    // Record and Leave come first, so a short window that scrolls the panel still shows them.
    auto* top = new QHBoxLayout;
    if (record) {
        auto* button = new QToolButton(this);
        button->setObjectName("presentRecord");
        button->setDefaultAction(record); // its text and checked state say whether a clip is recording
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        button->setFocusPolicy(Qt::NoFocus);
        button->setStyleSheet(kRecordStyle);
        top->addWidget(button);
    }
    top->addStretch(1);
    auto* leave = new QPushButton(tr("Leave (Esc)"), this);
    leave->setObjectName("presentLeave");
    leave->setFocusPolicy(Qt::NoFocus);
    top->addWidget(leave);
    layout->addLayout(top);
    readouts_ = new PresentReadouts(controller, this);
    layout->addWidget(readouts_);
    chooser_ = new QComboBox(this);
    chooser_->setObjectName("presentPlotChooser");
    chooser_->setFocusPolicy(Qt::NoFocus);
    chooser_->setToolTip(tr("Which of the scene's plots to show"));
    chooser_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    chooser_->setMinimumContentsLength(kChooserCharacters);
    layout->addWidget(chooser_);
    layout->addLayout(plotBox_, 1);
    controls_ = new LessonControls(controller, this);
    layout->addWidget(controls_);
    connect(leave, &QPushButton::clicked, this, &PresentPanel::leaveRequested);
    connect(controls_, &LessonControls::toolRequested, this, &PresentPanel::toolRequested);
    connect(chooser_, &QComboBox::activated, this, [this](int item) {
        if (const Model* model = controller_->model())
            QSettings().setValue("present/plot/" + QString::fromStdString(model->kind()),
                                 chooser_->itemData(item).toString());
        showPlot(item);
    });
    connect(controller, &SimulationController::modelReplaced, this, &PresentPanel::fillChooser);
    fillChooser();
}

void PresentPanel::fillChooser() {
    const Model* model = controller_->model();
    const QString kind = model ? QString::fromStdString(model->kind()) : QString();
    const QSignalBlocker block(chooser_);
    chooser_->clear();
    if (distributionKinds(QStringLiteral("speedHistogram")).contains(kind))
        chooser_->addItem(tr("Speed distribution"), QStringLiteral("speedHistogram"));
    if (distributionKinds(QStringLiteral("vxHistogram")).contains(kind))
        chooser_->addItem(tr("v_x distribution"), QStringLiteral("vxHistogram"));
    for (const SeriesPlotSpec& spec : seriesPlotSpecs())
        if (spec.kinds.contains(kind)) chooser_->addItem(spec.title, spec.objectName);
    // The registration's first plot, unless the teacher chose another for this kind before.
    const QString first = model ? QString::fromStdString(presentPlot(*model)) : QString();
    const QString wanted = QSettings().value("present/plot/" + kind, first).toString();
    const int item = std::max(0, chooser_->findData(wanted));
    chooser_->setCurrentIndex(item);
    showPlot(item);
}

void PresentPanel::showPlot(int item) {
    delete plot_;
    plot_ = nullptr;
    const QString name = chooser_->itemData(item).toString();
    if (name.isEmpty()) return;
    // "present_" keeps the docks' plots the only ones under their own object names.
    if (name == QLatin1String("speedHistogram") || name == QLatin1String("vxHistogram")) {
        plot_ = new DistributionPlot(controller_, "present_" + name,
                                     name == QLatin1String("speedHistogram") ? "speed" : "vx", this);
    } else {
        for (SeriesPlotSpec spec : seriesPlotSpecs())
            if (spec.objectName == name) {
                spec.objectName = "present_" + name;
                plot_ = new SeriesPlot(controller_, spec, this);
            }
    }
    if (!plot_) return;
    plot_->setObjectName("presentPlot");
    // The plot's text is the board's divided by kFontScale (the usual size; in projector mode about 1.2×
    // it): at the board's size the title, legend, tick values and axis labels took about 110 px of a
    // 150 px panel on a projector at 1024 × 700, leaving the curves 40 px.
    QFont plotFont = font();
    plotFont.setPointSizeF(font().pointSizeF() / kFontScale);
    plot_->setFont(plotFont);
    // The drawing itself keeps a readable height, whatever controls the plot has above it; the gaps
    // between title, legend, axes and their labels are pared down, each pixel going to the curves.
    for (QCustomPlot* canvas : plot_->findChildren<QCustomPlot*>()) {
        canvas->setMinimumHeight(
            std::max(kPlotMinimumHeight, kPanelMinimumHeight * std::max(1, canvas->axisRectCount())));
        canvas->plotLayout()->setRowSpacing(0);
        for (QCPAxisRect* rect : canvas->axisRects()) {
            rect->setMinimumMargins(QMargins());
            for (QCPAxis* axis : rect->axes()) {
                axis->setPadding(kAxisGap);
                axis->setTickLabelPadding(kAxisGap);
                axis->setLabelPadding(kAxisGap);
            }
        }
        for (int i = 0; i < canvas->plotLayout()->elementCount(); ++i)
            if (auto* legend = qobject_cast<QCPLegend*>(canvas->plotLayout()->elementAt(i))) {
                legend->setMargins(QMargins(kAxisGap, 0, kAxisGap, 0));
                legend->setRowSpacing(0);
            }
    }
    plotBox_->addWidget(plot_);
    plot_->show();
}

} // namespace pl::ui
