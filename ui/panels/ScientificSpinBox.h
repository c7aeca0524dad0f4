// A double spin box that shows and accepts values in %g form (1e-05, 100000), so a time step and a
// stiffness are both readable; the arrows step by a fixed increment or by ten per cent.
#pragma once

#include <QDoubleSpinBox>

namespace pl::ui {

class ScientificSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    explicit ScientificSpinBox(QWidget* parent = nullptr);
    // 0: relative steps of 10 %; otherwise a fixed increment.
    void setIncrement(double increment) { increment_ = increment; }

    QString textFromValue(double value) const override;
    double valueFromText(const QString& text) const override;
    QValidator::State validate(QString& text, int& pos) const override;
    void stepBy(int steps) override;

private:
    double increment_ = 0.0;
};

} // namespace pl::ui
