// MainWindow's actions, menus and tool bars. Every toolbar action has a shortcut and a tooltip.
#include "BenchmarkDialog.h"
#include "ExperimentDocument.h"
#include "FileDialogs.h"
#include "MainWindow.h"
#include "PreferencesDialog.h"
#include "SimulationController.h"
#include "SpringSlider.h"
#include "ViewChooser.h"
#include "catalog/ModelCatalog.h"
#include "i18n/Translations.h"
#include "present/PresentMode.h"
#include "viewport/ViewportCore.h"
#include <QSettings>

#include <QActionGroup>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QToolBar>

namespace pl::ui {

namespace {
constexpr double kHeatStep = 1.1;   // one press of Heat / Cool: ×1.1 or ÷1.1 kinetic energy
constexpr int kPresetListRows = 12; // the preset list's height in rows; it scrolls for the rest

QAction* menuAction(QMenu* menu, const QString& text, const QKeySequence& shortcut, const QString& tip) {
    QAction* action = menu->addAction(text);
    action->setShortcut(shortcut);
    action->setToolTip(shortcut.isEmpty()
                           ? tip
                           : QStringLiteral("%1 (%2)").arg(tip, shortcut.toString(QKeySequence::NativeText)));
    action->setStatusTip(tip);
    return action;
}
} // namespace

void MainWindow::createActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QMenu* newMenu = file->addMenu(tr("&New experiment"));
    for (const ModelDescriptor& info : modelCatalog()) {
        QAction* action = newMenu->addAction(coreText(info.title));
        connect(action, &QAction::triggered, this,
                [this, kind = info.kind] { document_->newExperiment(kind); });
    }
    if (!newMenu->actions().isEmpty()) newMenu->actions().front()->setShortcut(QKeySequence::New);
    connect(menuAction(file, tr("&Open preset…"), QKeySequence::Open, tr("Open a preset file")),
            &QAction::triggered, this, [this] {
                const QString path =
                    files::openFileName(this, files::Place::Experiments, tr("Open preset"),
                                        tr("Experiments and snapshots (*.particlelab *.plsnap *.json)"));
                if (!path.isEmpty()) document_->open(path);
            });
    recentMenu_ = file->addMenu(tr("Open &recent"));
    file->addSeparator();
    connect(menuAction(file, tr("&Save preset"), QKeySequence::Save, tr("Save the experiment as a preset")),
            &QAction::triggered, document_, &ExperimentDocument::save);
    connect(menuAction(file, tr("Save preset &as…"), QKeySequence::SaveAs,
                       tr("Save the experiment under a new name")),
            &QAction::triggered, document_, &ExperimentDocument::saveAs);
    connect(menuAction(file, tr("Save sna&pshot…"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_S),
                       tr("Save the experiment with every particle, to continue exactly where it is")),
            &QAction::triggered, this, [this] {
                const QString path =
                    files::saveFileName(this, files::Place::Experiments, tr("Save snapshot"),
                                        document_->title() + ".plsnap", tr("Snapshots (*.plsnap *.json)"));
                if (!path.isEmpty()) document_->saveSnapshotTo(path);
            });
    file->addSeparator();
    connect(menuAction(file, tr("Save viewport &image…"), QKeySequence(Qt::CTRL | Qt::Key_E),
                       tr("Save what the viewport shows as a PNG")),
            &QAction::triggered, this, [this] {
                const QString path =
                    files::saveFileName(this, files::Place::Exports, tr("Save viewport image"),
                                        document_->title() + ".png", tr("PNG image (*.png)"));
                if (path.isEmpty()) return;
                const QString error = saveViewportImage(path);
                if (!error.isEmpty()) QMessageBox::critical(this, tr("Cannot save the image"), error);
            });
    createReportAction(file);
    file->addSeparator();
    createLammpsActions(file);
    file->addSeparator();
    QAction* preferences = menuAction(file, tr("Pr&eferences…"), QKeySequence::Preferences,
                                      tr("Choose the language of ParticleLab"));
    preferences->setObjectName("preferencesAction");
    connect(preferences, &QAction::triggered, this, [this] {
        auto* dialog = new PreferencesDialog(this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
    });
    file->addSeparator();
    connect(menuAction(file, tr("&Quit"), QKeySequence::Quit, tr("Close ParticleLab")), &QAction::triggered,
            this, &QWidget::close);

    QMenu* sim = menuBar()->addMenu(tr("&Simulation"));
    QToolBar* bar = addToolBar(tr("Simulation"));
    bar->setObjectName("simulationToolBar");
    playAction_ = menuAction(sim, tr("Play"), Qt::Key_Space, tr("Run or pause the simulation"));
    playAction_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    playAction_->setObjectName("playAction");
    connect(playAction_, &QAction::triggered, controller_, &SimulationController::togglePlay);
    QAction* step = menuAction(sim, tr("Step"), Qt::Key_Period, tr("Advance one time step"));
    step->setIcon(style()->standardIcon(QStyle::SP_MediaSkipForward));
    connect(step, &QAction::triggered, controller_, &SimulationController::stepOnce);
    stepAction_ = step;
    QAction* reset = menuAction(sim, tr("Reset"), QKeySequence(Qt::CTRL | Qt::Key_R),
                                tr("Restart from the initial state with the current parameters"));
    reset->setIcon(style()->standardIcon(QStyle::SP_BrowserReload));
    connect(reset, &QAction::triggered, controller_, &SimulationController::reset);
    bar->addActions({playAction_, step, reset});
    runActions_ = {playAction_, step, reset};
    createRecordAction(sim, bar);
    bar->addSeparator();
    // The pace: automatic (as many steps as half of each frame allows, up to the scene's watchable rate)
    // or a fixed, signed number of steps per frame; the box shows the automatic pace's steps as it runs.
    autoPace_ = menuAction(sim, tr("Automatic pace"), Qt::Key_A,
                           tr("As many steps as half of each frame allows, up to a pace that keeps the "
                              "scene watchable"));
    autoPace_->setObjectName("autoPaceAction");
    autoPace_->setIconText(tr("Auto"));
    autoPace_->setCheckable(true);
    connect(autoPace_, &QAction::triggered, controller_, [this](bool on) {
        if (on)
            controller_->setAutomaticPace();
        else // fixed at the steps the automatic pace takes now
            controller_->setStepsPerFrame(controller_->stepsPerFrame());
    });
    bar->addAction(autoPace_);
    bar->addWidget(new QLabel(tr(" Steps per frame "), bar));
    speed_ = new QSpinBox(bar);
    speed_->setObjectName("stepsPerFrame");
    speed_->setRange(-SimulationController::kMaxStepsPerFrame, SimulationController::kMaxStepsPerFrame);
    speed_->setToolTip(tr("Signed steps per frame: negative values run time backwards, 0 stands still "
                          "([ slower, ] faster); a number typed here fixes the pace"));
    connect(speed_, &QSpinBox::valueChanged, controller_, &SimulationController::setStepsPerFrame);
    connect(controller_, &SimulationController::paceChanged, this, &MainWindow::showPace);
    connect(controller_, &SimulationController::frameAdvanced, this, [this] {
        if (controller_->automaticPace() && !speed_->hasFocus()) showPace();
    });
    bar->addWidget(speed_);
    QAction* slower = menuAction(sim, tr("Slower"), Qt::Key_BracketLeft, tr("One step per frame less"));
    connect(slower, &QAction::triggered, speed_, [this] { speed_->stepDown(); });
    QAction* faster = menuAction(sim, tr("Faster"), Qt::Key_BracketRight, tr("One step per frame more"));
    connect(faster, &QAction::triggered, speed_, [this] { speed_->stepUp(); });
    QAction* reverse = menuAction(sim, tr("Reverse time"), Qt::Key_Backspace, tr("Run time the other way"));
    connect(reverse, &QAction::triggered, controller_, &SimulationController::reverse);
    runActions_ << autoPace_ << slower << faster << reverse;
    showPace();

    // Where the models compute: the factory in gl/Backends.h decides what "auto" means here.
    QMenu* backendMenu = sim->addMenu(tr("Compute &backend"));
    auto* backends = new QActionGroup(this);
    const struct {
        gl::Backend backend;
        QString text, tip;
    } backendEntries[] = {
        {gl::Backend::Auto, tr("&Automatic"),
         tr("The GPU for scenes large enough to gain from it, else the CPU")},
        {gl::Backend::Cpu, tr("&CPU"), tr("The OpenMP reference models")},
        {gl::Backend::Gl, tr("&GPU (OpenGL compute)"),
         tr("OpenGL 4.3 compute shaders; the CPU where none exist")},
    };
    for (const auto& entry : backendEntries) {
        QAction* action = menuAction(backendMenu, entry.text, {}, entry.tip);
        action->setCheckable(true);
        action->setChecked(entry.backend == controller_->backend());
        action->setObjectName(
            QString("backend-%1").arg(QString::fromStdString(gl::backendName(entry.backend))));
        backends->addAction(action);
        connect(action, &QAction::triggered, this, [this, b = entry.backend] {
            controller_->setBackend(b);
            QSettings().setValue("simulation/backend", QString::fromStdString(gl::backendName(b)));
        });
    }
    connect(menuAction(sim, tr("Benchmark this &machine…"), {},
                       tr("Time the gas and the fluid at growing N on the CPU and the GPU")),
            &QAction::triggered, this, [this] {
                auto* dialog = new BenchmarkDialog(this);
                dialog->setAttribute(Qt::WA_DeleteOnClose);
                dialog->show();
            });
    createRunOnLammpsAction(sim);

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    connect(menuAction(viewMenu_, tr("Zoom to &fit"), QKeySequence(Qt::CTRL | Qt::Key_0),
                       tr("Show the whole scene (the wheel zooms, the middle button pans)")),
            &QAction::triggered, this, [this] { viewportCore_->zoomToFit(); });
    projectorAction_ =
        menuAction(viewMenu_, tr("&Projector mode"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P),
                   tr("Large fonts and thick lines for a classroom projector"));
    projectorAction_->setObjectName("projectorAction");
    projectorAction_->setCheckable(true);
    connect(projectorAction_, &QAction::toggled, this, &MainWindow::setProjectorMode);
    presentAction_ =
        menuAction(viewMenu_, tr("P&resent"), Qt::Key_F5,
                   tr("Full screen: the viewport, one plot, big readouts and a lesson's controls "
                      "(Escape leaves)"));
    presentAction_->setObjectName("presentAction");
    presentAction_->setCheckable(true);
    connect(presentAction_, &QAction::toggled, this, [this](bool on) { present_->setActive(on); });
    // The particles' colours: the scale follows the gas as it is heated, or stays the model's fixed one.
    QAction* colourScale = menuAction(viewMenu_, tr("&Automatic colour scale"), QKeySequence(),
                                      tr("The top of the colour scale follows the particles as they heat up; "
                                         "off: the scene's fixed scale, so heating shows as redder colours"));
    colourScale->setObjectName("automaticColourScaleAction");
    colourScale->setCheckable(true);
    colourScale->setChecked(QSettings().value("view/automaticColourScale", true).toBool());
    viewportCore_->colourScale().setAutomatic(colourScale->isChecked());
    connect(colourScale, &QAction::toggled, this, [this](bool on) {
        viewportCore_->colourScale().setAutomatic(on);
        QSettings().setValue("view/automaticColourScale", on);
        viewportCore_->requestFrame();
    });
    viewChooser_ = new ViewChooser(controller_, viewMenu_, this);
    connect(viewChooser_, &ViewChooser::problem, this,
            [this](const QString& problem) { statusBar()->showMessage(problem, 6000); });
    viewMenu_->addSeparator();
}

void MainWindow::createSceneBar() {
    QToolBar* bar = addToolBar(tr("Experiment"));
    bar->setObjectName("experimentToolBar");
    bar->addWidget(new QLabel(tr(" Scene "), bar));
    scenePicker_ = new QComboBox(bar);
    for (const ModelDescriptor& info : modelCatalog())
        scenePicker_->addItem(coreText(info.title), QString::fromStdString(info.kind));
    scenePicker_->setToolTip(tr("The kind of simulation: choosing one opens its first built-in experiment"));
    connect(scenePicker_, &QComboBox::activated, this, [this](int index) {
        const QString kind = scenePicker_->itemData(index).toString();
        if (controller_->model() && QString::fromStdString(controller_->model()->kind()) == kind) return;
        for (const BuiltinPreset* p : builtinPresetsOf(kind.toStdString()))
            if (document_->open(QString::fromStdString(p->name))) return;
        modelChanged(); // cancelled or failed: show the scene that still runs
    });
    bar->addWidget(scenePicker_);
    bar->addWidget(new QLabel(tr(" Preset "), bar));
    presetPicker_ = new QComboBox(bar);
    presetPicker_->setObjectName("presetPicker");
    presetPicker_->setMinimumContentsLength(18);
    // A list that drops down below the box and scrolls, not the style's list laid over it: that put the
    // current preset on the box and the ones before it above, past the top of a 700 px screen, with
    // nothing for the wheel to scroll.
    presetPicker_->setStyleSheet(QStringLiteral("QComboBox { combobox-popup: 0; }"));
    presetPicker_->setMaxVisibleItems(kPresetListRows);
    presetPicker_->setToolTip(tr("Built-in experiments and your saved presets"));
    connect(presetPicker_, &QComboBox::activated, this, [this](int index) {
        const QString target = presetPicker_->itemData(index).toString();
        if (!target.isEmpty()) document_->open(target);
        fillPresetPicker(); // shows the experiment that runs, also after a cancelled or failed load
    });
    bar->addWidget(presetPicker_);
    fillPresetPicker();
}

void MainWindow::createToolPalette() {
    addToolBarBreak();
    QToolBar* bar = addToolBar(tr("Tools"));
    bar->setObjectName("toolsToolBar");
    QMenu* menu = menuBar()->addMenu(tr("&Tools"));
    tools_ = new QActionGroup(this);
    const struct {
        ViewportTool tool;
        QString text, tip;
    } entries[] = {
        {ViewportTool::Drag, tr("Drag"),
         tr("Drag obstacles and the piston; drag empty space to pan (in the fluid: to pour; where fields "
            "are sampled: to read the local values)")},
        {ViewportTool::Spawn, tr("Spawn"),
         tr("Drag a rectangle to fill it with particles, or click for one")},
        {ViewportTool::AddDisc, tr("Add disc"), tr("Click to place a disc obstacle")},
        {ViewportTool::AddBox, tr("Add box"), tr("Drag a rectangle to place a box obstacle")},
        {ViewportTool::Remove, tr("Remove"), tr("Click an obstacle to remove it")},
        {ViewportTool::Piston, tr("Piston"), tr("Drag to move the piston (when enabled in Parameters)")},
        {ViewportTool::ProfileLine, tr("Profile line"),
         tr("Drag a line across the flow: the Profile dock plots a sampled field along it")},
    };
    int key = Qt::Key_1;
    for (const auto& entry : entries) {
        QAction* action = menuAction(menu, entry.text, QKeySequence(key++), entry.tip);
        action->setCheckable(true);
        action->setChecked(entry.tool == ViewportTool::Drag);
        tools_->addAction(action);
        bar->addAction(action);
        connect(action, &QAction::triggered, this,
                [this, tool = entry.tool] { viewportCore_->setTool(tool); });
    }
    // The gravity switch (the fluid write-up's toggle): every scene with gravity has it as "gravity_on".
    gravity_ = menuAction(menu, tr("Gravity"), Qt::Key_G, tr("Switch gravity on or off"));
    gravity_->setObjectName("gravityAction");
    gravity_->setCheckable(true);
    connect(gravity_, &QAction::triggered, this, [this](bool on) {
        const QString problem = controller_->setParameters({{"gravity_on", on}});
        if (!problem.isEmpty()) statusBar()->showMessage(problem, 6000);
    });
    connect(controller_, &SimulationController::parametersChanged, this, &MainWindow::syncGravity);
    connect(controller_, &SimulationController::modelReplaced, this, &MainWindow::syncGravity);
    // Gravity, Heat and Show have a bar of their own: on a narrow window it moves to the next row
    // (WindowFit.h) instead of hiding behind the tool bar's overflow button.
    bar = addToolBar(tr("Gravity, heat and view"));
    bar->setObjectName("heatViewToolBar");
    bar->addAction(gravity_);
    bar->addSeparator();
    bar->addWidget(new QLabel(tr(" Cool "), bar));
    heat_ = new SpringSlider(Qt::Horizontal, bar);
    heat_->setObjectName("heatSlider");
    heat_->setRange(-100, 100);
    heat_->setFixedWidth(140);
    heat_->setToolTip(tr("Hold to the right to heat, to the left to cool, the faster the further (at the "
                         "right end kT doubles in about 4 s of the scene's pace); it springs back when "
                         "released"));
    connect(heat_, &QSlider::valueChanged, controller_,
            [this](int v) { controller_->setHeatRate(v / 100.0); });
    connect(heat_, &QSlider::sliderReleased, heat_,
            [this] { heat_->setValue(0); }); // a drag ended in code too
    bar->addWidget(heat_);
    bar->addWidget(new QLabel(tr(" Heat "), bar));
    viewChooser_->addTo(bar);
    menu->addSeparator();
    const auto scaleEnergy = [this](double factor) {
        if (controller_->scaleKineticEnergy(factor)) viewport_->update();
    };
    connect(menuAction(menu, tr("Heat"), QKeySequence(Qt::CTRL | Qt::Key_Up),
                       tr("Raise the kinetic energy by 10 %")),
            &QAction::triggered, this, [scaleEnergy] { scaleEnergy(kHeatStep); });
    connect(menuAction(menu, tr("Cool"), QKeySequence(Qt::CTRL | Qt::Key_Down),
                       tr("Lower the kinetic energy by 10 %")),
            &QAction::triggered, this, [scaleEnergy] { scaleEnergy(1.0 / kHeatStep); });
    menu->addSeparator();
    // The piston at the scene's piston speed: pressing the same direction again holds it.
    const auto drivePiston = [this](int direction) {
        const SceneTools* tools = controller_->tools();
        if (!tools || !tools->hasPiston()) {
            statusBar()->showMessage(
                tr("This experiment has no piston: tick “Piston” in Parameters → Walls and fields."), 6000);
            return;
        }
        controller_->drivePiston(tools->pistonDirection() == direction ? 0 : direction);
        if (!controller_->isRunning() && tools->pistonDirection() != 0)
            statusBar()->showMessage(tr("The piston moves while time runs (Space)."), 6000);
    };
    connect(menuAction(menu, tr("Compress"), QKeySequence(Qt::CTRL | Qt::Key_Left),
                       tr("Move the piston left at the piston speed; again to hold it")),
            &QAction::triggered, this, [drivePiston] { drivePiston(-1); });
    connect(menuAction(menu, tr("Expand"), QKeySequence(Qt::CTRL | Qt::Key_Right),
                       tr("Move the piston right at the piston speed; again to hold it")),
            &QAction::triggered, this, [drivePiston] { drivePiston(+1); });
}

void MainWindow::showPace() {
    const QSignalBlocker block(speed_); // showing the pace is no choice of it
    const bool automatic = controller_->automaticPace();
    autoPace_->setChecked(automatic);
    speed_->setPrefix(automatic ? tr("auto ") : QString());
    // Before its first frame the automatic pace shows its direction.
    const int n = controller_->stepsPerFrame();
    speed_->setValue(automatic && n == 0 ? controller_->direction() : n);
}

void MainWindow::syncGravity() {
    const Model* model = controller_->model();
    const bool toggle = model && findSpec(model->paramSpecs(), "gravity_on");
    gravity_->setVisible(toggle);
    if (!toggle) return;
    // The switch shows the gravity the disks feel: g, and off where the scene has g = 0 (then it is set
    // in Parameters, and the switch waits for it).
    const ParamValues values = model->params();
    const auto strength = values.find("gravity");
    const double g = strength == values.end() ? 1.0 : std::get<double>(strength->second);
    const ParamSpec* spec = findSpec(model->paramSpecs(), "gravity");
    const QString unit = spec ? translatedUnit(*spec) : QString();
    const QSignalBlocker block(gravity_);
    gravity_->setChecked(g != 0 && std::get<bool>(values.at("gravity_on")));
    gravity_->setEnabled(g != 0 && !controller_->isReadOnly());
    gravity_->setIconText(g == 0 || strength == values.end()
                              ? tr("Gravity")
                              : tr("Gravity %1").arg(QLocale().toString(std::abs(g), 'g', 3)));
    gravity_->setText(g == 0 || strength == values.end()
                          ? tr("Gravity")
                          : tr("Gravity (g = %1 %2)").arg(QLocale().toString(std::abs(g), 'g', 3), unit));
    gravity_->setToolTip(g == 0 ? tr("This scene has no gravity (g = 0): set Gravity in Parameters")
                                : tr("Switch gravity on or off (%1)")
                                      .arg(gravity_->shortcut().toString(QKeySequence::NativeText)));
}

void MainWindow::fillPresetPicker() {
    const QSignalBlocker block(presetPicker_);
    presetPicker_->clear();
    for (const auto& p : builtinPresets())
        presetPicker_->addItem(QString::fromStdString(p.name), QString::fromStdString(p.name));
    const QStringList user = ExperimentDocument::userPresetFiles();
    if (!user.isEmpty()) presetPicker_->insertSeparator(presetPicker_->count());
    for (const QString& path : user)
        presetPicker_->addItem(tr("%1 (mine)").arg(QFileInfo(path).completeBaseName()), path);
    int current = presetPicker_->findData(document_->filePath());
    if (current < 0 || document_->filePath().isEmpty()) current = presetPicker_->findData(document_->title());
    if (current < 0) {
        presetPicker_->insertItem(0, document_->title(), QString());
        current = 0;
    }
    presetPicker_->setCurrentIndex(current);
}

void MainWindow::fillRecentMenu() {
    recentMenu_->clear();
    const QStringList files = document_->recentFiles();
    for (const QString& path : files)
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] { document_->open(path); })
            ->setToolTip(path);
    recentMenu_->setEnabled(!files.isEmpty());
}

} // namespace pl::ui
