// The window on the screen it has: the first window's size, a window kept inside the screen's available
// area, and the dock areas' plots turned into tabs when the window is too short to stack them at a
// readable height, and back to strips when it is tall enough again.
#pragma once

#include <QSize>
#include <Qt>

class QMainWindow;
class QWidget;

namespace pl::ui {

// The size of a first window (no saved geometry): preferred, or what the screen's available area leaves
// after the window manager's frame, whichever is smaller.
QSize firstWindowSize(const QWidget* window, QSize preferred);
// Shrinks and moves the window so that its frame lies inside its screen's available area.
void keepInsideScreen(QWidget* window);
// When the docks of area stand one above the other and one of their plots has less than panelHeight
// pixels per panel, gathers them into one group of tabs, so each plot has the area's whole height.
// Returns whether it did.
bool tabifyWhenShort(QMainWindow* window, Qt::DockWidgetArea area, int panelHeight);

// Undoes tabifyWhenShort once the window is tall enough for the docks it gathered to stand one above the
// other again at panelHeight per panel (and the same docks are shown): the layout from before comes back.
// Returns whether it did.
bool stackWhenTall(QMainWindow* window, Qt::DockWidgetArea area);

// Lays the top tool bars out in rows that fit the window's width: a bar that would pass the right edge
// starts a new row (and rows it started join again when there is room), so no item falls into a bar's
// overflow menu.
void wrapToolBars(QMainWindow* window);

} // namespace pl::ui
