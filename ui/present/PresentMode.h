// Present mode (View → Present, F5, --present): the window goes full screen with only the viewport and
// one side panel (readouts, a plot, the lesson's controls); Escape or F5 brings back exactly the layout
// it replaced: docks, tool bars, menu and status bar, window state and geometry.
#pragma once

#include "viewport/ViewportCore.h"

#include <QByteArray>
#include <QFont>
#include <QList>
#include <QObject>

class QAction;
class QDockWidget;
class QMainWindow;
class QScrollArea;
class QShortcut;

namespace pl::ui {

class PresentPanel;
class SimulationController;

class PresentMode : public QObject {
    Q_OBJECT
public:
    // viewport: the window's central widget, which takes the keyboard focus while presenting; baseFont:
    // the window's text before projector mode enlarges it (the panel's own enlargement starts from it).
    PresentMode(QMainWindow* window, SimulationController* controller, QWidget* viewport,
                const QFont& baseFont);

    bool isActive() const { return dock_ != nullptr; }
    void setActive(bool on);
    PresentPanel* panel() const { return panel_; }
    // The panel's share of the window's width, up to kPanelMaxWidth px; the viewport keeps the rest
    // (two thirds of the window or more, so well over half its area).
    static constexpr double kPanelShare = 0.34;
    static constexpr int kPanelMaxWidth = 560;
    static constexpr double kPanelMostShare = 0.45; // a board that needs more scrolls instead
    static constexpr int kPanelSlack = 4;           // the dock's and the scroll area's edges

signals:
    void activeChanged(bool on);
    void toolRequested(ViewportTool tool); // a lesson control asks for a viewport tool

protected:
    // Keeps the panel's share on resizes; a new application font (projector mode) builds the panel anew.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void enter();
    void leave();
    void makePanel(); // in the scroll area, in the font the window's text has now
    void fitPanel();
    void hideEverythingElse(); // also after a scene change, which may bring docks back

    QMainWindow* window_;
    SimulationController* controller_;
    QWidget* viewport_;
    QFont baseFont_;
    QShortcut* escape_;
    QDockWidget* dock_ = nullptr;
    QScrollArea* scroll_ = nullptr;
    PresentPanel* panel_ = nullptr;
    bool widened_ = false; // the board needed the widest share at this window size
    struct Saved {
        QByteArray state, geometry;
        Qt::WindowStates windowState;
        bool menuBar = true, statusBar = true;
    } saved_;
    QList<QAction*> borrowed_; // menu actions added to the window so their keys work without the menu bar
};

} // namespace pl::ui
