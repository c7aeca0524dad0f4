// ViewportCore: tools act on the model only between steps (Qt delivers input between frames). A drag
// only sets a target: while time runs the model moves the obstacle or piston there at its bounded tool
// speed every step (KinematicDrive.h), so what the particles feel does not depend on the frame rate;
// while time stands still the body is placed at once, at rest.
#include "ViewportCore.h"

#include "FieldOverlay.h"
#include "SceneDescription.h"
#include "ScenePainter.h"
#include "SimulationController.h"
#include "i18n/Translations.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <QWidget>
#include <cmath>

namespace pl::ui {

namespace {
constexpr double kNewObstacleFraction = 0.06; // radius of a clicked-in obstacle, of the shorter box side
constexpr double kPistonGrabPx = 8.0;
constexpr double kClickPx = 3.0; // a press and release closer than this is a click, not a rectangle
const QColor kWalls(200, 205, 220);

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
        probe_.reset();
        colourScale_.restart();
        setProfileLine(std::nullopt); // another domain: the old line would mean nothing there
        describeSoon_ = true;
    });
    // A parameter such as the field shown changes the picture even while time stands still.
    connect(controller, &SimulationController::parametersChanged, this, [this] {
        describeSoon_ = true;
        requestFrame();
    });
    frameClock_.start();
    describedClock_.start();
    updateCursor();
}

void ViewportCore::beginPaint() {
    const Model* model = controller_->model();
    scene_ = !model ? SceneView{} : drawsGpuBuffers_ ? model->sceneViewSharingGpu() : model->sceneView();
    // A reset run starts at the model's top again; an exploded state's speeds say nothing about a scale.
    if (model && model->stepCount() < paintedStep_) colourScale_.restart();
    paintedStep_ = model ? model->stepCount() : 0;
    if (model && !model->failure()) colourScale_.apply(scene_);
    transform_.fit(scene_, widget_->size(), kSceneMarginPx);
}

void ViewportCore::requestFrame() const {
    if (frameRequest_)
        frameRequest_();
    else
        widget_->update();
}

void ViewportCore::endPaint() {
    // A screen reader reads the description when asked: once a second keeps its numbers current without
    // an accessibility event every frame.
    if (describeSoon_ || describedClock_.elapsed() >= kDescribeIntervalMs) describe();
    controller_->frameShown();
    ++framesCounted_;
    if (frameClock_.elapsed() >= 1000) {
        framesPerSecond_ = 1000.0 * framesCounted_ / static_cast<double>(frameClock_.restart());
        framesCounted_ = 0;
    }
}

void ViewportCore::describe() {
    describeSoon_ = false;
    describedClock_.restart();
    const Model* model = controller_->model();
    const QString name = model ? sceneAccessibleName(*model) : tr("Scene: none loaded");
    const QString description =
        model ? sceneAccessibleDescription(*model, scene_, *controller_->series()) : QString();
    // Each setter sends its change event to the accessibility tree; an unchanged text sends none.
    if (widget_->accessibleName() != name) widget_->setAccessibleName(name);
    if (widget_->accessibleDescription() != description) widget_->setAccessibleDescription(description);
}

void ViewportCore::setTool(ViewportTool tool) {
    tool_ = tool;
    gesture_ = Gesture::None;
    updateCursor();
    requestFrame();
}

void ViewportCore::zoomToFit() {
    transform_.zoomToFit();
    requestFrame();
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
    case ViewportTool::ProfileLine:
        widget_->setCursor(Qt::CrossCursor);
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
        requestFrame();
        return true;
    }
    default:
        return false;
    }
}

void ViewportCore::press(QMouseEvent* event) {
    pressPx_ = currentPx_ = event->position();
    const SceneTools* tools = controller_->tools();
    if (event->button() == Qt::RightButton && probe_) {
        closeProbe();
        return;
    }
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
        } else if (hasSampledFields()) { // read the local values, as Bird's Visual Wind Tunnel does
            gesture_ = Gesture::Probe;
            probe_ = world;
            requestFrame();
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
        requestFrame();
        break;
    }
    case ViewportTool::ProfileLine:
        if (!hasSampledFields()) {
            emit statusMessage(tr("This experiment samples no fields to draw a profile of."));
            return;
        }
        gesture_ = Gesture::Line;
        break;
    case ViewportTool::Remove:
        if (const auto hit = obstacleAt(world)) {
            controller_->removeObstacle(*hit);
            hovered_.reset();
            requestFrame();
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
            requestFrame();
        }
        if (tool_ == ViewportTool::AddDisc) requestFrame(); // the preview follows the mouse
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
    case Gesture::Probe:
        probe_ = world;
        break;
    case Gesture::Rectangle:
    case Gesture::Pour:
    case Gesture::Line:
        break;
    }
    requestFrame();
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
    if (finished == Gesture::Probe) probe_ = transform_.toWorld(currentPx_);
    if (finished == Gesture::Line) {
        if (distance(pressPx_, currentPx_) < kClickPx)
            emit statusMessage(tr("Drag across the flow to draw the profile line."));
        else
            setProfileLine(QLineF(transform_.toWorld(pressPx_), transform_.toWorld(currentPx_)));
    }
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
        requestFrame();
    }
    updateCursor();
    requestFrame();
}

void ViewportCore::paintField(QPainter& painter) const {
    if (scene_.field) pl::ui::paintField(painter, transform_, *scene_.field);
}

void ViewportCore::paintParticles(QPainter& painter) const {
    paintSceneParticles(painter, transform_, scene_, widget_->rect());
}

void ViewportCore::paintOverlay(QPainter& painter) const {
    std::optional<std::size_t> active = hovered_;
    if (gesture_ == Gesture::DragObstacle) active = grabbed_;
    paintSceneBodies(painter, transform_, scene_, active);
    paintSteeredTarget(painter);
    paintScenePiston(painter, transform_, scene_, gesture_ == Gesture::DragPiston);
    if (gesture_ == Gesture::Rectangle || gesture_ == Gesture::Pour) { // the write-up's spawn preview
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
    if (gesture_ == Gesture::Line)
        paintProfileLine(painter, QLineF(pressPx_, currentPx_));
    else if (profileLine_)
        paintProfileLine(painter, QLineF(transform_.toWidget(profileLine_->x1(), profileLine_->y1()),
                                         transform_.toWidget(profileLine_->x2(), profileLine_->y2())));
    paintLegends(painter, transform_, scene_);
    if (probe_) {
        const QStringList text = probeText();
        if (!text.isEmpty())
            paintProbe(painter, transform_.toWidget(probe_->x(), probe_->y()), text.front(), text.mid(1),
                       transform_.size());
    }
    if (const Model* model = controller_->model(); model && model->failure())
        paintNotice(painter, widget_->rect(),
                    tr("The simulation stopped: its state is no longer physical. Press Reset (Ctrl+R) to "
                       "start again; its message said which change to take back."));
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

} // namespace pl::ui
