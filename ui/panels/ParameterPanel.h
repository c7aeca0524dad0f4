// The Parameters dock: one editor per ParamSpec of the loaded model, grouped as the specs say, with units
// and tooltips. Live parameters act at once; the others are marked and wait for Reset, and the panel
// says how many are waiting. A rejected value shows a dialog naming the problem and reverts the editor.
#pragma once

#include "common/ParamSpec.h"

#include <QWidget>
#include <functional>
#include <map>

class QLabel;
class QPushButton;
class QVBoxLayout;

namespace pl::ui {

class SimulationController;

class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParameterPanel(SimulationController* controller, QWidget* parent = nullptr);

    // Applies one value as if typed by the user; returns the error shown, or empty.
    QString apply(const std::string& key, const ParamValue& value);
    // The editor widget of a key (for tests and focus), nullptr when absent.
    QWidget* editor(const std::string& key) const;

private:
    void rebuild();
    void showValues();
    void updatePendingBanner();
    QWidget* createEditor(const ParamSpec& spec);

    SimulationController* controller_;
    QVBoxLayout* groups_ = nullptr;
    QWidget* content_ = nullptr;
    QLabel* pending_ = nullptr;
    QPushButton* resetButton_ = nullptr;
    std::map<std::string, QWidget*> editors_;
    std::map<std::string, std::function<void(const ParamValue&)>> setters_; // show a value, no signals
};

} // namespace pl::ui
