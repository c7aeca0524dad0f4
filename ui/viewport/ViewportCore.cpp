// ViewportCore: tools act on the model only between steps (Qt delivers input between frames). A drag
// only sets a target: while time runs the model moves the obstacle or piston there at its bounded tool
// speed every step (KinematicDrive.h), so what the particles feel does not depend on the frame rate;
// while time stands still the body is placed at once, at rest.
#include "ViewportCore.h"

#include "Palette.h"
#include "SimulationController.h"
#include "i18n/Translations.h"

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
    connect(controller, &SimulationController::modelReplaced, this, [this] {
        gesture_ = Gesture::None;
        hovered_.reset();
        steeredTo_.reset();
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

std::optional<std::size_t> ViewportCore::obstacleAt(QPointF world) const {
    const SceneTools* tools = controller_->tools();
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
    const SceneTools* tools = controller_->tools();
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
        } else if (nearPiston(pressPx_) && tools->hasPiston()) {
            gesture_ = Gesture::DragPiston;
        } else {
            gesture_ = scene_.dragPours ? Gesture::Pour : Gesture::Pan;
        }
        break;
    case ViewportTool::Piston:
        if (!tools->hasPiston()) {
            emit statusMessage(
                tr("This experiment has no piston: tick “Piston” in Parameters → Walls and fields."));
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
        controller_->addObstacle(disc);
        widget_->update();
        break;
    }
    case ViewportTool::Remove:
        if (const auto hit = obstacleAt(world)) {
            controller_->removeObstacle(*hit);
            hovered_.reset();
            widget_->update();
        }
        break;
    }
    updateCursor();
}

void ViewportCore::move(QMouseEvent* event) {
    const QPointF previous = currentPx_;
    currentPx_ = event->position();
    const QPointF world = transform_.toWorld(currentPx_);
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
        steerObstacle(world + grabOffset_);
        break;
    case Gesture::DragPiston:
        steerPiston(world.x());
        break;
    case Gesture::Rectangle:
    case Gesture::Pour:
        break;
    }
    widget_->update();
}

void ViewportCore::steerObstacle(QPointF target) {
    if (!controller_->steerObstacle(grabbed_, target.x(), target.y())) return;
    if (controller_->isRunning())
        steeredTo_ = target; // drawn until the body arrives
    else
        steeredTo_.reset();
}

void ViewportCore::steerPiston(double x) {
    controller_->steerPiston(x);
}

