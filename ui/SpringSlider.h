// A slider that acts while it is held: let go, it springs back to 0, however it was moved — the handle
// dragged, the groove held (which steps it on while pressed) or an arrow key held. The wheel, which has
// no "let go", does not move it. Heat / Cool is one: a latched heater would run the gas away.
#pragma once

#include <QKeyEvent>
#include <QMouseEvent>
#include <QSlider>

namespace pl::ui {

class SpringSlider : public QSlider {
public:
    using QSlider::QSlider;

protected:
    void mouseReleaseEvent(QMouseEvent* event) override {
        QSlider::mouseReleaseEvent(event);
        setValue(0);
    }
    void keyReleaseEvent(QKeyEvent* event) override {
        QSlider::keyReleaseEvent(event);
        if (!event->isAutoRepeat()) setValue(0);
    }
    void wheelEvent(QWheelEvent* event) override { event->ignore(); } // the toolbar's, not a setting
};

} // namespace pl::ui
