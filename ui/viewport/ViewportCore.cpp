// ViewportCore: tools act on the model only between steps (Qt delivers input between frames), and a
// dragged obstacle gets the velocity of the mouse in simulated time, so the particles it hits are pushed
// as by a moving wall (MdBoundaries reflects in the obstacle's frame).
#include "ViewportCore.h"

#include "Palette.h"
#include "SimulationController.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <QWidget>
#include <cmath>

namespace pl::ui {

namespace {
constexpr double kMarginPx = 14.0;
constexpr double kNewObstacleFraction = 0.06; // radius of a clicked-in obstacle, of the shorter box side
constexpr double kPistonGrabPx = 8.0;
constexpr double kClickPx = 3.0; // a press and release closer than this is a click, not a rectangle
constexpr double kPointRadiusPx = 2.0;
const QColor kWalls(200, 205, 220);
const QColor kObstacleFill(120, 128, 150);
const QColor kObstacleHover(170, 178, 200);
const QColor kLegendBack(0, 0, 0, 150);

double distance(QPointF a, QPointF b) {
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}
} // namespace

ViewportCore::ViewportCore(SimulationController* controller, QWidget* widget)
    : QObject(widget), controller_(controller), widget_(widget) {
    widget->installEventFilter(this);
    widget->setMouseTracking(true);
    connect(controller, &SimulationController::frameAdvanced, this, &ViewportCore::applyPendingDrag);
    connect(controller, &SimulationController::modelReplaced, this, [this] {
        gesture_ = Gesture::None;
        dragTarget_.reset();
        hovered_.reset();
    });
    frameClock_.start();
    updateCursor();
}

void ViewportCore::beginPaint() {
    const Model* model = controller_->model();
    scene_ = !model ? SceneView{} : drawsGpuBuffers_ ? model->sceneViewSharingGpu() : model->sceneView();
    transform_.fit(scene_, widget_->size(), kMarginPx);
}

void ViewportCore::endPaint() {
    ++framesCounted_;
    if (frameClock_.elapsed() >= 1000) {
        framesPerSecond_ = 1000.0 * framesCounted_ / static_cast<double>(frameClock_.restart());
        framesCounted_ = 0;
    }
}

void ViewportCore::setTool(ViewportTool tool) {
    tool_ = tool;
    gesture_ = Gesture::None;
    updateCursor();
    widget_->update();
}

void ViewportCore::zoomToFit() {
    transform_.zoomToFit();
    widget_->update();
}

void ViewportCore::updateCursor() {
    switch (tool_) {
    case ViewportTool::Drag:
        widget_->setCursor(gesture_ == Gesture::DragObstacle ? Qt::ClosedHandCursor : Qt::OpenHandCursor);
        break;
    case ViewportTool::Spawn:
    case ViewportTool::AddDisc:
    case ViewportTool::AddBox:
        widget_->setCursor(Qt::CrossCursor);
        break;
    case ViewportTool::Remove:
        widget_->setCursor(Qt::PointingHandCursor);
        break;
    case ViewportTool::Piston:
        widget_->setCursor(Qt::SplitHCursor);
        break;
    }
}

void ViewportCore::edited() {
    controller_->noteEdited();
    widget_->update();
}

std::optional<std::size_t> ViewportCore::obstacleAt(QPointF world) const {
    Model* model = controller_->model();
    SceneTools* tools = model ? model->tools() : nullptr;
    if (!tools) return std::nullopt;
    const auto& obstacles = tools->obstacles();
    for (std::size_t i = obstacles.size(); i-- > 0;) // the topmost (last drawn) first
        if (obstacles[i].contains(world.x(), world.y(), 0.0)) return i;
    return std::nullopt;
}

bool ViewportCore::nearPiston(QPointF widgetPoint) const {
    return scene_.pistonX &&
           std::abs(transform_.toWidget(*scene_.pistonX, 0).x() - widgetPoint.x()) < kPistonGrabPx;
}

bool ViewportCore::eventFilter(QObject* watched, QEvent* event) {
    if (watched != widget_) return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        press(static_cast<QMouseEvent*>(event));
        return true;
    case QEvent::MouseMove:
        move(static_cast<QMouseEvent*>(event));
        return true;
    case QEvent::MouseButtonRelease:
        release(static_cast<QMouseEvent*>(event));
        return true;
    case QEvent::Wheel: {
        auto* wheel = static_cast<QWheelEvent*>(event);
        transform_.zoomAt(wheel->position(), std::pow(1.0015, wheel->angleDelta().y()));
        widget_->update();
        return true;
    }
    default:
        return false;
    }
}

