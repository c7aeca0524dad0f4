// The quick choice of what the viewport shows in a scene with sampled fields: the particles or one field
// as a colour map (the model's `view` parameter, which the parameter panel offers too), as a combo box
// in the Tools bar and as View → Colour map. Hidden for scenes without sampled fields.
#pragma once

#include <QObject>
#include <QString>

class QAction;
class QActionGroup;
class QComboBox;
class QMenu;
class QToolBar;

namespace pl::ui {

class SimulationController;

class ViewChooser : public QObject {
    Q_OBJECT
public:
    // The submenu goes into viewMenu at once; the combo box into a tool bar with addTo().
    ViewChooser(SimulationController* controller, QMenu* viewMenu, QObject* parent);
    void addTo(QToolBar* bar);
    QComboBox* combo() const { return combo_; }
    QMenu* menu() const { return menu_; }
    // The parameter this chooses.
    static constexpr const char* kKey = "view";

signals:
    void problem(const QString& message); // the model refused the choice

private:
    void rebuild(); // a new model: its choices, or nothing
    void sync();    // the model's current choice
    void choose(const QString& choice);

    SimulationController* controller_;
    QMenu* menu_;
    QActionGroup* group_;
    QComboBox* combo_ = nullptr;
    QAction* labelAction_ = nullptr;
    QAction* comboAction_ = nullptr;
};

// How a choice of the `view` parameter reads: "mach" → "Mach number" (translated); unknown ones as they
// are, capitalised.
QString viewChoiceText(const QString& choice);

} // namespace pl::ui
