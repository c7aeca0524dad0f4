// ScientificSpinBox: decimals are set to the maximum so QDoubleSpinBox never rounds a small value to 0.
#include "ScientificSpinBox.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QLocale>
#include <algorithm>
#include <cmath>

namespace pl::ui {

ScientificSpinBox::ScientificSpinBox(QWidget* parent) : QDoubleSpinBox(parent) {
    setDecimals(300);
    setKeyboardTracking(false);
    setAccelerated(true);
    setFocusPolicy(Qt::StrongFocus); // the wheel does not take the focus (nor the value) on its way past
}

double ScientificSpinBox::readNumber(const QString& text, bool* ok) {
    const QLocale locale = numberLocale();
    if (text.contains(locale.groupSeparator())) {
        *ok = false;
        return 0.0;
    }
    return locale.toDouble(text, ok);
}

QLocale ScientificSpinBox::numberLocale() {
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);
    return locale;
}

void ScientificSpinBox::setStepLimits(double min, double max) {
    stepMin_ = min;
    stepMax_ = max;
}

QString ScientificSpinBox::body(const QString& text) const {
    QString b = text;
    if (!suffix().isEmpty() && b.endsWith(suffix())) b.chop(suffix().size());
    return b.trimmed();
}

bool ScientificSpinBox::textIsNumber() const {
    bool ok = false;
    readNumber(body(lineEdit()->text()), &ok);
    return ok;
}

QString ScientificSpinBox::textFromValue(double value) const {
    if (!typed_.isEmpty() && value == typedValue_) return typed_;
    if (integer_ && value == std::floor(value) && std::abs(value) < 1e15)
        return numberLocale().toString(value, 'f', 0);
    return numberLocale().toString(value, 'g', 6);
}

double ScientificSpinBox::valueFromText(const QString& text) const {
    bool ok = false;
    return readNumber(body(text), &ok);
}

// Whatever is typed stays in the field (letters, a comma where the language writes a point): what is no
// number is reported on Enter or when the field is left, never swallowed while typing.
QValidator::State ScientificSpinBox::validate(QString& text, int&) const {
    bool ok = false;
    const double value = readNumber(body(text), &ok);
    return ok && value >= minimum() && value <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
}

void ScientificSpinBox::fixup(QString&) const {}

void ScientificSpinBox::rememberTyped() {
    bool ok = false;
    const QString typed = body(lineEdit()->text());
    const double value = readNumber(typed, &ok);
    if (!ok) return;
    typed_ = typed;
    typedValue_ = value;
}

void ScientificSpinBox::stepBy(int steps) {
    typed_.clear(); // the arrows' value is shown in the box's own form
    const double v = value();
    double next = v == 0.0 ? steps * 1e-3 : v * std::pow(1.1, steps);
    if (increment_ > 0) next = v + steps * increment_;
    if (integer_) next = std::round(next) == v ? v + steps : std::round(next);
    setValue(std::clamp(next, std::max(stepMin_, minimum()), std::min(stepMax_, maximum())));
    emit editingFinished();
}

void ScientificSpinBox::keyPressEvent(QKeyEvent* event) {
    const bool enter = event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter;
    if (enter && reportsUnreadable_ && !textIsNumber()) {
        emit unreadableText(lineEdit()->text()); // not interpreted: the spin box would put back its value
        return;
    }
    if (enter) rememberTyped();
    if (event->key() == Qt::Key_Escape) {
        setValue(value()); // the text shows the value again
        emit editCancelled();
    }
    QDoubleSpinBox::keyPressEvent(event);
}

void ScientificSpinBox::focusOutEvent(QFocusEvent* event) {
    const QString typed = lineEdit()->text();
    const bool unreadable = reportsUnreadable_ && !textIsNumber();
    if (!unreadable) rememberTyped();
    QDoubleSpinBox::focusOutEvent(event);
    if (!unreadable) return;
    lineEdit()->setText(typed); // the base class showed the previous value again
    emit unreadableText(typed);
}

void ScientificSpinBox::wheelEvent(QWheelEvent* event) {
    if (!hasFocus()) {
        event->ignore(); // on to the scroll area around the field
        return;
    }
    typed_.clear();
    QDoubleSpinBox::wheelEvent(event);
}

} // namespace pl::ui
