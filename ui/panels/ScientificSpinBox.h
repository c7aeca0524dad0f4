// A double spin box that shows and accepts values in %g form (1e-05, 100000), so a time step and a
// stiffness are both readable; the arrows step by a fixed increment or by ten per cent. Numbers are read
// in the UI's language and nothing else (German 2,5 is 2.5; in English 2,5 is no number, never 25: no
// group separators, read or written); a typed number stays as it was typed (1e7 stays 1e7); the wheel
// turns it only while it has the keyboard focus, so a wheel over a panel of fields scrolls the panel.
#pragma once

#include <QDoubleSpinBox>
#include <QLocale>
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
    // The locale numbers are read and written in: the default (the UI's language), without group
    // separators.
    static QLocale numberLocale();
    // A number in that locale; false in *ok for anything else, a group separator included (Qt reads
    // English "2,5" as 25 even where group separators are refused).
    static double readNumber(const QString& text, bool* ok);

    QString textFromValue(double value) const override;
    double valueFromText(const QString& text) const override;
    QValidator::State validate(QString& text, int& pos) const override;
    // Nothing: QDoubleSpinBox's fixup drops group separators, which turned English "2,5" into 25.
    void fixup(QString& text) const override;
    void stepBy(int steps) override;

signals:
    void unreadableText(const QString& text);
    void editCancelled(); // Escape: the typed text is dropped

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    QString body(const QString& text) const; // text without suffix and spaces
    void rememberTyped();                    // the text as typed, shown while the value is the one it says

    double increment_ = 0.0;
    double stepMin_ = -std::numeric_limits<double>::max();
    double stepMax_ = std::numeric_limits<double>::max();
    bool integer_ = false;
    bool reportsUnreadable_ = false;
    QString typed_;           // the last number as the user typed it
    double typedValue_ = 0.0; // and its value
};

} // namespace pl::ui
