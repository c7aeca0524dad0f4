// ParticleView painting with QPainter: an aspect-correct map from model to widget coordinates.
#include "ParticleView.h"

#include "SimulationController.h"
#include "ThermalPalette.h"
#include "md/MdModel.h"

#include <QPainter>
#include <cmath>

namespace pl::ui {

namespace {
const QColor kBackground = QColor::fromRgbF(0.031f, 0.039f, 0.078f); // the seed's clear colour
const QColor kWalls(200, 205, 220);
const QColor kObstacle(120, 128, 150);
constexpr double kColourScaleOverRms = 2.8;
constexpr int kMarginPx = 12;
} // namespace

ParticleView::ParticleView(SimulationController* controller, QWidget* parent)
    : QWidget(parent), controller_(controller) {
    setAttribute(Qt::WA_OpaquePaintEvent);
    connect(controller, &SimulationController::frameAdvanced, this, qOverload<>(&QWidget::update));
    connect(controller, &SimulationController::modelReplaced, this, [this] {
        rescaleColours();
        update();
    });
}

void ParticleView::rescaleColours() {
    const auto* md = dynamic_cast<const MdModel*>(controller_->model());
    if (!md || md->particleCount() == 0) return;
    const auto& s = md->state();
    double sum = 0;
    for (std::size_t i = 0; i < s.size(); ++i) sum += s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i];
    const double rms = std::sqrt(sum / static_cast<double>(s.size()));
    if (rms > 0) colourSpeedMax_ = kColourScaleOverRms * rms;
}

void ParticleView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), kBackground);
    const auto* md = dynamic_cast<const MdModel*>(controller_->model());
    if (!md) return;
    const MdParams& p = md->parameters();
    const double scale =
        std::min((width() - 2.0 * kMarginPx) / p.boxWidth, (height() - 2.0 * kMarginPx) / p.boxHeight);
    const double originX = 0.5 * width(), originY = 0.5 * height();
    auto map = [&](double x, double y) { return QPointF(originX + scale * x, originY - scale * y); };

    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(kWalls, 1.5));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(QRectF(map(p.left(), p.top()), map(0.5 * p.boxWidth, p.bottom())));
    if (p.pistonEnabled) {
        painter.setPen(QPen(kWalls, 4));
        painter.drawLine(map(p.right(), p.bottom()), map(p.right(), p.top()));
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(kObstacle);
    for (const auto& o : md->obstacles()) {
        if (o.shape == Obstacle::Shape::Disc)
            painter.drawEllipse(map(o.x, o.y), scale * o.radius, scale * o.radius);
        else
            painter.drawRect(QRectF(map(o.x - o.halfWidth, o.y + o.halfHeight),
                                    map(o.x + o.halfWidth, o.y - o.halfHeight)));
    }
    const auto& s = md->state();
    const double radius[2] = {std::max(1.0, 0.5 * scale * p.a.diameter),
                              std::max(1.0, 0.5 * scale * p.b.diameter)};
    for (std::size_t i = 0; i < s.size(); ++i) {
        painter.setBrush(thermalColor(std::hypot(s.vx[i], s.vy[i]) / colourSpeedMax_));
        const double r = radius[s.species[i]];
        painter.drawEllipse(map(s.x[i], s.y[i]), r, r);
    }
}

} // namespace pl::ui
