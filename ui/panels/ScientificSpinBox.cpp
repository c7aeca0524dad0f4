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
    QLocale().toDouble(body(lineEdit()->text()), &ok);
    return ok;
}

QString ScientificSpinBox::textFromValue(double value) const {
    if (integer_ && value == std::floor(value) && std::abs(value) < 1e15)
        return QLocale().toString(value, 'f', 0);
    return QLocale().toString(value, 'g', 6);
}

double ScientificSpinBox::valueFromText(const QString& text) const {
    return QLocale().toDouble(body(text));
}

QValidator::State ScientificSpinBox::validate(QString& text, int&) const {
    const QString b = body(text);
    if (b.isEmpty() || b == "-" || b == "+" || b.endsWith('e') || b.endsWith('E') || b.endsWith("e-") ||
        b.endsWith("E-") || b.endsWith("e+") || b.endsWith("E+"))
        return QValidator::Intermediate;
    bool ok = false;
    const double value = QLocale().toDouble(b, &ok);
    if (!ok) return QValidator::Invalid;
    return value >= minimum() && value <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
}

void ScientificSpinBox::stepBy(int steps) {
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
    if (event->key() == Qt::Key_Escape) {
        setValue(value()); // the text shows the value again
        emit editCancelled();
    }
    QDoubleSpinBox::keyPressEvent(event);
}

void ScientificSpinBox::focusOutEvent(QFocusEvent* event) {
    const QString typed = lineEdit()->text();
    const bool unreadable = reportsUnreadable_ && !textIsNumber();
    QDoubleSpinBox::focusOutEvent(event);
    if (!unreadable) return;
    lineEdit()->setText(typed); // the base class showed the previous value again
    emit unreadableText(typed);
}

} // namespace pl::ui
