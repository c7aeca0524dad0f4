// A double spin box that shows and accepts values in %g form (1e-05, 100000), so a time step and a
// stiffness are both readable; the arrows step by a fixed increment or by ten per cent.
#pragma once

#include <QDoubleSpinBox>
#include <limits>

namespace pl::ui {

class ScientificSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    explicit ScientificSpinBox(QWidget* parent = nullptr);
    // 0: relative steps of 10 %; otherwise a fixed increment.
    void setIncrement(double increment) { increment_ = increment; }
    // Whole numbers written without exponent (2500, 1000000); a fraction typed in one still shows.
    void setIntegerMode(bool on) { integer_ = on; }
    // The arrows stay inside [min, max] even where the box accepts any typed value (see ParameterPanel).
    void setStepLimits(double min, double max);
    // On: text that is no number ("", "-", "1e") stays as typed and unreadableText() says so, instead of
    // the box silently showing its previous value again.
    void setReportsUnreadableText(bool on) { reportsUnreadable_ = on; }
    bool textIsNumber() const;

    QString textFromValue(double value) const override;
    double valueFromText(const QString& text) const override;
    QValidator::State validate(QString& text, int& pos) const override;
    void stepBy(int steps) override;

signals:
    void unreadableText(const QString& text);
    void editCancelled(); // Escape: the typed text is dropped

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    QString body(const QString& text) const; // text without suffix and spaces

    double increment_ = 0.0;
    double stepMin_ = -std::numeric_limits<double>::max();
    double stepMax_ = std::numeric_limits<double>::max();
    bool integer_ = false;
    bool reportsUnreadable_ = false;
};

} // namespace pl::ui