void ViewportCore::press(QMouseEvent* event) {
    pressPx_ = currentPx_ = event->position();
    SceneTools* tools = controller_->model() ? controller_->model()->tools() : nullptr;
    if (event->button() == Qt::MiddleButton || (event->button() == Qt::LeftButton && !tools)) {
        gesture_ = Gesture::Pan;
        return;
    }
    if (event->button() != Qt::LeftButton) return;
    const QPointF world = transform_.toWorld(pressPx_);
    switch (tool_) {
    case ViewportTool::Drag:
        if (const auto hit = obstacleAt(world)) {
            gesture_ = Gesture::DragObstacle;
            grabbed_ = *hit;
            const Obstacle& o = tools->obstacles()[*hit];
            grabOffset_ = QPointF(o.x - world.x(), o.y - world.y());
            lastDragTime_ = controller_->model()->time();
        } else if (nearPiston(pressPx_) && tools->hasPiston()) {
            gesture_ = Gesture::DragPiston;
        } else {
            gesture_ = Gesture::Pan;
        }
        break;
    case ViewportTool::Piston:
        if (!tools->hasPiston()) {
            emit statusMessage(
                tr("This experiment has no piston: enable it in Parameters (piston_enabled)."));
            return;
        }
        gesture_ = Gesture::DragPiston;
        move(event);
        break;
    case ViewportTool::Spawn:
    case ViewportTool::AddBox:
        gesture_ = Gesture::Rectangle;
        break;
    case ViewportTool::AddDisc: {
        Obstacle disc;
        disc.radius = kNewObstacleFraction * std::min(scene_.right - scene_.left, scene_.top - scene_.bottom);
        disc.x = world.x();
        disc.y = world.y();
        tools->addObstacle(disc);
        edited();
        break;
    }
    case ViewportTool::Remove:
        if (const auto hit = obstacleAt(world)) {
            tools->removeObstacle(*hit);
            hovered_.reset();
            edited();
        }
        break;
    }
    updateCursor();
}

void ViewportCore::move(QMouseEvent* event) {
    const QPointF previous = currentPx_;
    currentPx_ = event->position();
    const QPointF world = transform_.toWorld(currentPx_);
    SceneTools* tools = controller_->model() ? controller_->model()->tools() : nullptr;
    switch (gesture_) {
    case Gesture::None: {
        const auto hit = obstacleAt(world);
        if (hit != hovered_) {
            hovered_ = hit;
            widget_->update();
        }
        if (tool_ == ViewportTool::AddDisc) widget_->update(); // the preview follows the mouse
        return;
    }
    case Gesture::Pan:
        transform_.panBy(currentPx_ - previous);
        break;
    case Gesture::DragObstacle:
        dragTarget_ = world + grabOffset_;
        if (!controller_->isRunning()) applyPendingDrag(); // paused: place it now, at rest
        break;
    case Gesture::DragPiston:
        if (tools && tools->hasPiston()) {
            tools->movePiston(world.x(), 0.0);
            controller_->noteEdited();
        }
        break;
    case Gesture::Rectangle:
        break;
    }
    widget_->update();
}

void ViewportCore::applyPendingDrag() {
    if (gesture_ != Gesture::DragObstacle || !dragTarget_) return;
    Model* model = controller_->model();
    SceneTools* tools = model ? model->tools() : nullptr;
    if (!tools || grabbed_ >= tools->obstacles().size()) return;
    const Obstacle& o = tools->obstacles()[grabbed_];
    const double elapsed = model->time() - lastDragTime_;
    double vx = 0, vy = 0;
    if (controller_->isRunning() && elapsed != 0.0) { // signed: with time reversed the velocity flips
        vx = (dragTarget_->x() - o.x) / elapsed;
        vy = (dragTarget_->y() - o.y) / elapsed;
    }
    tools->moveObstacle(grabbed_, dragTarget_->x(), dragTarget_->y(), vx, vy);
    lastDragTime_ = model->time();
    dragTarget_.reset();
    controller_->noteEdited();
}

