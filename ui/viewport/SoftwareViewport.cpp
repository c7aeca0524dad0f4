// SoftwareViewport: background, the sampled field, particles, overlay, in that order.
#include "SoftwareViewport.h"

#include "FrameProfile.h"
#include "SimulationController.h"
#include "ViewportCore.h"

#include <QPainter>

namespace pl::ui {

SoftwareViewport::SoftwareViewport(SimulationController* controller, QWidget* parent)
    : QWidget(parent), core_(new ViewportCore(controller, this)) {
    setFocusPolicy(Qt::StrongFocus); // the window's keys start here, and a click brings them back
    setAttribute(Qt::WA_OpaquePaintEvent);
    connect(controller, &SimulationController::frameAdvanced, this, qOverload<>(&QWidget::update));
    connect(controller, &SimulationController::modelReplaced, this, qOverload<>(&QWidget::update));
}

void SoftwareViewport::paintEvent(QPaintEvent*) {
    const FramePartTimer timer(FramePart::Viewport);
    core_->beginPaint();
    QPainter painter(this);
    const auto& bg = core_->scene().background;
    painter.fillRect(rect(), QColor::fromRgbF(bg[0], bg[1], bg[2]));
    core_->paintField(painter);
    painter.setRenderHint(QPainter::Antialiasing);
    core_->paintParticles(painter);
    core_->paintOverlay(painter);
    core_->endPaint();
    painter.end();
    FrameProfile::instance().frameShown();
}

} // namespace pl::ui