void ViewportCore::release(QMouseEvent* event) {
    currentPx_ = event->position();
    const SceneTools* tools = controller_->tools();
    const Gesture finished = gesture_;
    gesture_ = Gesture::None;
    if (finished == Gesture::DragObstacle && tools && grabbed_ < tools->obstacles().size()) {
        steerObstacle(transform_.toWorld(currentPx_) + grabOffset_);
        controller_->releaseObstacle(grabbed_); // let go: it coasts to the last target and stops there
    }
    if (finished == Gesture::DragPiston) steerPiston(transform_.toWorld(currentPx_).x());
    if ((finished == Gesture::Rectangle || finished == Gesture::Pour) && tools) {
        QPointF a = transform_.toWorld(pressPx_), b = transform_.toWorld(currentPx_);
        const bool click = distance(pressPx_, currentPx_) < kClickPx;
        if (tool_ == ViewportTool::Spawn || finished == Gesture::Pour) {
            if (click) b = a;
            emit statusMessage(controller_->spawnInRectangle(a.x(), a.y(), b.x(), b.y()));
        } else {
            Obstacle box;
            box.shape = Obstacle::Shape::Box;
            const double half =
                kNewObstacleFraction * std::min(scene_.right - scene_.left, scene_.top - scene_.bottom);
            box.x = click ? a.x() : 0.5 * (a.x() + b.x());
            box.y = click ? a.y() : 0.5 * (a.y() + b.y());
            box.halfWidth = click ? half : 0.5 * std::abs(a.x() - b.x());
            box.halfHeight = click ? half : 0.5 * std::abs(a.y() - b.y());
            controller_->addObstacle(box);
        }
        widget_->update();
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
        // Tick values along the bottom and the left edge of what is visible, inside the box (the view's
        // margin is narrow): steps of 1, 2 or 5 × 10^k, about one per kTickSpacingPx, following zoom and pan.
        constexpr double kTickSpacingPx = 90.0, kTickPx = 5.0;
        const auto niceStep = [](double span, double pixels) {
            const double raw = std::abs(span) * kTickSpacingPx / std::max(pixels, 1.0);
            const double decade = std::pow(10.0, std::floor(std::log10(raw)));
            for (const double m : {1.0, 2.0, 5.0})
                if (m * decade >= raw) return m * decade;
            return 10.0 * decade;
        };
        const auto tickText = [](double v, double step) {
            return QString::number(std::abs(v) < 1e-6 * step ? 0.0 : v, 'g', 4);
        };
        const QFontMetricsF metrics(painter.font());
        const double line = metrics.height();
        const QRectF shown = box.intersected(QRectF(QPointF(0, 0), transform_.size()));
        const QPointF low = transform_.toWorld(shown.bottomLeft()),
                      high = transform_.toWorld(shown.topRight());
        painter.setPen(kWalls);
        double numbersWidth = 0; // of the y tick values, so the y label starts beside them
        if (shown.width() > 0 && shown.height() > 0 && high.x() > low.x() && high.y() > low.y()) {
            const double dx = niceStep(high.x() - low.x(), shown.width());
            for (double v = std::ceil(low.x() / dx) * dx; v <= high.x() + 1e-9 * dx; v += dx) {
                const double px = transform_.toWidget(v, 0).x();
                painter.drawLine(QPointF(px, shown.bottom()), QPointF(px, shown.bottom() - kTickPx));
                painter.drawText(QRectF(px - 4 * line, shown.bottom() - kTickPx - line, 8 * line, line),
                                 Qt::AlignCenter, tickText(v, dx));
            }
            const double dy = niceStep(high.y() - low.y(), shown.height());
            for (double v = std::ceil(low.y() / dy) * dy; v <= high.y() + 1e-9 * dy; v += dy) {
                const double py = transform_.toWidget(0, v).y();
                const QString text = tickText(v, dy);
                painter.drawLine(QPointF(shown.left(), py), QPointF(shown.left() + kTickPx, py));
                painter.drawText(QRectF(shown.left() + kTickPx + 2, py - 0.5 * line, 8 * line, line),
                                 Qt::AlignLeft | Qt::AlignVCenter, text);
                numbersWidth = std::max(numbersWidth, metrics.horizontalAdvance(text));
            }
        }
        // The axis names sit clear of the tick values: x above the bottom row, y right of the left column.
        painter.drawText(shown.adjusted(4, 0, -4, -(kTickPx + line + 2)), Qt::AlignRight | Qt::AlignBottom,
                         coreText(scene_.xLabel));
        painter.drawText(shown.adjusted(kTickPx + numbersWidth + 12, 4, 0, 0), Qt::AlignLeft | Qt::AlignTop,
                         coreText(scene_.yLabel));
    }
    if (!scene_.hint.empty()) {
        // The seed's faint instruction: large, bold, 20 % opaque, out of the way once there is fluid.
        QFont font = painter.font();
        font.setBold(true);
        font.setPointSizeF(font.pointSizeF() * 2.2);
        painter.save();
        painter.setFont(font);
        painter.setPen(QColor(255, 255, 255, 51));
        painter.drawText(box, Qt::AlignCenter | Qt::TextWordWrap, coreText(scene_.hint));
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
    paintSteeredTarget(painter);
    if (scene_.pistonX) {
        const double x = transform_.toWidget(*scene_.pistonX, 0).x();
        painter.setPen(QPen(kWalls, gesture_ == Gesture::DragPiston ? 6 : 4));
        painter.drawLine(QPointF(x, box.top()), QPointF(x, box.bottom()));
    }
    if (gesture_ == Gesture::Rectangle || gesture_ == Gesture::Pour) { // the seed's spawn preview
        painter.setPen(QPen(QColor(255, 255, 255, 200), 1, Qt::DashLine));
        painter.setBrush(tool_ == ViewportTool::Spawn || gesture_ == Gesture::Pour
                             ? QColor(255, 255, 255, 60)
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

void ViewportCore::paintSteeredTarget(QPainter& painter) const {
    // Where a dragged obstacle is heading: it follows the hand at the tool speed, so it may lag behind.
    const SceneTools* tools = controller_->tools();
    if (!steeredTo_ || !tools || !tools->bodiesMoving() || grabbed_ >= scene_.obstacles.size()) return;
    const Obstacle& o = scene_.obstacles[grabbed_];
    painter.save();
    painter.setPen(QPen(kWalls, 1.0, Qt::DashLine));
    painter.setBrush(Qt::NoBrush);
    const double x = steeredTo_->x(), y = steeredTo_->y();
    if (o.shape == Obstacle::Shape::Disc)
        painter.drawEllipse(transform_.toWidget(x, y), transform_.scale() * o.radius,
                            transform_.scale() * o.radius);
    else
        painter.drawRect(
            transform_.toWidget(x - o.halfWidth, y - o.halfHeight, x + o.halfWidth, y + o.halfHeight));
    painter.drawLine(transform_.toWidget(o.x, o.y), transform_.toWidget(x, y));
    painter.restore();
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
                             coreText(scene_.categories[c]));
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
    painter.drawText(labels, Qt::AlignHCenter | Qt::AlignVCenter, coreText(scene_.colourLabel));
    painter.drawText(labels, Qt::AlignRight | Qt::AlignVCenter, QString::number(scene_.colourMax, 'g', 3));
}

} // namespace pl::ui
