// ViewportRoom: the left and the right dock areas are each one column of docks (stacked or tabbed), so
// an area narrows as a whole, and the room the central widget lacks is taken from the areas in
// proportion to how far each is above its minimum width.
#include "ViewportRoom.h"

#include "WindowFit.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QEvent>
#include <QLayout>
#include <QMainWindow>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <functional>

namespace pl::ui {

namespace {
constexpr int kLateLookMs = 50;
constexpr int kPasses = 4; // a dock may stop at its minimum: later passes give the rest to the others

struct Area {
    QList<QDockWidget*> docks;
    int width = 0, minimum = 0;
};
} // namespace

ViewportRoom::ViewportRoom(QMainWindow* window) : QObject(window), window_(window) {
    window->installEventFilter(this);
}

void ViewportRoom::settle() {
    for (int i = 0; i < 2; ++i) {
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        if (window_->layout()) window_->layout()->activate();
    }
}

void ViewportRoom::keepWidthAcross(const std::function<void()>& change) {
    const bool shown = window_->isVisible() && window_->centralWidget();
    const int before = shown ? window_->centralWidget()->width() : 0;
    change();
    if (!shown) return;
    widenCentral(before);
    // Fonts reach the docks' layouts through posted events: look again once they have run.
    for (int delay : {0, kLateLookMs})
        QTimer::singleShot(delay, this, [this, before] { widenCentral(before); });
}

void ViewportRoom::widenCentral(int width) {
    QWidget* central = window_->centralWidget();
    if (!central) return;
    settle();
    for (int pass = 0; pass < kPasses; ++pass) {
        const int missing = width - central->width();
        if (missing <= 0) return;
        Area areas[2];
        for (QDockWidget* dock : window_->findChildren<QDockWidget*>()) {
            if (!dock->isVisible() || dock->isFloating()) continue;
            const Qt::DockWidgetArea where = window_->dockWidgetArea(dock);
            if (where != Qt::LeftDockWidgetArea && where != Qt::RightDockWidgetArea) continue;
            Area& area = areas[where == Qt::LeftDockWidgetArea ? 0 : 1];
            area.docks << dock;
            area.width = std::max(area.width, dock->width());
            area.minimum = std::max({area.minimum, dock->minimumWidth(), dock->minimumSizeHint().width()});
        }
        const int slack =
            std::max(0, areas[0].width - areas[0].minimum) + std::max(0, areas[1].width - areas[1].minimum);
        if (slack == 0) return;
        QList<QDockWidget*> docks;
        QList<int> widths;
        for (const Area& area : areas) {
            const int own = std::max(0, area.width - area.minimum);
            const int cut = std::min(own, static_cast<int>(std::ceil(double(missing) * own / slack)));
            for (QDockWidget* dock : area.docks) {
                docks << dock;
                widths << area.width - cut;
            }
        }
        window_->resizeDocks(docks, widths, Qt::Horizontal);
        settle();
    }
}

void ViewportRoom::refit() {
    if (pending_) return;
    pending_ = true;
    QTimer::singleShot(0, this, &ViewportRoom::keepShare);
}

void ViewportRoom::keepShare() {
    pending_ = false;
    if (!window_->isVisible()) return;
    // Tall enough again for the plots that became tabs: they stand one above the other as before.
    if (stackWhenTall(window_, Qt::RightDockWidgetArea) | stackWhenTall(window_, Qt::LeftDockWidgetArea)) {
        refit(); // measured again once the plots have their new heights, not the tabs' old ones
        return;
    }
    wrapToolBars(window_);
    settle();
    // Too short for the plots stacked at a readable height: they become tabs.
    if (tabifyWhenShort(window_, Qt::RightDockWidgetArea, kReadablePanelHeight) |
        tabifyWhenShort(window_, Qt::LeftDockWidgetArea, kReadablePanelHeight))
        settle();
    widenCentral(static_cast<int>(kMinCentralShare * window_->width()));
}

bool ViewportRoom::eventFilter(QObject* watched, QEvent* event) {
    if (watched == window_ && (event->type() == QEvent::Show || event->type() == QEvent::Resize))
        refit(); // once per burst of resizes, after the layout has taken the new size
    return QObject::eventFilter(watched, event);
}

} // namespace pl::ui
