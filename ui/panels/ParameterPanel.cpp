// ParameterPanel: editors made from ParamSpec kinds — Real: ScientificSpinBox, Integer: QSpinBox,
// Boolean: QCheckBox, Choice: QComboBox, Color: a swatch button with QColorDialog.
#include "ParameterPanel.h"

#include "ScientificSpinBox.h"
#include "SimulationController.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>
#include <climits>

namespace pl::ui {

namespace {

QString tooltipFor(const ParamSpec& spec) {
    QString text = QString::fromStdString(spec.tooltip);
    text += QObject::tr("\nAllowed: %1").arg(QString::fromStdString(describeAllowed(spec)));
    text +=
        spec.appliesLive ? QObject::tr("\nTakes effect at once.") : QObject::tr("\nTakes effect on Reset.");
    return text;
}

QString labelFor(const ParamSpec& spec) {
    QString text = QString::fromStdString(spec.label);
    if (!spec.unit.empty()) text += QStringLiteral(" [%1]").arg(QString::fromStdString(spec.unit));
    if (!spec.appliesLive) text += QStringLiteral(" ⟲");
    return text;
}

void paintSwatch(QPushButton* button, const QString& colour) {
    button->setText(colour);
    button->setStyleSheet(QStringLiteral("background-color: %1;").arg(colour));
}

} // namespace

ParameterPanel::ParameterPanel(SimulationController* controller, QWidget* parent)
    : QWidget(parent), controller_(controller) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* banner = new QHBoxLayout;
    pending_ = new QLabel(this);
    pending_->setWordWrap(true);
    resetButton_ = new QPushButton(tr("Reset now"), this);
    resetButton_->setToolTip(tr("Restart the experiment so the parameters marked ⟲ take effect (Ctrl+R)"));
    connect(resetButton_, &QPushButton::clicked, controller_, &SimulationController::reset);
    banner->addWidget(pending_, 1);
    banner->addWidget(resetButton_);
    layout->addLayout(banner);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    content_ = new QWidget(scroll);
    groups_ = new QVBoxLayout(content_);
    groups_->setContentsMargins(0, 0, 0, 0);
    scroll->setWidget(content_);
    layout->addWidget(scroll, 1);
    connect(controller_, &SimulationController::modelReplaced, this, &ParameterPanel::rebuild);
    connect(controller_, &SimulationController::parametersChanged, this, [this] {
        showValues();
        updatePendingBanner();
    });
    rebuild();
}

void ParameterPanel::rebuild() {
    while (QLayoutItem* item = groups_->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    editors_.clear();
    setters_.clear();
    const Model* model = controller_->model();
    if (!model) return;
    std::map<std::string, QFormLayout*> forms;
    for (const ParamSpec& spec : model->paramSpecs()) {
        QFormLayout*& form = forms[spec.group];
        if (!form) {
            auto* box = new QGroupBox(QString::fromStdString(spec.group), content_);
            form = new QFormLayout(box);
            form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
            groups_->addWidget(box);
        }
        QWidget* editor = createEditor(spec);
        editor->setToolTip(tooltipFor(spec));
        auto* label = new QLabel(labelFor(spec), editor->parentWidget());
        label->setToolTip(editor->toolTip());
        label->setBuddy(editor);
        form->addRow(label, editor);
        editors_[spec.key] = editor;
    }
    groups_->addStretch(1);
    showValues();
    updatePendingBanner();
}

QWidget* ParameterPanel::createEditor(const ParamSpec& spec) {
    const std::string key = spec.key;
    switch (spec.kind) {
    case ParamKind::Real: {
        auto* box = new ScientificSpinBox(content_);
        box->setRange(spec.min, spec.max);
        box->setIncrement(spec.step);
        connect(box, &QDoubleSpinBox::editingFinished, this, [this, key, box] {
            if (box->value() != std::get<double>(controller_->model()->params().at(key)))
                apply(key, box->value());
        });
        setters_[key] = [box](const ParamValue& v) { box->setValue(std::get<double>(v)); };
        return box;
    }
    case ParamKind::Integer: {
        auto* box = new QSpinBox(content_);
        box->setRange(static_cast<int>(std::max<double>(spec.min, INT_MIN)),
                      static_cast<int>(std::min<double>(spec.max, INT_MAX)));
        box->setSingleStep(spec.step >= 1 ? static_cast<int>(spec.step) : 1);
        box->setKeyboardTracking(false);
        box->setGroupSeparatorShown(true);
        connect(box, &QSpinBox::valueChanged, this, [this, key](int value) { apply(key, double(value)); });
        setters_[key] = [box](const ParamValue& v) { box->setValue(static_cast<int>(std::get<double>(v))); };
        return box;
    }
    case ParamKind::Boolean: {
        auto* box = new QCheckBox(content_);
        connect(box, &QCheckBox::toggled, this, [this, key](bool on) { apply(key, on); });
        setters_[key] = [box](const ParamValue& v) { box->setChecked(std::get<bool>(v)); };
        return box;
    }
    case ParamKind::Choice: {
        auto* box = new QComboBox(content_);
        for (const auto& choice : spec.choices) box->addItem(QString::fromStdString(choice));
        connect(box, &QComboBox::activated, this,
                [this, key, box](int) { apply(key, box->currentText().toStdString()); });
        setters_[key] = [box](const ParamValue& v) {
            box->setCurrentText(QString::fromStdString(std::get<std::string>(v)));
        };
        return box;
    }
    case ParamKind::Color: {
        auto* button = new QPushButton(content_);
        connect(button, &QPushButton::clicked, this, [this, key, button] {
            const QColor chosen = QColorDialog::getColor(QColor(button->text()), this);
            if (chosen.isValid()) apply(key, chosen.name().toStdString());
        });
        setters_[key] = [button](const ParamValue& v) {
            paintSwatch(button, QString::fromStdString(std::get<std::string>(v)));
        };
        return button;
    }
    }
    return new QLabel(content_);
}

QString ParameterPanel::apply(const std::string& key, const ParamValue& value) {
    const QString error = controller_->setParameters({{key, value}});
    if (!error.isEmpty()) {
        showValues(); // the editor goes back to the value the model kept
        QMessageBox::warning(this, tr("Invalid parameter value"), error);
    }
    return error;
}

QWidget* ParameterPanel::editor(const std::string& key) const {
    const auto it = editors_.find(key);
    return it == editors_.end() ? nullptr : it->second;
}

void ParameterPanel::showValues() {
    const Model* model = controller_->model();
    if (!model) return;
    for (const auto& [key, value] : model->params()) {
        const auto it = setters_.find(key);
        if (it == setters_.end()) continue;
        const QSignalBlocker block(editors_.at(key));
        it->second(value);
    }
}

void ParameterPanel::updatePendingBanner() {
    const auto waiting = controller_->pendingUntilReset().size();
    if (waiting == 0) {
        pending_->setText(tr("Parameters marked ⟲ take effect on Reset; the others act at once."));
        pending_->setStyleSheet({});
        resetButton_->setEnabled(false);
    } else {
        pending_->setText(tr("%n change(s) wait for Reset.", nullptr, static_cast<int>(waiting)));
        pending_->setStyleSheet(QStringLiteral("font-weight: bold; color: #a05000;"));
        resetButton_->setEnabled(true);
    }
}

} // namespace pl::ui
