// MainWindow: composition only. Actions live in MainWindowActions.cpp.
#include "MainWindow.h"
#include "methods/MethodsLab.h"

#include "Autosave.h"
#include "ExperimentDocument.h"
#include "PaceAdvice.h"
#include "ShortcutGuard.h"
#include "SimulationController.h"
#include "ViewportRoom.h"
#include "WindowFit.h"
#include "panels/ParameterPanel.h"
#include "plots/DistributionPlot.h"
#include "plots/ProfilePlot.h"
#include "plots/SeriesPlotSpecs.h"
#include "present/PresentMode.h"
#include "viewport/GLViewport.h"
#include "viewport/SoftwareViewport.h"
#include "viewport/ViewportCore.h"

#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QGuiApplication>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QSaveFile>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
constexpr double kProjectorFontScale = 1.6;
constexpr int kStatusIntervalMs = 250;
// Small enough that at 1024 px the plots leave the viewport its room; axes and legends still fit.
constexpr int kPlotMinimumWidth = 280;
// Below ViewportRoom::kReadablePanelHeight per panel the docks become tabs (WindowFit.h); this minimum
// only keeps a plot from vanishing while a window is made smaller.
constexpr int kPanelMinimumHeight = 80;
constexpr int kCanvasTitleRoom = 20;     // a legend or caption row above the panels
constexpr QSize kFirstWindow(1280, 800); // on a larger screen; a smaller one gets its available area

