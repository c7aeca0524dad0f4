// Large readouts for present mode: the few numbers a lesson is about, as the scene's kind lists them in
// its registration (PresentBoard.h), read from the controller's series store after every sample.
#pragma once

#include <QString>
#include <QStringList>
#include <QWidget>
#include <vector>

class QGridLayout;
class QLabel;

namespace pl {
class Model;
}

namespace pl::ui {

class SimulationController;

// One number on the board: a series column, how it is named and printed.
struct ReadoutSpec {
    QString column; // the model's series column
    QString name;   // what the class reads, e.g. "kT"
    QString unit;   // after the number; empty for model units
    double scale = 1.0;
    char format = 'g';
    int precision = 3;
    bool needsBodies = false; // left out while the scene has no body
};

// The readouts of the model's kind, in the UI's language.
std::vector<ReadoutSpec> readoutSpecsFor(const Model& model);

class PresentReadouts : public QWidget {
    Q_OBJECT
public:
    explicit PresentReadouts(SimulationController* controller, QWidget* parent = nullptr);
    // "name = value unit" per readout, as shown (for tests and the accessible description).
    QStringList texts() const;

protected:
    void changeEvent(QEvent* event) override; // the numbers scale with the panel's font

private:
    void rebuild(); // a new table: the scene (and so the readouts) may have changed
    void refresh(); // a new row
    QString valueText(const ReadoutSpec& spec, int column) const;

    SimulationController* controller_;
    QGridLayout* grid_;
    struct Shown {
        ReadoutSpec spec;
        int column;
        QLabel* name;
        QLabel* value;
    };
    std::vector<Shown> shown_;
};

} // namespace pl::ui
