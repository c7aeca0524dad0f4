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
class TimeSeries;
} // namespace pl

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
// A readout's value in the latest row of table, as the board writes it (the language's digits, plain up to
// a million, the unit after it); a dash for no row or a value that is not finite.
QString readoutValueText(const ReadoutSpec& spec, const TimeSeries& table, int column);

class PresentReadouts : public QWidget {
    Q_OBJECT
public:
    explicit PresentReadouts(SimulationController* controller, QWidget* parent = nullptr);
    // "name = value unit" per readout, as shown (for tests and the accessible description).
    QStringList texts() const;

    // As narrow as the readouts stacked (each name above its number) can be: a wider board puts each name
    // beside its number, a line less per row.
    QSize minimumSizeHint() const override;

protected:
    void changeEvent(QEvent* event) override;       // the numbers scale with the panel's font
    void resizeEvent(QResizeEvent* event) override; // beside or above, as the width allows

private:
    void rebuild();          // a new table: the scene (and so the readouts) may have changed
    void refresh();          // a new row
    int besideWidth() const; // the width that the names beside their numbers need
    void place(bool beside); // puts the labels into the grid, names beside or above their numbers

    SimulationController* controller_;
    QGridLayout* grid_;
    struct Shown {
        ReadoutSpec spec;
        int column;
        QLabel* name;
        QLabel* value;
    };
    std::vector<Shown> shown_;
    bool beside_ = false;
};

} // namespace pl::ui
