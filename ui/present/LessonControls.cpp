// LessonControls: built anew for each scene from the list its kind's registration gives (or, where it
// gives none, from what the model offers: PresentBoard.h). The controls fill a two-column grid, the wide
// ones a whole row, so the board keeps the panel's width. Sizes come from a style sheet: large handles
// for a projector.
#include "LessonControls.h"

#include "PresentBoard.h"
#include "SimulationController.h"
#include "ViewChooser.h"
#include "common/SceneTools.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace pl::ui {

namespace {
constexpr int kSliderSteps = 100;
constexpr int kPourIntervalMs = 150;   // one small block of fluid per interval while Pour is held
constexpr double kPourFraction = 0.04; // side of the poured block, as a fraction of the tank width
constexpr int kViewColumns = 2;        // the field buttons wrap after this many
constexpr int kColumnGap = 10;         // px between the two columns: German buttons fill 45 % of 1024 px

// Large enough to hit on a projector's touch screen, small enough that a 700 px high board holds a
// readable plot beside four rows of controls.
const char* kStyle = "QPushButton { padding: 5px 8px; }"
                     "QPushButton:checked { background: #2a5aaa; color: white; }"
                     "QSlider { min-height: 36px; }"
                     "QSlider::groove:horizontal { height: 10px; background: #c8c8c8; border-radius: 5px; }"
                     "QSlider::handle:horizontal { width: 34px; margin: -12px 0; border-radius: 17px;"
                     " background: #2a5aaa; }";

double number(const ParamValues& values, const std::string& key, double fallback) {
    const auto it = values.find(key);
    if (it == values.end()) return fallback;
    if (const auto* d = std::get_if<double>(&it->second)) return *d;
    return fallback;
}

// The latest finite value of a series column, or fallback.
double latest(SimulationController* controller, const QString& column, double fallback) {
    const SeriesStore* store = controller->series();
    const int c = store->column(column);
    if (c < 0 || store->rows() == 0) return fallback;
    const double v = store->table().row(store->rows() - 1)[static_cast<std::size_t>(c)];
    return std::isfinite(v) ? v : fallback;
}
} // namespace

LessonControls::LessonControls(SimulationController* controller, QWidget* parent)
    : QWidget(parent), controller_(controller), layout_(new QVBoxLayout(this)), pour_(new QTimer(this)) {
    setObjectName("lessonControls");
    setStyleSheet(kStyle);
    layout_->setContentsMargins(0, 0, 0, 0);
    pour_->setInterval(kPourIntervalMs);
    connect(pour_, &QTimer::timeout, this, &LessonControls::pourOnce);
    connect(controller, &SimulationController::modelReplaced, this, &LessonControls::rebuild);
    connect(controller, &SimulationController::parametersChanged, this, &LessonControls::syncState);
    connect(controller, &SimulationController::frameAdvanced, this, &LessonControls::syncState);
    connect(controller, &SimulationController::runningChanged, this, &LessonControls::syncState);
    rebuild();
}

void LessonControls::rebuild() {
    pour_->stop();
    delete body_;
    body_ = new QWidget(this);
    grid_ = new QGridLayout(body_);
    grid_->setContentsMargins(0, 0, 0, 0);
    grid_->setHorizontalSpacing(kColumnGap);
    grid_->setColumnStretch(0, 1);
    grid_->setColumnStretch(1, 1);
    layout_->addWidget(body_);
    run_ = nullptr;
    count_ = nullptr;
    pistonSwitch_ = nullptr;
    std::fill(std::begin(pistonButtons_), std::end(pistonButtons_), nullptr);
    viewButtons_.clear();
    row_ = 0;
    column_ = 0;
    addRunRow();
    if (Model* model = controller_->model())
        for (LessonControl control : lessonControls(*model)) addControl(control);
    message_ = new QLabel(body_);
    message_->setWordWrap(true);
    message_->hide();
    grid_->addWidget(message_, grid_->rowCount(), 0, 1, 2);
    syncState();
}

QPushButton* LessonControls::addButton(QLayout* row, const QString& text, const QString& objectName) {
    auto* button = new QPushButton(text, body_);
    button->setObjectName(objectName);
    button->setFocusPolicy(Qt::NoFocus); // the keys stay with the viewport
    row->addWidget(button);
    return button;
}

QVBoxLayout* LessonControls::addCell() {
    auto* group = new QVBoxLayout;
    group->setSpacing(2);
    grid_->addLayout(group, row_, column_);
    if (++column_ == 2) {
        column_ = 0;
        ++row_;
    }
    return group;
}

