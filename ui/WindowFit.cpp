// WindowFit: sizes are measured against QScreen::availableGeometry (the screen less panels and docks of
// the desktop) and the frame the window manager adds, as far as it is known before the window is shown.
#include "WindowFit.h"

#include <QDockWidget>
#include <QLayout>
#include <QMainWindow>
#include <QScreen>
#include <QToolBar>
#include <QWidget>
#include <algorithm>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
// A frame's title bar and borders before the window manager has told their size.
constexpr QSize kAssumedFrame(12, 40);

QRect availableArea(const QWidget* window) {
    const QScreen* screen = window->screen();
    return screen ? screen->availableGeometry() : QRect();
}

// The window manager's frame around the client area, as far as it is known: none before the window is
// shown (a restored geometry already is the size the window had inside its frame).
QSize frameOf(const QWidget* window) {
    if (!window->isVisible()) return {0, 0};
    return window->frameGeometry().size() - window->size();
}

// The window properties under which tabifyWhenShort keeps what stackWhenTall needs, per area.
QByteArray stackKey(Qt::DockWidgetArea area) {
    return "pl_stackedDocks" + QByteArray::number(int(area));
}

// The docks the window shows (in tabs or not), which decide whether a saved layout still applies.
QStringList shownDockNames(const QMainWindow* window) {
    QStringList names;
    for (const QDockWidget* dock : window->findChildren<QDockWidget*>())
        if (!dock->isHidden()) names << dock->objectName();
    names.sort();
    return names;
}

} // namespace

QSize firstWindowSize(const QWidget* window, QSize preferred) {
    const QRect area = availableArea(window);
    if (area.isEmpty()) return preferred;
    return preferred.boundedTo(area.size() - kAssumedFrame);
}

void keepInsideScreen(QWidget* window) {
    const QRect area = availableArea(window);
    if (area.isEmpty()) return;
    const QSize frame = frameOf(window);
    const QSize size = window->size().boundedTo(area.size() - frame);
    if (size != window->size()) window->resize(size);
    QRect outer(window->frameGeometry().topLeft(), size + frame);
    if (area.contains(outer)) return;
    outer.moveRight(std::min(outer.right(), area.right()));
    outer.moveBottom(std::min(outer.bottom(), area.bottom()));
    outer.moveLeft(std::max(outer.left(), area.left()));
    outer.moveTop(std::max(outer.top(), area.top()));
    window->move(outer.topLeft());
}

bool tabifyWhenShort(QMainWindow* window, Qt::DockWidgetArea area, int panelHeight) {
    // The area's docks, and those of them shown one above the other (one per group of tabs).
    QList<QDockWidget*> docks, shown;
    bool squeezed = false;
    for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
        if (dock->isFloating() || window->dockWidgetArea(dock) != area) continue;
        docks << dock;
        if (!dock->isVisible() || dock->visibleRegion().isEmpty()) continue;
        shown << dock;
        for (const QCustomPlot* canvas : dock->findChildren<QCustomPlot*>())
            squeezed |=
                canvas->isVisible() && canvas->height() < panelHeight * std::max(1, canvas->axisRectCount());
    }
    const QByteArray key = stackKey(area);
    if (shown.size() >= 2 && !squeezed) { // the layout to come back to, and the height it needs
        window->setProperty(key + "Fits", window->height());
        window->setProperty(key + "FitState", window->saveState());
    }
    if (shown.size() < 2 || !squeezed) return false;
    // The layout before, and the height at which each of its plots has panelHeight again, for
    // stackWhenTall: without them the docks stayed tabs after the window was enlarged.
    int missing = 0;
    for (const QDockWidget* dock : std::as_const(shown)) {
        int own = 0;
        for (const QCustomPlot* canvas : dock->findChildren<QCustomPlot*>())
            if (canvas->isVisible())
                own = std::max(own, panelHeight * std::max(1, canvas->axisRectCount()) - canvas->height());
        missing += own;
    }
    // The height at which they last stood apart whole, where known, else an estimate from what each lacks.
    const int fits = window->property(key + "Fits").toInt();
    const int needed = window->height() + missing;
    const QByteArray fitState = window->property(key + "FitState").toByteArray();
    window->setProperty(key + "State", fits > window->height() ? fitState : window->saveState());
    window->setProperty(key + "Height", fits > window->height() ? std::min(fits, needed) : needed);
    window->setProperty(key + "Docks", shownDockNames(window));
    for (QDockWidget* dock : std::as_const(docks))
        if (dock != shown.front()) window->tabifyDockWidget(shown.front(), dock);
    shown.front()->raise(); // the plot on top stays in front
    return true;
}

bool stackWhenTall(QMainWindow* window, Qt::DockWidgetArea area) {
    const QByteArray key = stackKey(area);
    const QByteArray state = window->property(key + "State").toByteArray();
    if (state.isEmpty()) return false;
    if (window->property(key + "Docks").toStringList() != shownDockNames(window)) {
        window->setProperty(key + "State", QVariant()); // another scene's docks: that layout is gone
        return false;
    }
    if (window->height() < window->property(key + "Height").toInt()) return false;
    window->setProperty(key + "State", QVariant());
    window->restoreState(state);
    return true;
}

void wrapToolBars(QMainWindow* window) {
    constexpr const char* kOwnBreak = "rowStartedToFit"; // breaks this function made, not the window's own
    int row = 0;
    for (QToolBar* bar : window->findChildren<QToolBar*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (bar->isHidden() || bar->isFloating() || window->toolBarArea(bar) != Qt::TopToolBarArea) continue;
        const int width = bar->sizeHint().width();
        const bool ownBreak = bar->property(kOwnBreak).toBool();
        const bool fixedBreak = window->toolBarBreak(bar) && !ownBreak;
        if (fixedBreak || row == 0) {
            row = width;
        } else if (row + width > window->width()) {
            if (!ownBreak) {
                window->insertToolBarBreak(bar);
                bar->setProperty(kOwnBreak, true);
            }
            row = width;
        } else {
            if (ownBreak) {
                window->removeToolBarBreak(bar);
                bar->setProperty(kOwnBreak, false);
            }
            row += width;
        }
    }
}

} // namespace pl::ui
