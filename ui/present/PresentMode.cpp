// PresentMode: what it hides it records first (QMainWindow::saveState holds docks and tool bars; the menu
// and status bar and the window's state are kept beside it), and leaving puts exactly that back.
#include "PresentMode.h"

#include "PresentPanel.h"
#include "SimulationController.h"

#include <QApplication>
#include <QDockWidget>
#include <QEvent>
#include <QLayout>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>
#include <QShortcut>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <algorithm>

namespace pl::ui {

namespace {
// Every action of a menu tree that has a key.
void collectShortcutActions(const QList<QAction*>& actions, QList<QAction*>& out) {
    for (QAction* action : actions) {
        if (QMenu* menu = action->menu())
            collectShortcutActions(menu->actions(), out);
        else if (!action->shortcut().isEmpty())
            out << action;
    }
}
} // namespace

PresentMode::PresentMode(QMainWindow* window, SimulationController* controller, QWidget* viewport,
                         const QFont& baseFont)
    : QObject(window), window_(window), controller_(controller), viewport_(viewport), baseFont_(baseFont),
      escape_(new QShortcut(QKeySequence(Qt::Key_Escape), window)) {
    escape_->setEnabled(false);
    connect(escape_, &QShortcut::activated, this, [this] { setActive(false); });
    connect(controller, &SimulationController::modelReplaced, this, [this] {
        if (isActive()) hideEverythingElse(); // the window shows a new scene's docks: not here
    });
}

void PresentMode::setActive(bool on) {
    if (on == isActive()) return;
    on ? enter() : leave();
    emit activeChanged(on);
}

void PresentMode::enter() {
    QStatusBar* status = window_->findChild<QStatusBar*>(QString(), Qt::FindDirectChildrenOnly);
    saved_ = {window_->saveState(), window_->saveGeometry(), window_->windowState(),
              window_->menuWidget() && !window_->menuWidget()->isHidden(), status && !status->isHidden()};
    // A window too short for the board (a large font on a small screen) scrolls the panel rather than
    // squeezing the viewport; the board is laid out to fit 1024 × 700 without it.
    scroll_ = new QScrollArea;
    scroll_->setWidgetResizable(true);
    scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll_->setFrameShape(QFrame::NoFrame);
    makePanel();
    dock_ = new QDockWidget(tr("Present"), window_);
    dock_->setObjectName("presentDock");
    dock_->setFeatures(QDockWidget::NoDockWidgetFeatures);
    dock_->setTitleBarWidget(new QWidget(dock_)); // no title: the panel is part of the layout
    dock_->setWidget(scroll_);
    window_->addDockWidget(Qt::RightDockWidgetArea, dock_);
    hideEverythingElse();
    // Without a menu bar its actions' keys would stop working: the window holds them meanwhile.
    QList<QAction*> keyed;
    if (auto* bar = qobject_cast<QMenuBar*>(window_->menuWidget()))
        collectShortcutActions(bar->actions(), keyed);
    borrowed_.clear();
    for (QAction* action : std::as_const(keyed))
        if (!window_->actions().contains(action)) {
            window_->addAction(action);
            borrowed_ << action;
        }
    if (window_->menuWidget()) window_->menuWidget()->hide();
    if (status) status->hide();
    escape_->setEnabled(true);
    window_->installEventFilter(this);
    window_->showFullScreen();
    fitPanel();
    QTimer::singleShot(0, this, &PresentMode::fitPanel); // again once full screen has taken effect
    viewport_->setFocus(Qt::OtherFocusReason);
}

void PresentMode::makePanel() {
    // The panel's text is PresentPanel::kFontScale times the window's usual text, or the window's text
    // where projector mode has made that larger: the two enlargements do not multiply (2.2 × at 1.6 and
    // 1.35 left a 1024 × 700 board with a 30 px plot and its controls below the screen's edge).
    QFont font = QApplication::font();
    font.setPointSizeF(std::max(font.pointSizeF(), baseFont_.pointSizeF() * PresentPanel::kFontScale));
    panel_ = new PresentPanel(controller_, window_->findChild<QAction*>("recordAction"), font);
    panel_->installEventFilter(this); // its minimum width grows with longer numbers or another scene
    connect(panel_, &PresentPanel::leaveRequested, this, [this] { setActive(false); });
    connect(panel_, &PresentPanel::toolRequested, this, &PresentMode::toolRequested);
    delete scroll_->takeWidget();
    scroll_->setWidget(panel_);
    widened_ = false;
}

void PresentMode::hideEverythingElse() {
    for (QDockWidget* dock : window_->findChildren<QDockWidget*>())
        if (dock != dock_) dock->hide();
    for (QToolBar* bar : window_->findChildren<QToolBar*>()) bar->hide();
}

void PresentMode::fitPanel() {
    if (!dock_) return;
    // The share, widened (up to kPanelMostShare) where the board needs more to show its controls whole;
    // the readouts' numbers and a new scene's controls may need more later (the panel's LayoutRequest).
    const int needed = panel_->minimumSizeHint().width() +
                       panel_->style()->pixelMetric(QStyle::PM_ScrollBarExtent) + kPanelSlack;
    const int most = static_cast<int>(kPanelMostShare * window_->width());
    int width = std::min(
        std::max(std::min(kPanelMaxWidth, static_cast<int>(kPanelShare * window_->width())), needed), most);
    // A board taller than the window at that width (projector mode on 1024 × 700) takes the widest share:
    // wrapped titles take fewer lines and the readouts fit beside their names, so nothing needs scrolling.
    // Once widened it stays so until the window's size changes, so the two widths never alternate.
    QLayout* layout = panel_->layout();
    const int tallest =
        std::max(panel_->minimumSizeHint().height(),
                 layout->hasHeightForWidth() ? layout->minimumHeightForWidth(panel_->width()) : 0);
    if (!widened_ && tallest > window_->height()) widened_ = true;
    if (widened_) width = std::max(width, most);
    if (width != dock_->width()) window_->resizeDocks({dock_}, {width}, Qt::Horizontal);
}

bool PresentMode::eventFilter(QObject* watched, QEvent* event) {
    if (dock_ && watched == window_ && event->type() == QEvent::Resize) widened_ = false;
    if (dock_ && ((watched == window_ && event->type() == QEvent::Resize) ||
                  (watched == panel_ && event->type() == QEvent::LayoutRequest)))
        QTimer::singleShot(0, this, &PresentMode::fitPanel);
    // Projector mode switched while presenting: the panel keeps the font it was made with, so it is made
    // again (its children's style sheets fix their fonts at creation).
    if (dock_ && watched == window_ && event->type() == QEvent::ApplicationFontChange)
        QTimer::singleShot(0, this, [this] {
            if (!dock_) return;
            makePanel();
            fitPanel();
        });
    return QObject::eventFilter(watched, event);
}

void PresentMode::leave() {
    window_->removeEventFilter(this);
    escape_->setEnabled(false);
    window_->removeDockWidget(dock_);
    dock_->deleteLater();
    dock_ = nullptr;
    scroll_ = nullptr;
    panel_ = nullptr;
    for (QAction* action : std::as_const(borrowed_)) window_->removeAction(action);
    borrowed_.clear();
    if (window_->menuWidget()) window_->menuWidget()->setVisible(saved_.menuBar);
    if (auto* status = window_->findChild<QStatusBar*>(QString(), Qt::FindDirectChildrenOnly))
        status->setVisible(saved_.statusBar);
    window_->setWindowState(saved_.windowState);
    if (!(saved_.windowState & (Qt::WindowFullScreen | Qt::WindowMaximized)))
        window_->restoreGeometry(saved_.geometry);
    window_->restoreState(saved_.state);
    viewport_->setFocus(Qt::OtherFocusReason);
}

} // namespace pl::ui
