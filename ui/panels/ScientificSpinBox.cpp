// ScientificSpinBox: decimals are set to the maximum so QDoubleSpinBox never rounds a small value to 0.
#include "ScientificSpinBox.h"

#include <QLocale>
#include <cmath>

namespace pl::ui {

ScientificSpinBox::ScientificSpinBox(QWidget* parent) : QDoubleSpinBox(parent) {
    setDecimals(300);
    setKeyboardTracking(false);
    setAccelerated(true);
}

QString ScientificSpinBox::textFromValue(double value) const {
    return QLocale().toString(value, 'g', 6);
}

double ScientificSpinBox::valueFromText(const QString& text) const {
    QString body = text;
    if (!suffix().isEmpty() && body.endsWith(suffix())) body.chop(suffix().size());
    return QLocale().toDouble(body.trimmed());
}

QValidator::State ScientificSpinBox::validate(QString& text, int&) const {
    QString body = text;
    if (!suffix().isEmpty() && body.endsWith(suffix())) body.chop(suffix().size());
    body = body.trimmed();
    if (body.isEmpty() || body == "-" || body == "+" || body.endsWith('e') || body.endsWith('E') ||
        body.endsWith("e-") || body.endsWith("E-"))
        return QValidator::Intermediate;
    bool ok = false;
    const double value = QLocale().toDouble(body, &ok);
    if (!ok) return QValidator::Invalid;
    return value >= minimum() && value <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
}

void ScientificSpinBox::stepBy(int steps) {
    const double v = value();
    if (increment_ > 0)
        setValue(v + steps * increment_);
    else
        setValue(v == 0.0 ? steps * 1e-3 : v * std::pow(1.1, steps));
    emit editingFinished();
}

} // namespace pl::ui