void ViewportCore::release(QMouseEvent* event) {
    currentPx_ = event->position();
    SceneTools* tools = controller_->model() ? controller_->model()->tools() : nullptr;
    const Gesture finished = gesture_;
    gesture_ = Gesture::None;
    if (finished == Gesture::DragObstacle && tools && grabbed_ < tools->obstacles().size()) {
        dragTarget_ = transform_.toWorld(currentPx_) + grabOffset_;
        gesture_ = Gesture::DragObstacle; // for the last move
        applyPendingDrag();
        gesture_ = Gesture::None;
        const Obstacle& o = tools->obstacles()[grabbed_];
        tools->moveObstacle(grabbed_, o.x, o.y, 0.0, 0.0); // let go: it stops
    }
    if (finished == Gesture::Rectangle && tools) {
        QPointF a = transform_.toWorld(pressPx_), b = transform_.toWorld(currentPx_);
        const bool click = distance(pressPx_, currentPx_) < kClickPx;
        if (tool_ == ViewportTool::Spawn) {
            if (click) b = a;
            emit statusMessage(QString::fromStdString(tools->spawnInRectangle(a.x(), a.y(), b.x(), b.y())));
        } else {
            Obstacle box;
            box.shape = Obstacle::Shape::Box;
            const double half =
                kNewObstacleFraction * std::min(scene_.right - scene_.left, scene_.top - scene_.bottom);
            box.x = click ? a.x() : 0.5 * (a.x() + b.x());
            box.y = click ? a.y() : 0.5 * (a.y() + b.y());
            box.halfWidth = click ? half : 0.5 * std::abs(a.x() - b.x());
            box.halfHeight = click ? half : 0.5 * std::abs(a.y() - b.y());
            tools->addObstacle(box);
        }
        edited();
    }
    updateCursor();
    widget_->update();
}

void ViewportCore::paintParticles(QPainter& painter) const {
    painter.setPen(Qt::NoPen);
    const double scale = transform_.scale();
    for (std::size_t i = 0; i < scene_.size(); ++i) {
        painter.setBrush(paletteColour(scene_.colours, scene_.value[i]));
        const double r = scene_.radius[i] > 0 ? std::max(1.0, scale * scene_.radius[i]) : kPointRadiusPx;
        painter.drawEllipse(transform_.toWidget(scene_.x[i], scene_.y[i]), r, r);
    }
}

void ViewportCore::paintOverlay(QPainter& painter) const {
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF box = transform_.toWidget(scene_.left, scene_.bottom, scene_.right, scene_.top);
    painter.setBrush(Qt::NoBrush);
    if (scene_.drawBox) {
        painter.setPen(QPen(kWalls, 1.5));
        painter.drawRect(box);
    }
    if (!scene_.xLabel.empty() || !scene_.yLabel.empty()) {
        painter.setPen(QPen(kWalls, 1.0, Qt::DashLine));
        const QPointF origin = transform_.toWidget(0, 0);
        painter.drawLine(QPointF(box.left(), origin.y()), QPointF(box.right(), origin.y()));
        painter.drawLine(QPointF(origin.x(), box.top()), QPointF(origin.x(), box.bottom()));
        painter.setPen(kWalls);
        painter.drawText(box.adjusted(4, 0, -4, -4), Qt::AlignRight | Qt::AlignBottom,
                         QString::fromStdString(scene_.xLabel));
        painter.drawText(box.adjusted(4, 4, 0, 0), Qt::AlignLeft | Qt::AlignTop,
                         QString::fromStdString(scene_.yLabel));
    }
    if (!scene_.hint.empty()) {
        // The seed's faint instruction: large, bold, 20 % opaque, out of the way once there is fluid.
        QFont font = painter.font();
        font.setBold(true);
        font.setPointSizeF(font.pointSizeF() * 2.2);
        painter.save();
        painter.setFont(font);
        painter.setPen(QColor(255, 255, 255, 51));
        painter.drawText(box, Qt::AlignCenter | Qt::TextWordWrap, QString::fromStdString(scene_.hint));
        painter.restore();
    }
    for (std::size_t i = 0; i < scene_.obstacles.size(); ++i) {
        const Obstacle& o = scene_.obstacles[i];
        const bool active = hovered_ == i || (gesture_ == Gesture::DragObstacle && grabbed_ == i);
        painter.setPen(QPen(kWalls, active ? 2.0 : 1.0));
        painter.setBrush(active ? kObstacleHover : kObstacleFill);
        if (o.shape == Obstacle::Shape::Disc)
            painter.drawEllipse(transform_.toWidget(o.x, o.y), transform_.scale() * o.radius,
                                transform_.scale() * o.radius);
        else
            painter.drawRect(transform_.toWidget(o.x - o.halfWidth, o.y - o.halfHeight, o.x + o.halfWidth,
                                                 o.y + o.halfHeight));
    }
    if (scene_.pistonX) {
        const double x = transform_.toWidget(*scene_.pistonX, 0).x();
        painter.setPen(QPen(kWalls, gesture_ == Gesture::DragPiston ? 6 : 4));
        painter.drawLine(QPointF(x, box.top()), QPointF(x, box.bottom()));
    }
    if (gesture_ == Gesture::Rectangle) { // the fluid seed's semi-transparent spawn preview
        painter.setPen(QPen(QColor(255, 255, 255, 200), 1, Qt::DashLine));
        painter.setBrush(tool_ == ViewportTool::Spawn ? QColor(255, 255, 255, 60)
                                                      : QColor(120, 128, 150, 120));
        painter.drawRect(QRectF(pressPx_, currentPx_).normalized());
    }
    if (tool_ == ViewportTool::AddDisc && gesture_ == Gesture::None && widget_->underMouse()) {
        const double r = transform_.scale() * kNewObstacleFraction *
                         std::min(scene_.right - scene_.left, scene_.top - scene_.bottom);
        painter.setPen(QPen(kWalls, 1, Qt::DashLine));
        painter.setBrush(QColor(120, 128, 150, 90));
        painter.drawEllipse(currentPx_, r, r);
    }
    paintLegend(painter);
}

