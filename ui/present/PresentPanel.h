// The side panel of present mode: Record and Leave on top, big readouts, one large plot of the teacher's
// choice among the scene's plots, and the lesson's controls, all in a font larger than the rest of the
// window.
#pragma once

#include "viewport/ViewportCore.h"

#include <QWidget>

class QAction;
class QComboBox;
class QPushButton;
class QVBoxLayout;

namespace pl::ui {

class LessonControls;
class PresentReadouts;
class SimulationController;

class PresentPanel : public QWidget {
    Q_OBJECT
public:
    // The panel's text against the window's usual text (projector mode's larger text is not enlarged again).
    static constexpr double kFontScale = 1.35;
    // record: the window's Record clip action (checked while recording), shown as a button; may be null.
    // font: the panel's text, set before its children exist (styled widgets keep the font they are made
    // with).
    PresentPanel(SimulationController* controller, QAction* record, const QFont& font,
                 QWidget* parent = nullptr);

    QComboBox* plotChooser() const { return chooser_; }
    QWidget* currentPlot() const { return plot_; }
    PresentReadouts* readouts() const { return readouts_; }
    LessonControls* controls() const { return controls_; }

signals:
    void leaveRequested();
    void toolRequested(ViewportTool tool);

private:
    void fillChooser();      // the scene's plots; the last choice for this scene is kept (QSettings)
    void showPlot(int item); // replaces the plot widget by the chosen one

    SimulationController* controller_;
    QVBoxLayout* plotBox_;
    PresentReadouts* readouts_ = nullptr;
    QComboBox* chooser_ = nullptr;
    QWidget* plot_ = nullptr;
    LessonControls* controls_ = nullptr;
};

} // namespace pl::ui
