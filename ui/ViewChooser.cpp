// ViewChooser: both controls only ask the controller to set the parameter, and both follow the model
// (parametersChanged, modelReplaced), so they agree with the parameter panel whichever was used.
#include "ViewChooser.h"

#include "SimulationController.h"

#include <QActionGroup>
#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QToolBar>

namespace pl::ui {

namespace {
const ParamSpec* viewSpec(const Model* model) {
    if (!model || !model->sampledFields()) return nullptr;
    const ParamSpec* spec = findSpec(model->paramSpecs(), ViewChooser::kKey);
    return spec && spec->kind == ParamKind::Choice ? spec : nullptr;
}
} // namespace

QString viewChoiceText(const QString& choice) {
    if (choice == QLatin1String("particles")) return ViewChooser::tr("Particles");
    if (choice == QLatin1String("density")) return ViewChooser::tr("Number density");
    if (choice == QLatin1String("speed")) return ViewChooser::tr("Flow speed");
    if (choice == QLatin1String("temperature")) return ViewChooser::tr("Temperature");
    if (choice == QLatin1String("mach")) return ViewChooser::tr("Mach number");
    return choice.isEmpty() ? choice : choice.front().toUpper() + choice.mid(1);
}

ViewChooser::ViewChooser(SimulationController* controller, QMenu* viewMenu, QObject* parent)
    : QObject(parent), controller_(controller), menu_(viewMenu->addMenu(tr("Colour &map"))),
      group_(new QActionGroup(this)), combo_(new QComboBox) {
    menu_->setToolTip(tr("Show the particles or a sampled field as a colour map"));
    combo_->setObjectName("viewChooser");
    combo_->setToolTip(tr("Show the particles or a sampled field as a colour map (click the flow to read "
                          "the local values)"));
    connect(combo_, &QComboBox::activated, this,
            [this](int index) { choose(combo_->itemData(index).toString()); });
    connect(controller_, &SimulationController::modelReplaced, this, &ViewChooser::rebuild);
    connect(controller_, &SimulationController::parametersChanged, this, &ViewChooser::sync);
    rebuild();
}

void ViewChooser::addTo(QToolBar* bar) {
    labelAction_ = bar->addWidget(new QLabel(tr(" Show "), bar));
    comboAction_ = bar->addWidget(combo_);
    rebuild();
}

void ViewChooser::rebuild() {
    const ParamSpec* spec = viewSpec(controller_->model());
    {
        const QSignalBlocker block(combo_);
        combo_->clear();
        for (QAction* action : group_->actions()) delete action;
        if (spec)
            for (const std::string& choice : spec->choices) {
                const QString key = QString::fromStdString(choice);
                combo_->addItem(viewChoiceText(key), key);
                QAction* action = menu_->addAction(viewChoiceText(key));
                action->setCheckable(true);
                action->setData(key);
                group_->addAction(action);
                connect(action, &QAction::triggered, this, [this, key] { choose(key); });
            }
    }
    const bool shown = spec != nullptr;
    const bool editable = shown && !controller_->isReadOnly();
    menu_->menuAction()->setVisible(shown);
    menu_->setEnabled(editable);
    combo_->setEnabled(editable);
    if (labelAction_) labelAction_->setVisible(shown);
    if (comboAction_) comboAction_->setVisible(shown);
    sync();
}

void ViewChooser::sync() {
    const Model* model = controller_->model();
    if (!viewSpec(model)) return;
    const auto& params = model->params();
    const auto value = params.find(kKey);
    if (value == params.end()) return;
    const QString current = QString::fromStdString(std::get<std::string>(value->second));
    const QSignalBlocker block(combo_);
    combo_->setCurrentIndex(combo_->findData(current));
    for (QAction* action : group_->actions()) action->setChecked(action->data().toString() == current);
}

void ViewChooser::choose(const QString& choice) {
    const QString error = controller_->setParameters({{kKey, choice.toStdString()}});
    if (!error.isEmpty()) {
        emit problem(error);
        sync(); // the controls show what the model kept
    }
}

} // namespace pl::ui
