// ParameterPanel: editors made from ParamSpec kinds — Real and Integer: ScientificSpinBox, Boolean:
// QCheckBox, Choice: QComboBox, Color: a swatch button with QColorDialog. The number editors accept any
// number: the model's validation, not a spin box's range, decides, so its answer can be shown.
#include "ParameterPanel.h"

#include "ScientificSpinBox.h"
#include "ShortcutGuard.h"
#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "i18n/Translations.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace pl::ui {

namespace {

QString tooltipFor(const ParamSpec& spec) {
    QString text = translatedTooltip(spec);
    text += QObject::tr("\nAllowed: %1").arg(translatedAllowed(spec));
    text +=
        spec.appliesLive ? QObject::tr("\nTakes effect at once.") : QObject::tr("\nTakes effect on Reset.");
    return text;
}

QString labelFor(const ParamSpec& spec) {
    QString text = translatedLabel(spec);
    if (!spec.unit.empty()) text += QStringLiteral(" [%1]").arg(translatedUnit(spec));
    if (!spec.appliesLive) text += QStringLiteral(" ⟲");
    return text;
}

// Beyond any parameter's range, so that every typed number reaches the model's validation.
constexpr double kAnyNumber = 1e300;
const QColor kProblemText("#b00000");
const QColor kProblemField("#ffd9d9");

void paintSwatch(QPushButton* button, const QString& colour) {
    button->setText(colour);
    button->setStyleSheet(QStringLiteral("background-color: %1;").arg(colour));
}

} // namespace

ParameterPanel::ParameterPanel(SimulationController* controller, QWidget* parent)
    : QWidget(parent), controller_(controller) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    units_ = new QLabel(this);
    units_->setObjectName("unitsLine");
    units_->setWordWrap(true);
    layout->addWidget(units_);
    bannerRow_ = new QBoxLayout(QBoxLayout::LeftToRight);
    banner_ = new QStackedWidget(this);
    idleLine_ = new QLabel(tr("Parameters marked ⟲ take effect on Reset; the others act at once."), banner_);
    idleLine_->setObjectName("idleLine");
    idleLine_->setWordWrap(true);
    pending_ = new QLabel(banner_);
    pending_->setObjectName("pendingLine");
    pending_->setWordWrap(true);
    pending_->setStyleSheet(QStringLiteral("font-weight: bold; color: #a05000;"));
    banner_->addWidget(idleLine_);
    banner_->addWidget(pending_);
    resetButton_ = new QPushButton(tr("Reset now"), this);
    resetButton_->setObjectName("resetNow");
    resetButton_->setToolTip(tr("Restart the experiment so the parameters marked ⟲ take effect (Ctrl+R)"));
    connect(resetButton_, &QPushButton::clicked, controller_, &SimulationController::reset);
    bannerRow_->addWidget(banner_, 1);
    bannerRow_->addWidget(resetButton_, 0, Qt::AlignRight);
    layout->addLayout(bannerRow_);
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
    problems_.clear();
    showUnits();
    const Model* model = controller_->model();
    if (!model) return;
    std::map<std::string, QFormLayout*> forms;
    for (const ParamSpec& spec : model->paramSpecs()) {
        QFormLayout*& form = forms[spec.group];
        if (!form) {
            auto* box = new QGroupBox(translatedGroup(spec), content_);
            form = new QFormLayout(box);
            form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
            // Long labels (German ones) wrap, and a field that still does not fit goes below its label:
            // never a field cut off at the panel's edge.
            form->setRowWrapPolicy(QFormLayout::WrapLongRows);
            groups_->addWidget(box);
        }
        QWidget* editor = createEditor(spec);
        editor->setToolTip(tooltipFor(spec));
        auto* label = new QLabel(labelFor(spec), editor->parentWidget());
        label->setWordWrap(true);
        label->setToolTip(editor->toolTip());
        label->setBuddy(editor);
        form->addRow(label, editor);
        editors_[spec.key] = editor;
        auto* problem = new QLabel(editor->parentWidget());
        problem->setObjectName(QString::fromStdString("problem-" + spec.key));
        problem->setWordWrap(true);
        QPalette red = problem->palette();
        red.setColor(QPalette::WindowText, kProblemText);
        problem->setPalette(red);
        form->addRow(problem);
        form->setRowVisible(problem, false);
        problems_[spec.key] = {form, problem};
    }
    groups_->addStretch(1);
    showValues();
    updatePendingBanner();
}