// A plot's minimum size: its width, and a readable height for each of its panels.
void keepReadable(QWidget* plot) {
    plot->setMinimumWidth(kPlotMinimumWidth);
    for (QCustomPlot* canvas : plot->findChildren<QCustomPlot*>())
        canvas->setMinimumHeight(kPanelMinimumHeight * std::max(1, canvas->axisRectCount()) +
                                 kCanvasTitleRoom);
}
} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), controller_(new SimulationController(this)),
      document_(new ExperimentDocument(controller_, this)), baseFont_(QApplication::font()) {
    setWindowTitle(tr("ParticleLab"));
    setDockOptions(AnimatedDocks | AllowTabbedDocks | AllowNestedDocks);
    createViewport();
    createActions();
    createSceneBar();
    createToolPalette();
    createDocks();
    status_ = new QLabel(this);
    status_->setObjectName("statusLine");
    statusBar()->addPermanentWidget(status_);
    statusBar()->addWidget(new PaceAdvice(controller_, this)); // shows only while the pace falls short
    // A message that does not fit beside the status line takes the whole bar while it shows: clipped,
    // "Run complete: 500 steps." ran into the particle count and read "Run complete: 52,000 particles".
    connect(statusBar(), &QStatusBar::messageChanged, this, [this](const QString& message) {
        const int room =
            statusBar()->width() - status_->sizeHint().width() - 4 * statusBar()->fontMetrics().height();
        status_->setVisible(message.isEmpty() ||
                            statusBar()->fontMetrics().horizontalAdvance(message) <= room);
    });
    auto* statusTimer = new QTimer(this);
    connect(statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
    statusTimer->start(kStatusIntervalMs);
    connect(controller_, &SimulationController::modelReplaced, this, &MainWindow::modelChanged);
    connect(controller_, &SimulationController::frameAdvanced, this, &MainWindow::updateStatus);
    connect(controller_, &SimulationController::runningChanged, this, &MainWindow::updateStatus);
    connect(controller_, &SimulationController::failed, this, [this](const QString& message) {
        updateRunActions(); // the viewport says to Reset; Play would do nothing
        QMessageBox::warning(this, tr("The simulation stopped"), message);
    });
    connect(controller_, &SimulationController::parametersChanged, this, &MainWindow::updateRunActions);
    // A body dragged into the shock tube brings the forces dock; the last one removed takes it away.
    connect(controller_, &SimulationController::edited, this, &MainWindow::showDocksThatApply);
    connect(controller_, &SimulationController::runningChanged, this, [this](bool running) {
        playAction_->setText(running ? tr("Pause") : tr("Play"));
        playAction_->setIcon(style()->standardIcon(running ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
        if (running) statusBar()->clearMessage(); // "Run complete" and the like belong to the run before
    });
    connect(document_, &ExperimentDocument::changed, this, &MainWindow::documentChanged);
    const auto showMessage = [this](const QString& message) { statusBar()->showMessage(message, 6000); };
    connect(viewportCore_, &ViewportCore::statusMessage, this, showMessage);
    connect(controller_, &SimulationController::notice, this, showMessage);
    // After the window's own modelReplaced handler, so a scene change while presenting hides its docks.
    present_ = new PresentMode(this, controller_, viewport_, baseFont_);
    connect(present_, &PresentMode::activeChanged, presentAction_, [this](bool on) {
        const QSignalBlocker block(presentAction_);
        presentAction_->setChecked(on);
    });
    connect(present_, &PresentMode::toolRequested, this,
            [this](ViewportTool tool) { tools_->actions().at(static_cast<int>(tool))->trigger(); });
    room_ = new ViewportRoom(this);
    autosave_ = new Autosave(controller_, document_, this);
    readSettings();
    new ShortcutGuard(this, viewport_); // the shortcuts act whatever has focus, except while typing
    viewport_->setFocus(Qt::OtherFocusReason);
}

MainWindow::~MainWindow() {
    controller_->disconnect(this);
}

void MainWindow::createViewport() {
    // The offscreen platform shows no native OpenGL windows (and Qt 6.4 crashes making GL widgets there):
    // draw with QPainter there.
    if (QGuiApplication::platformName() == QLatin1String("offscreen")) {
        auto* view = new SoftwareViewport(controller_, this);
        viewportCore_ = view->core();
        viewport_ = view;
    } else {
        auto* view = new GLViewport(controller_, this);
        viewportCore_ = view->core();
        viewport_ = view;
    }
    viewport_->setObjectName("viewport");
    setCentralWidget(viewport_);
}

QDockWidget* MainWindow::addDock(QWidget* content, const QString& title, const QString& objectName,
                                 Qt::DockWidgetArea area, const QStringList& kinds) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(objectName);
    dock->setWidget(content);
    dock->setProperty("kinds", kinds);
    addDockWidget(area, dock);
    viewMenu_->addAction(dock->toggleViewAction());
    return dock;
}

void MainWindow::createDocks() {
    parameters_ = new ParameterPanel(controller_, this);
    parameters_->setMinimumWidth(280);
    addDock(parameters_, tr("Parameters"), "parametersDock", Qt::LeftDockWidgetArea);
    histogram_ = new DistributionPlot(controller_, "speedHistogram", "speed", this);
    keepReadable(histogram_);
    QDockWidget* speed = addDock(histogram_, tr("Speed distribution"), "speedHistogramDock",
                                 Qt::RightDockWidgetArea, distributionKinds("speedHistogram"));
    auto* vx = new DistributionPlot(controller_, "vxHistogram", "vx", this);
    keepReadable(vx);
    tabifyDockWidget(speed, addDock(vx, tr("v_x distribution"), "vxHistogramDock", Qt::RightDockWidgetArea,
                                    distributionKinds("vxHistogram")));
    speed->raise();
    QDockWidget* previous = nullptr;
    for (const SeriesPlotSpec& spec : seriesPlotSpecs()) {
        auto* plot = new SeriesPlot(controller_, spec, this);
        keepReadable(plot);
        seriesPlots_.push_back(plot);
        QDockWidget* dock =
            addDock(plot, spec.title, spec.objectName + "Dock", Qt::RightDockWidgetArea, spec.kinds);
        dock->setProperty("needsBodies", spec.needsBodies);
        if (previous) tabifyDockWidget(previous, dock);
        previous = dock;
    }
    if (!seriesPlots_.empty())
        findChild<QDockWidget*>(seriesPlots_.front()->spec().objectName + "Dock")->raise();
    // A field along the line drawn with the Profile line tool: for every scene with sampled fields.
    profilePlot_ = new ProfilePlot(controller_, viewportCore_, this);
    keepReadable(profilePlot_);
    QDockWidget* profile = addDock(profilePlot_, tr("Profile"), "profileDock", Qt::RightDockWidgetArea);
    profile->setProperty("needsFields", true);
    if (previous) tabifyDockWidget(previous, profile);
    connect(viewportCore_, &ViewportCore::profileLineChanged, profile, [this, profile] {
        if (!viewportCore_->profileLine() || (present_ && present_->isActive())) return;
        profile->show(); // a line just drawn: its profile comes to the front
        profile->raise();
    });
    // Experiments on the numerics themselves, for every scene: opened from the View menu as a floating
    // window, so that while hidden it takes no room from the scene's docks.
    QDockWidget* lab = addDock(new MethodsLab(this, controller_), tr("Methods lab"), "methodsLabDock",
                               Qt::RightDockWidgetArea);
    lab->setFloating(true);
    lab->resize(920, 680);
    lab->hide();
    // On a 1024 × 700 screen that ran past the bottom edge: each time it opens, it is fitted into the
    // screen's available area, the window manager's frame included.
    connect(lab, &QDockWidget::visibilityChanged, lab, [lab](bool visible) {
        if (!visible || !lab->isFloating()) return;
        lab->resize(firstWindowSize(lab, lab->size()));
        keepInsideScreen(lab);
    });
}

bool MainWindow::dockApplies(const QDockWidget* dock) const {
    const Model* model = controller_->model();
    if (!model) return false;
    const QStringList kinds = dock->property("kinds").toStringList();
    const SceneTools* tools = controller_->tools();
    return (kinds.isEmpty() || kinds.contains(QString::fromStdString(model->kind()))) &&
           (!dock->property("needsFields").toBool() || model->sampledFields()) &&
           (!dock->property("needsBodies").toBool() || (tools && !tools->obstacles().empty()));
}

void MainWindow::showDocksThatApply() {
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        const bool applies = dockApplies(dock);
        dock->toggleViewAction()->setEnabled(applies);
        if (!applies && !dock->isHidden()) {
            hiddenForScene_.insert(dock);
            dock->hide();
        } else if (applies && hiddenForScene_.remove(dock)) {
            dock->show();
        }
    }
}

void MainWindow::modelChanged() {
    const Model* model = controller_->model();
    if (!model) return;
    const QString kind = QString::fromStdString(model->kind());
    scenePicker_->setCurrentIndex(scenePicker_->findData(kind));
    showDocksThatApply();
    // The scene's first series dock comes to the front of the tabbed stack.
    for (SeriesPlot* plot : seriesPlots_) {
        auto* dock = findChild<QDockWidget*>(plot->spec().objectName + "Dock");
        if (dock && dockApplies(dock)) {
            dock->raise();
            break;
        }
    }
    tools_->setEnabled(controller_->model()->tools() != nullptr);
    heat_->setEnabled(controller_->model()->tools() != nullptr);
    // An imported run is shown, not run: what would change it is off until a preset is opened.
    const bool ours = !controller_->isReadOnly();
    for (QAction* action : std::as_const(runActions_)) action->setEnabled(ours);
    updateRunActions();
    speed_->setEnabled(ours);
    parameters_->setEnabled(ours);
    viewportCore_->zoomToFit();
    updateStatus();
    if (room_) room_->refit(); // the Show chooser and the scene's docks come and go
}

void MainWindow::updateRunActions() {
    const Model* model = controller_->model();
    const bool runnable = model && !controller_->isReadOnly() && !model->failure();
    playAction_->setEnabled(runnable);
    stepAction_->setEnabled(runnable);
}

void MainWindow::documentChanged() {
    setWindowTitle(tr("%1[*] — ParticleLab").arg(document_->title()));
    setWindowModified(document_->isModified());
    fillRecentMenu();
    fillPresetPicker();
}

bool MainWindow::openPreset(const QString& nameOrPath) {
    return document_->open(nameOrPath);
}

QImage MainWindow::viewportImage() const {
    if (auto* gl = qobject_cast<GLViewport*>(viewport_)) return gl->grabFramebuffer();
    return viewport_->grab().toImage();
}

QImage MainWindow::windowImage() {
    QImage image = grab().toImage();
    if (qobject_cast<GLViewport*>(viewport_)) {
        QPainter painter(&image);
        painter.drawImage(viewport_->mapTo(this, QPoint(0, 0)), viewportImage());
    }
    return image;
}

QString MainWindow::saveViewportImage(const QString& path) {
    const QImage image = viewportImage();
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.commit())
        return tr("Cannot write %1: %2").arg(path, file.errorString());
    return {};
}

