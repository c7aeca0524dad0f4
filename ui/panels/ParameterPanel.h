// The Parameters dock: the kind's unit system on its first line, then one editor per ParamSpec of the loaded
// model, grouped as the specs say, with units and tooltips. Live parameters act at once; the others are
// marked and wait for Reset, and the panel says how many are waiting. A rejected value stays in its field as
// typed; the field turns red and a line under it says what is wrong, in the labels' words, until a valid
// value is applied or Escape drops it.
#pragma once

#include "common/ParamSpec.h"

#include <QWidget>
#include <functional>
#include <map>

class QBoxLayout;
class QFormLayout;
class QLabel;
class QPushButton;
class QStackedWidget;
class QVBoxLayout;

namespace pl::ui {

class SimulationController;

class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParameterPanel(SimulationController* controller, QWidget* parent = nullptr);

    // Applies one value as if typed by the user; returns the error shown under its field, or empty.
    QString apply(const std::string& key, const ParamValue& value);
    // The editor widget of a key (for tests and focus), nullptr when absent.
    QWidget* editor(const std::string& key) const;
    // What is wrong with the value in a key's field, empty when it was accepted.
    QString problem(const std::string& key) const;

private:
    void rebuild();
    void showUnits();
    void showValues();
    void updatePendingBanner();
    void fitBanner(); // the line beside Reset now, or above it where the panel is too narrow
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;
    QWidget* createEditor(const ParamSpec& spec);
    bool eventFilter(QObject* watched, QEvent* event) override; // the wheel over an unfocused choice
    void showValue(const std::string& key);                     // the model's value, without signals
    void showProblem(const std::string& key, const QString& text);
    void clearProblem(const std::string& key);

    SimulationController* controller_;
    QVBoxLayout* groups_ = nullptr;
    QWidget* content_ = nullptr;
    QLabel* units_ = nullptr; // "Units: reduced (L, T, M)"; the tooltip says each quantity's unit
    // The banner's two lines, stacked: its height is the taller one's, so the fields below never move
    // when changes start or stop waiting for Reset.
    QBoxLayout* bannerRow_ = nullptr;
    QStackedWidget* banner_ = nullptr;
    QLabel* idleLine_ = nullptr;
    QLabel* pending_ = nullptr;
    QPushButton* resetButton_ = nullptr;
    std::map<std::string, QWidget*> editors_;
    struct ProblemLine {
        QFormLayout* form;
        QLabel* label; // red, under the field; its row is hidden while the value is accepted
    };
    std::map<std::string, ProblemLine> problems_;
    std::map<std::string, std::function<void(const ParamValue&)>> setters_; // show a value, no signals
};

} // namespace pl::ui
