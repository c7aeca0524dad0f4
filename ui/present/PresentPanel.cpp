// PresentPanel: its plots are separate instances of the docks' plot classes (they read the same series
// store), so entering and leaving present mode never moves a dock's widgets around.
#include "PresentPanel.h"

#include "LessonControls.h"
#include "PresentReadouts.h"
#include "SimulationController.h"
#include "plots/DistributionPlot.h"
#include "plots/SeriesPlotSpecs.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace pl::ui {

namespace {
constexpr double kPanelFontScale = 1.35;
constexpr int kPlotMinimumHeight = 220; // below this a short window scrolls the panel instead

// Each scene's first choice: the plot a first lesson on it is about.
QString defaultPlot(const QString& kind) {
    if (kind == QLatin1String("gas")) return QStringLiteral("speedHistogram");
    if (kind == QLatin1String("dsmc")) return QStringLiteral("temperaturesPlot");
    return QStringLiteral("densityErrorPlot");
}
} // namespace

PresentPanel::PresentPanel(SimulationController* controller, QWidget* parent)
    : QWidget(parent), controller_(controller), plotBox_(new QVBoxLayout) {
    setObjectName("presentPanel");
    QFont big = font();
    big.setPointSizeF(font().pointSizeF() * kPanelFontScale);
    setFont(big); // before the children exist: styled widgets keep the font they were made with
    readouts_ = new PresentReadouts(controller, this);
    chooser_ = new QComboBox(this);
    controls_ = new LessonControls(controller, this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(readouts_);
    chooser_->setObjectName("presentPlotChooser");
    chooser_->setFocusPolicy(Qt::NoFocus);
    chooser_->setToolTip(tr("Which of the scene's plots to show"));
    auto* top = new QHBoxLayout;
    top->addWidget(chooser_, 1);
    auto* leave = new QPushButton(tr("Leave (Esc)"), this);
    leave->setObjectName("presentLeave");
    leave->setFocusPolicy(Qt::NoFocus);
    top->addWidget(leave);
    layout->addLayout(top);
    layout->addLayout(plotBox_, 1);
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
    const QString wanted = QSettings().value("present/plot/" + kind, defaultPlot(kind)).toString();
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
    plot_->setMinimumHeight(kPlotMinimumHeight);
    plotBox_->addWidget(plot_);
    plot_->show();
}

} // namespace pl::ui