void MainWindow::setProjectorMode(bool on) {
    QFont font = baseFont_;
    if (on) font.setPointSizeF(baseFont_.pointSizeF() * kProjectorFontScale);
    room_->keepWidthAcross([&font] { QApplication::setFont(font); }); // larger text, not a smaller view
    projectorAction_->setChecked(on);
    room_->refit(); // once the bars and docks have their new size
}

void MainWindow::updateStatus() {
    const Model* model = controller_->model();
    if (!model) return;
    if (controller_->isReadOnly()) {
        status_->setText(tr("%1, read-only: %2 particles, %3 rows up to t = %4, step %5. Open a preset to "
                            "simulate again.")
                             .arg(controller_->importedFrom())
                             .arg(model->particleCount())
                             .arg(controller_->series()->rows())
                             .arg(model->time(), 0, 'g', 6)
                             .arg(model->stepCount()));
        return;
    }
    // The pace as the class sees it: steps a second and how much simulated time a second of the lesson
    // shows; while time stands, that it stands (not "0 steps/s, 0 fps").
    const QLocale locale;
    const QString particles = locale.toString(static_cast<qulonglong>(model->particleCount()));
    const QString time = locale.toString(model->time(), 'g', 6);
    const QString step = locale.toString(static_cast<qlonglong>(model->stepCount()));
    const QString backend = model->backend() == "gl" ? tr("GPU") : tr("CPU");
    if (!controller_->isRunning()) {
        status_->setText(
            tr("%1 particles   t = %2   step %3   stopped   %4").arg(particles, time, step, backend));
        return;
    }
    status_->setText(tr("%1 particles   t = %2   step %3   %4 steps/s (%5 %6 per second)   %7 fps   %8")
                         .arg(particles, time, step)
                         .arg(locale.toString(controller_->stepsPerSecond(), 'f', 0))
                         .arg(locale.toString(controller_->simulatedPerSecond(), 'g', 3))
                         .arg(controller_->timeUnit())
                         .arg(locale.toString(viewportCore_->framesPerSecond(), 'f', 0))
                         .arg(backend));
}

