// The viewport drawn with QPainter alone: used where no OpenGL widget can be made (the `offscreen`
// platform, a machine without GL). Same snapshot, tools and overlay as GLViewport.
#pragma once

#include <QWidget>

namespace pl::ui {

class SimulationController;
class ViewportCore;

class SoftwareViewport : public QWidget {
    Q_OBJECT
public:
    explicit SoftwareViewport(SimulationController* controller, QWidget* parent = nullptr);
    ViewportCore* core() const { return core_; }
    QSize sizeHint() const override { return {800, 800}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    ViewportCore* core_;
};

} // namespace pl::ui