QVBoxLayout* LessonControls::addRow() {
    if (column_ != 0) { // the half row left open stays empty
        column_ = 0;
        ++row_;
    }
    auto* group = new QVBoxLayout;
    group->setSpacing(2);
    grid_->addLayout(group, row_++, 0, 1, 2);
    return group;
}

void LessonControls::addControl(LessonControl control) {
    switch (control) {
    case LessonControl::Heat:
        if (controller_->tools()) addHeatSlider(addCell());
        return;
    case LessonControl::ParticleCount:
        addParticleCount(addCell());
        return;
    case LessonControl::Piston:
        if (controller_->tools()) {
            QVBoxLayout* drive = addRow(); // the three buttons take a row; the switch a cell below
            addPistonGroup(drive, addCell());
        }
        return;
    case LessonControl::Gravity:
        addGravitySlider(addCell(), gravityMaximum(*controller_->model()));
        return;
    case LessonControl::GravitySwitch:
        addGravitySwitch(addCell());
        return;
    case LessonControl::Pour:
        if (controller_->tools()) addPourButton(addCell());
        return;
    case LessonControl::SpawnTool:
        if (controller_->tools()) addSpawnToolButton(addCell());
        return;
    case LessonControl::Pace:
        addPaceSlider(addCell());
        return;
    case LessonControl::FieldView:
        addFieldButtons();
        return;
    }
}

QSlider* LessonControls::addSlider(QVBoxLayout* group, const QString& title, QLabel** valueLabel) {
    auto* header = new QHBoxLayout;
    auto* name = new QLabel(title, body_);
    name->setWordWrap(true); // a narrow panel wraps the title instead of widening itself
    header->addWidget(name, 1);
    auto* value = new QLabel(body_);
    header->addWidget(value);
    if (valueLabel) *valueLabel = value;
    auto* slider = new QSlider(Qt::Horizontal, body_);
    slider->setFocusPolicy(Qt::NoFocus);
    group->addLayout(header);
    group->addWidget(slider);
    return slider;
}

void LessonControls::addRunRow() {
    // Half a row: the first control of the scene takes the other half.
    QVBoxLayout* group = addCell();
    group->addStretch(1);
    auto* row = new QHBoxLayout;
    group->addLayout(row);
    run_ = addButton(row, tr("Run"), "lessonRun");
    connect(run_, &QPushButton::clicked, controller_, &SimulationController::togglePlay);
    connect(addButton(row, tr("Reset"), "lessonReset"), &QPushButton::clicked, controller_,
            &SimulationController::reset);
}

void LessonControls::addHeatSlider(QVBoxLayout* group) {
    // Temperature: held to a side it heats or cools at a rate per simulated time proportional to the
    // slider, and springs back, as the tool bar's Heat slider; the readout shows where kT has got to.
    QSlider* heat = addSlider(group, tr("◀ Cool   Heat ▶"), nullptr);
    heat->setObjectName("lessonHeat");
    heat->setRange(-kSliderSteps, kSliderSteps);
    connect(heat, &QSlider::valueChanged, controller_,
            [this](int v) { controller_->setHeatRate(static_cast<double>(v) / kSliderSteps); });
    connect(heat, &QSlider::sliderReleased, heat, [heat] { heat->setValue(0); });
}

void LessonControls::addParticleCount(QVBoxLayout* group) {
    // Particle number: the experiment restarts with N particles at the temperature it has now, so the
    // class compares pressures at equal temperature. Spawning could only add particles, and is refused
    // where they overlap. What N and the temperature are is the kind's (PresentSpec::particleCount).
    const ParticleCountControl* control = particleCountControl(*controller_->model());
    if (!control) return;
    const ParamValues values = controller_->parameterValues();
    const double total = std::max(1.0, control->count(values));
    const int top = static_cast<int>(std::max(total, control->largest(values)));
    count_ = addSlider(
        group, tr("Particles (restart at this %1)").arg(QString::fromStdString(control->temperatureColumn)),
        &countLabel_);
    count_->setObjectName("lessonCount");
    count_->setRange(std::max(1, top / 50), top);
    count_->setValue(static_cast<int>(total));
    countLabel_->setText(QString::number(static_cast<int>(total)));
    connect(count_, &QSlider::valueChanged, countLabel_,
            [this](int n) { countLabel_->setText(QString::number(n)); });
    connect(count_, &QSlider::sliderReleased, this, [this] { applyParticleCount(count_->value()); });
    connect(count_, &QSlider::actionTriggered, this, [this](int action) {
        if (action != QAbstractSlider::SliderMove) // a click on the groove: applies at once
            QTimer::singleShot(0, this, [this] { applyParticleCount(count_->value()); });
    });
}