void MainWindow::readSettings() {
    QSettings settings;
    // The size the window had last time, small or large; a first window fits the screen it opens on.
    const QByteArray geometry = settings.value("window/geometry").toByteArray();
    if (geometry.isEmpty() || !restoreGeometry(geometry)) resize(firstWindowSize(this, kFirstWindow));
    keepInsideScreen(this);
    restoreState(settings.value("window/state").toByteArray());
    setProjectorMode(settings.value("window/projector", false).toBool());
    try {
        const auto backend =
            gl::backendFromName(settings.value("simulation/backend", "auto").toString().toStdString());
        controller_->setBackend(backend);
        if (auto* action = findChild<QAction*>(
                QString("backend-%1").arg(QString::fromStdString(gl::backendName(backend)))))
            action->setChecked(true);
    } catch (const std::invalid_argument&) { // a stale or hand-edited setting: keep automatic
    }
}

void MainWindow::writeSettings() const {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    settings.setValue("window/projector", projectorAction_->isChecked());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!document_->maybeSave()) {
        event->ignore();
        return;
    }
    // Docks hidden only because this scene lacks their data count as shown for the next start.
    for (QDockWidget* dock : std::as_const(hiddenForScene_)) dock->show();
    writeSettings();
    autosave_->discard(); // a clean exit: nothing to restore next time
    event->accept();
}

} // namespace pl::ui