// The units come from the kind's registration, as the CLI's help and the docs print them.
void ParameterPanel::showUnits() {
    const Model* model = controller_->model();
    const ModelDescriptor* kind = model ? findModel(model->kind()) : nullptr;
    units_->setVisible(kind != nullptr);
    if (!kind) return;
    units_->setText(tr("Units: %1").arg(coreText(kind->units.name)));
    units_->setToolTip(coreText(kind->units.summary));
}

QWidget* ParameterPanel::createEditor(const ParamSpec& spec) {
    const std::string key = spec.key;
    switch (spec.kind) {
    case ParamKind::Real:
    case ParamKind::Integer: {
        auto* box = new ScientificSpinBox(content_);
        box->setRange(-kAnyNumber, kAnyNumber);
        box->setStepLimits(spec.min, spec.max);
        box->setIntegerMode(spec.kind == ParamKind::Integer);
        box->setIncrement(spec.kind == ParamKind::Integer ? std::max(spec.step, 1.0) : spec.step);
        box->setReportsUnreadableText(true);
        connect(box, &QDoubleSpinBox::editingFinished, this, [this, key, box] {
            if (box->value() == std::get<double>(controller_->parameterValues().at(key)))
                clearProblem(key); // typed back the value in use
            else
                apply(key, box->value());
        });
        connect(box, &ScientificSpinBox::unreadableText, this, [this, spec](const QString& text) {
            // A decimal mark of the other language is named: in English 2,5 is no number (never 25).
            const QString point = ScientificSpinBox::numberLocale().decimalPoint();
            const QString other = point == QStringLiteral(".") ? QStringLiteral(",") : QStringLiteral(".");
            const QString allowed = translatedAllowed(spec);
            showProblem(
                spec.key,
                text.contains(other)
                    ? tr("%1: “%2” is not a number: decimals are written with “%3” (allowed: %4)")
                          .arg(translatedLabel(spec), text, point, allowed)
                    : tr("%1: “%2” is not a number (allowed: %3)").arg(translatedLabel(spec), text, allowed));
        });
        connect(box, &ScientificSpinBox::editCancelled, this, [this, key] {
            clearProblem(key);
            showValue(key);
        });
        setters_[key] = [box](const ParamValue& v) { box->setValue(std::get<double>(v)); };
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
        box->setFocusPolicy(Qt::StrongFocus);
        box->installEventFilter(this);
        // The choice in the UI's language; the key (presets, --set) as the item's data.
        for (const auto& choice : spec.choices)
            box->addItem(coreText(choice), QString::fromStdString(choice));
        connect(box, &QComboBox::activated, this,
                [this, key, box](int) { apply(key, box->currentData().toString().toStdString()); });
        setters_[key] = [box](const ParamValue& v) {
            box->setCurrentIndex(box->findData(QString::fromStdString(std::get<std::string>(v))));
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
    if (error.isEmpty()) {
        clearProblem(key);
        showValue(key);
        return error;
    }
    if (const auto setter = setters_.find(key); setter != setters_.end()) { // the field shows what was tried
        const QSignalBlocker block(editors_.at(key));
        setter->second(value);
    }
    showProblem(key, error);
    return error;
}

QString ParameterPanel::problem(const std::string& key) const {
    const auto it = problems_.find(key);
    return it == problems_.end() || !it->second.form->isRowVisible(it->second.label)
               ? QString()
               : it->second.label->text();
}

void ParameterPanel::showProblem(const std::string& key, const QString& text) {
    const auto it = problems_.find(key);
    if (it == problems_.end()) return;
    it->second.label->setText(text);
    it->second.form->setRowVisible(it->second.label, true);
    QWidget* field = editors_.at(key);
    QPalette red = field->palette();
    red.setColor(QPalette::Base, kProblemField);
    red.setColor(QPalette::Button, kProblemField);
    red.setColor(QPalette::Text, kProblemText);
    field->setPalette(red);
    field->setToolTip(text);
    field->setProperty(kRefusedFieldProperty, true);
}

void ParameterPanel::clearProblem(const std::string& key) {
    const auto it = problems_.find(key);
    if (it == problems_.end() || !it->second.form->isRowVisible(it->second.label)) return;
    it->second.form->setRowVisible(it->second.label, false);
    it->second.label->clear();
    QWidget* field = editors_.at(key);
    field->setPalette(QPalette()); // inherits the panel's again
    field->setProperty(kRefusedFieldProperty, false);
    if (const ParamSpec* spec = findSpec(controller_->model()->paramSpecs(), key))
        field->setToolTip(tooltipFor(*spec));
}

void ParameterPanel::showValue(const std::string& key) {
    const auto setter = setters_.find(key);
    if (setter == setters_.end()) return;
    const QSignalBlocker block(editors_.at(key));
    setter->second(controller_->parameterValues().at(key));
}

QWidget* ParameterPanel::editor(const std::string& key) const {
    const auto it = editors_.find(key);
    return it == editors_.end() ? nullptr : it->second;
}

void ParameterPanel::showValues() {
    const Model* model = controller_->model();
    if (!model) return;
    for (const auto& [key, value] : controller_->parameterValues()) {
        const auto it = setters_.find(key);
        if (it == setters_.end() || !problem(key).isEmpty()) continue; // a rejected field keeps its text
        const QSignalBlocker block(editors_.at(key));
        it->second(value);
    }
}

void ParameterPanel::updatePendingBanner() {
    const auto waiting = controller_->pendingUntilReset().size();
    // The waiting line's longest form is set while it is hidden too, so the banner keeps its height.
    pending_->setText(
        tr("%n change(s) wait for Reset.", nullptr, static_cast<int>(std::max<std::size_t>(waiting, 2))));
    if (waiting > 0)
        pending_->setText(tr("%n change(s) wait for Reset.", nullptr, static_cast<int>(waiting)));
    banner_->setCurrentWidget(waiting == 0 ? idleLine_ : pending_);
    resetButton_->setEnabled(waiting > 0);
    fitBanner();
}

void ParameterPanel::fitBanner() {
    // Beside the button the line would get less room than the button itself (German, projector mode):
    // it goes above it and takes the whole width.
    const int width =
        contentsRect().width() - layout()->contentsMargins().left() - layout()->contentsMargins().right();
    const int button = resetButton_->sizeHint().width();
    const bool above = 2 * button > width;
    bannerRow_->setDirection(above ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight);
    const int lineWidth = std::max(1, above ? width : width - button - bannerRow_->spacing());
    // A stacked widget takes its pages' one-line height: the wrapped lines ask for theirs.
    banner_->setMinimumHeight(
        std::max(idleLine_->heightForWidth(lineWidth), pending_->heightForWidth(lineWidth)));
}

void ParameterPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    fitBanner();
}

void ParameterPanel::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) fitBanner();
}

bool ParameterPanel::eventFilter(QObject* watched, QEvent* event) {
    // A choice turns under the wheel only once clicked into; otherwise the wheel scrolls the panel.
    if (event->type() == QEvent::Wheel) {
        auto* widget = qobject_cast<QWidget*>(watched);
        if (widget && !widget->hasFocus()) {
            event->ignore(); // on to the scroll area
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace pl::ui