void LessonControls::addPistonGroup(QVBoxLayout* drive, QVBoxLayout* toggle) {
    toggle->addStretch(1);
    auto* toggleRow = new QHBoxLayout;
    toggle->addLayout(toggleRow);
    pistonSwitch_ = addButton(toggleRow, tr("Piston"), "lessonPistonSwitch");
    pistonSwitch_->setCheckable(true);
    pistonSwitch_->setToolTip(tr("Replace the right wall by a piston"));
    connect(pistonSwitch_, &QPushButton::toggled, this, [this](bool on) {
        const QString problem = controller_->setParameters({{"piston_enabled", on}});
        if (!problem.isEmpty()) say(problem);
    });
    auto* row = new QHBoxLayout;
    drive->addLayout(row);
    const QString texts[] = {tr("◀ Compress"), tr("Stop"), tr("Expand ▶")};
    const char* names[] = {"lessonCompress", "lessonStop", "lessonExpand"};
    for (int i = 0; i < 3; ++i) {
        pistonButtons_[i] = addButton(row, texts[i], names[i]);
        pistonButtons_[i]->setCheckable(true);
        connect(pistonButtons_[i], &QPushButton::clicked, this, [this, direction = i - 1] {
            if (!controller_->drivePiston(direction)) return;
            syncState();
        });
    }
}

void LessonControls::addGravitySlider(QVBoxLayout* group, double maximum) {
    QLabel* value = nullptr;
    QSlider* slider = addSlider(group, tr("Gravity"), &value);
    slider->setObjectName("lessonGravity");
    slider->setRange(0, kSliderSteps);
    const double now = std::abs(number(controller_->parameterValues(), "gravity", 0));
    slider->setValue(static_cast<int>(std::lround(kSliderSteps * std::min(1.0, now / maximum))));
    value->setText(QLocale().toString(now, 'g', 3));
    connect(slider, &QSlider::valueChanged, this, [this, maximum, value](int v) {
        const double g = maximum * v / kSliderSteps;
        value->setText(QLocale().toString(g, 'g', 3));
        const QString problem = controller_->setParameters({{"gravity", g}});
        if (!problem.isEmpty()) say(problem);
    });
}

void LessonControls::addGravitySwitch(QVBoxLayout* group) {
    auto* switches = new QHBoxLayout;
    group->addStretch(1);
    group->addLayout(switches);
    QPushButton* gravity = addButton(switches, tr("Gravity on"), "lessonGravitySwitch");
    gravity->setCheckable(true);
    const ParamValues values = controller_->parameterValues();
    const auto on = values.find("gravity_on");
    gravity->setChecked(on != values.end() && std::holds_alternative<bool>(on->second) &&
                        std::get<bool>(on->second));
    connect(gravity, &QPushButton::toggled, this, [this](bool on) {
        const QString problem = controller_->setParameters({{"gravity_on", on}});
        if (!problem.isEmpty()) say(problem);
    });
}

void LessonControls::addPourButton(QVBoxLayout* group) {
    // Pour: held, it drops small blocks of particles into the middle of the scene's top, as a tap would.
    auto* pouring = new QHBoxLayout;
    group->addStretch(1);
    group->addLayout(pouring);
    QPushButton* pour = addButton(pouring, tr("Pour (hold)"), "lessonPour");
    connect(pour, &QPushButton::pressed, this, [this] {
        pourOnce();
        pour_->start();
    });
    connect(pour, &QPushButton::released, pour_, &QTimer::stop);
}

void LessonControls::addSpawnToolButton(QVBoxLayout* group) {
    auto* mouseRow = new QHBoxLayout;
    group->addStretch(1);
    group->addLayout(mouseRow);
    QPushButton* mouse = addButton(mouseRow, tr("Spawn tool"), "lessonSpawnTool");
    mouse->setToolTip(tr("Add particles where you like: drag a rectangle in the scene to fill it"));
    connect(mouse, &QPushButton::clicked, this, [this] {
        emit toolRequested(ViewportTool::Spawn);
        say(tr("Drag a rectangle in the scene to fill it with particles; a click adds one."));
    });
}