void ViewportCore::paintLegend(QPainter& painter) const {
    const QFontMetricsF metrics(painter.font());
    const double line = metrics.height();
    const double width = 11 * line;
    if (isCategorical(scene_.colours)) {
        if (scene_.categories.empty()) return;
        const QRectF frame(transform_.size().width() - width - 8, 8, width,
                           (static_cast<double>(scene_.categories.size()) + 0.6) * line);
        painter.setPen(Qt::NoPen);
        painter.setBrush(kLegendBack);
        painter.drawRoundedRect(frame, 4, 4);
        for (std::size_t c = 0; c < scene_.categories.size(); ++c) {
            const double y = frame.top() + (static_cast<double>(c) + 0.3) * line;
            painter.setBrush(paletteColour(scene_.colours, static_cast<double>(c)));
            painter.setPen(Qt::NoPen);
            painter.drawEllipse(QPointF(frame.left() + 0.7 * line, y + 0.5 * line), 0.3 * line, 0.3 * line);
            painter.setPen(Qt::white);
            painter.drawText(QRectF(frame.left() + 1.4 * line, y, width - 1.6 * line, line), Qt::AlignVCenter,
                             QString::fromStdString(scene_.categories[c]));
        }
        return;
    }
    const QRectF frame(transform_.size().width() - width - 8, 8, width, 2.6 * line);
    painter.setPen(Qt::NoPen);
    painter.setBrush(kLegendBack);
    painter.drawRoundedRect(frame, 4, 4);
    const QRectF bar(frame.left() + 0.5 * line, frame.top() + 0.3 * line, width - line, 0.8 * line);
    QLinearGradient gradient(bar.topLeft(), bar.topRight());
    const QVector<QColor>& stops = paletteStops(scene_.colours);
    for (qsizetype s = 0; s < stops.size(); ++s)
        gradient.setColorAt(static_cast<double>(s) / static_cast<double>(stops.size() - 1), stops[s]);
    painter.setBrush(gradient);
    painter.drawRect(bar);
    painter.setPen(Qt::white);
    const QRectF labels(bar.left(), bar.bottom() + 0.1 * line, bar.width(), line);
    painter.drawText(labels, Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("0"));
    painter.drawText(labels, Qt::AlignHCenter | Qt::AlignVCenter, QString::fromStdString(scene_.colourLabel));
    painter.drawText(labels, Qt::AlignRight | Qt::AlignVCenter, QString::number(scene_.colourMax, 'g', 3));
}

} // namespace pl::ui
