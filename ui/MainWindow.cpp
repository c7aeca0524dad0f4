// MainWindow: toolbar (play/pause, step, reset, signed speed, presets), the particle view, the speed
// histogram dock and a status line.
#include "MainWindow.h"

#include "ParticleView.h"
#include "SimulationController.h"
#include "SpeedHistogramPlot.h"
#include "catalog/ModelCatalog.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QLabel>
#include <QMessageBox>
#include <QSpinBox>
#include <QStatusBar>
#include <QToolBar>

namespace pl::ui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), controller_(new SimulationController(this)) {
    setWindowTitle(tr("ParticleLab"));
    setCentralWidget(new ParticleView(controller_, this));
    createActions();
    createDocks();
    status_ = new QLabel(this);
    statusBar()->addWidget(status_, 1);
    connect(controller_, &SimulationController::frameAdvanced, this, &MainWindow::updateStatus);
    connect(controller_, &SimulationController::failed, this, [this](const QString& message) {
        QMessageBox::warning(this, tr("The simulation stopped"), message);
    });
    connect(controller_, &SimulationController::runningChanged, this,
            [this](bool running) { playAction_->setText(running ? tr("Pause") : tr("Play")); });
}

void MainWindow::createActions() {
    QToolBar* bar = addToolBar(tr("Simulation"));
    bar->setObjectName("simulationToolBar");
    playAction_ = bar->addAction(tr("Play"), controller_, &SimulationController::togglePlay);
    playAction_->setShortcut(Qt::Key_Space);
    playAction_->setToolTip(tr("Run or pause the simulation (Space)"));
    QAction* step = bar->addAction(tr("Step"), controller_, &SimulationController::stepOnce);
    step->setShortcut(Qt::Key_Period);
    step->setToolTip(tr("Advance one time step (.)"));
    QAction* reset = bar->addAction(tr("Reset"), controller_, &SimulationController::reset);
    reset->setShortcut(Qt::CTRL | Qt::Key_R);
    reset->setToolTip(tr("Restart from the preset's initial state (Ctrl+R)"));
    bar->addSeparator();
    bar->addWidget(new QLabel(tr(" Steps per frame "), bar));
    speed_ = new QSpinBox(bar);
    speed_->setRange(-10, 10);
    speed_->setValue(controller_->stepsPerFrame());
    speed_->setToolTip(tr("Signed speed: negative values run time backwards, 0 pauses"));
    connect(speed_, &QSpinBox::valueChanged, controller_, &SimulationController::setStepsPerFrame);
    bar->addWidget(speed_);
    bar->addSeparator();
    presetPicker_ = new QComboBox(bar);
    for (const auto& p : builtinPresets())
        presetPicker_->addItem(QString::fromStdString(p.name), QString::fromStdString(p.name));
    presetPicker_->setToolTip(tr("Built-in experiments"));
    connect(presetPicker_, &QComboBox::activated, this,
            [this](int index) { openPreset(presetPicker_->itemData(index).toString()); });
    bar->addWidget(presetPicker_);
    QAction* open = bar->addAction(tr("Open…"), this, [this] {
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Open preset"), {}, tr("Presets (*.json)"));
        if (!path.isEmpty()) openPreset(path);
    });
    open->setShortcut(QKeySequence::Open);
}

void MainWindow::createDocks() {
    auto* dock = new QDockWidget(tr("Speed histogram"), this);
    dock->setObjectName("speedHistogramDock");
    histogram_ = new SpeedHistogramPlot(controller_, dock);
    histogram_->setMinimumSize(360, 260);
    dock->setWidget(histogram_);
    addDockWidget(Qt::RightDockWidgetArea, dock);
}

bool MainWindow::openPreset(const QString& nameOrPath) {
    try {
        return loadPreset(pl::loadPreset(nameOrPath.toStdString()), nameOrPath);
    } catch (const std::exception& e) {
        QMessageBox::critical(this, tr("Cannot open preset"), QString::fromUtf8(e.what()));
        return false;
    }
}

bool MainWindow::loadPreset(const Preset& preset, const QString& label) {
    const QString error = controller_->load(preset);
    if (!error.isEmpty()) {
        QMessageBox::critical(this, tr("Cannot open preset"), error);
        return false;
    }
    const int index = presetPicker_->findData(label);
    if (index >= 0) presetPicker_->setCurrentIndex(index);
    setWindowTitle(tr("ParticleLab — %1").arg(label));
    updateStatus();
    return true;
}

void MainWindow::updateStatus() {
    const Model* model = controller_->model();
    if (!model) return;
    status_->setText(tr("%1 particles   t = %2   step %3   %4 steps/s")
                         .arg(model->particleCount())
                         .arg(model->time(), 0, 'g', 6)
                         .arg(model->stepCount())
                         .arg(controller_->stepsPerSecond(), 0, 'f', 0));
}

} // namespace pl::ui
