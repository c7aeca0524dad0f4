// Keeps the viewport's room when something other than the user's own hand changes a window's dock
// layout: larger fonts (projector mode), a layout restored from the last session, a smaller window. The
// side docks give the room back, down to their minimum widths; a dock the user drags wider stays so
// until the window next changes size. It also lays the tool bars out in rows that fit the width, and
// turns stacked plot docks into tabs when the window is too short to give each a readable height.
#pragma once

#include <QObject>
#include <functional>

class QMainWindow;

namespace pl::ui {

class ViewportRoom : public QObject {
    Q_OBJECT
public:
    // The central widget keeps at least this share of the window's width, as far as docks allow.
    static constexpr double kMinCentralShare = 0.5;
    // Each panel of a plot dock keeps this height; below it, stacked docks become tabs.
    static constexpr int kReadablePanelHeight = 150;

    explicit ViewportRoom(QMainWindow* window);

    // Runs change (e.g. a font change) and then narrows the side docks until the central widget is at
    // least as wide as before, or the docks are at their minimum.
    void keepWidthAcross(const std::function<void()>& change);
    // Narrows the side docks until the central widget is at least width pixels wide, or they are at
    // their minimum widths.
    void widenCentral(int width);
    // Looks at the layout again once pending events have run (tool bars in rows that fit, plots too short
    // to stack turned into tabs, the viewport's share): after a change that resizes no window, such as
    // another scene's docks or larger fonts.
    void refit();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override; // shows and resizes of the window

private:
    void settle(); // lets pending layout requests run, so widths are the ones the user will see
    void keepShare();

    QMainWindow* window_;
    bool pending_ = false;
};

} // namespace pl::ui