void LessonControls::addPaceSlider(QVBoxLayout* group) {
    QLabel* value = nullptr;
    // 1 … 10 steps per frame, and at the right end the automatic pace (the scene's default).
    constexpr int kFixedSteps = 10, kAutomatic = kFixedSteps + 1;
    QSlider* speed = addSlider(group, tr("Steps per frame"), &value);
    speed->setObjectName("lessonSpeed");
    speed->setRange(1, kAutomatic);
    const auto show = [value](int n) { value->setText(n == kAutomatic ? tr("auto") : QString::number(n)); };
    speed->setValue(controller_->automaticPace()
                        ? kAutomatic
                        : std::clamp(std::abs(controller_->stepsPerFrame()), 1, kFixedSteps));
    show(speed->value());
    connect(speed, &QSlider::valueChanged, this, [this, show](int n) {
        show(n);
        if (n == kAutomatic)
            controller_->setAutomaticPace();
        else
            controller_->setStepsPerFrame(n);
    });
}

void LessonControls::addFieldButtons() {
    const ParamSpec* view = findSpec(controller_->model()->paramSpecs(), ViewChooser::kKey);
    if (!view || view->kind != ParamKind::Choice || !controller_->model()->sampledFields()) return;
    QVBoxLayout* group = addRow();
    group->addWidget(new QLabel(tr("Show"), body_));
    auto* buttons = new QGridLayout; // rows of a few buttons: the panel keeps its width
    buttons->setSpacing(4);
    group->addLayout(buttons);
    for (const std::string& choice : view->choices) {
        const QString key = QString::fromStdString(choice);
        auto* row = new QHBoxLayout;
        const int index = static_cast<int>(viewButtons_.size());
        buttons->addLayout(row, index / kViewColumns, index % kViewColumns);
        QPushButton* button = addButton(row, viewChoiceText(key), "lessonView-" + key);
        button->setCheckable(true);
        viewButtons_.push_back(button);
        connect(button, &QPushButton::clicked, this, [this, key] {
            const QString problem = controller_->setParameters({{ViewChooser::kKey, key.toStdString()}});
            if (!problem.isEmpty()) say(problem);
            syncState(); // the buttons show what the model kept
        });
    }
}

void LessonControls::applyParticleCount(int total) {
    Model* model = controller_->model();
    if (!model) return;
    const ParticleCountControl* control = particleCountControl(*model);
    if (!control) return;
    const ParamValues values = controller_->parameterValues(); // with a count that waits for Reset
    if (static_cast<int>(control->count(values)) == total) return;
    const double temperature = latest(controller_, QString::fromStdString(control->temperatureColumn),
                                      number(values, control->temperatureParameter, 0.0));
    const QString problem = controller_->setParameters(control->restartWith(values, total, temperature));
    if (!problem.isEmpty()) {
        say(problem);
        return;
    }
    const bool wasRunning = controller_->isRunning();
    controller_->reset();
    if (wasRunning) controller_->play();
    say(tr("Restarted with %1 particles at %2 = %3.")
            .arg(total)
            .arg(QString::fromStdString(control->temperatureColumn))
            .arg(temperature, 0, 'g', 3));
}

void LessonControls::pourOnce() {
    Model* model = controller_->model();
    if (!model || !controller_->tools()) return;
    const SceneView view = model->sceneView();
    const double side = kPourFraction * (view.right - view.left);
    const double x = 0.5 * (view.left + view.right), y = view.top - side;
    say(controller_->spawnInRectangle(x - 0.5 * side, y - side, x + 0.5 * side, y));
}

void LessonControls::syncState() {
    Model* model = controller_->model();
    if (run_) run_->setText(controller_->isRunning() ? tr("Pause") : tr("Run"));
    SceneTools* tools = model ? model->tools() : nullptr;
    const bool piston = tools && tools->hasPiston();
    if (pistonSwitch_) {
        const QSignalBlocker block(pistonSwitch_);
        pistonSwitch_->setChecked(piston);
    }
    for (int i = 0; i < 3; ++i)
        if (pistonButtons_[i]) {
            pistonButtons_[i]->setEnabled(piston);
            pistonButtons_[i]->setChecked(piston && tools->pistonDirection() == i - 1);
        }
    if (!viewButtons_.empty()) {
        const ParamValues values = model->params();
        const auto shown = values.find(ViewChooser::kKey);
        for (QPushButton* button : viewButtons_)
            button->setChecked(shown != values.end() &&
                               button->objectName() ==
                                   "lessonView-" +
                                       QString::fromStdString(std::get<std::string>(shown->second)));
    }
}

void LessonControls::say(const QString& sentence) {
    if (!message_) return;
    message_->setText(sentence);
    message_->setVisible(!sentence.isEmpty()); // an empty line would take a row from a short board
}

} // namespace pl::ui
