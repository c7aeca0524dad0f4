// ScenePainter: the scene's layers in the order of the software viewport (SoftwareViewport.cpp).
#include "ScenePainter.h"

#include "FieldOverlay.h"
#include "Palette.h"
#include "ParticleSplat.h"
#include "ViewportAxes.h"
#include "i18n/Translations.h"

#include <QPainter>
#include <algorithm>

namespace pl::ui {

namespace {
constexpr double kPointRadiusPx = 2.0; // a particle of radius 0, as the GL viewport draws it
const QColor kWalls(200, 205, 220);
const QColor kObstacleFill(120, 128, 150);
const QColor kObstacleHover(170, 178, 200);
} // namespace

void paintNotice(QPainter& painter, QRect area, const QString& text) {
    painter.save();
    QFont font = painter.font();
    font.setBold(true);
    painter.setFont(font);
    const int margin = painter.fontMetrics().height();
    const int width = std::max(margin * 4, std::min(area.width() - 2 * margin, margin * 30));
    const QRect textBox = painter.fontMetrics().boundingRect(QRect(0, 0, width, area.height()),
                                                             Qt::AlignCenter | Qt::TextWordWrap, text);
    QRect box = textBox.adjusted(-margin / 2, -margin / 2, margin / 2, margin / 2);
    box.moveCenter(area.center()); // over the scene, clear of the legends along the top
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(230, 120, 60), 2));
    painter.setBrush(QColor(20, 22, 30, 230));
    painter.drawRoundedRect(box, 6, 6);
    painter.setPen(Qt::white);
    painter.drawText(box, Qt::AlignCenter | Qt::TextWordWrap, text);
    painter.restore();
}

void paintSceneParticles(QPainter& painter, const ViewTransform& transform, const SceneView& scene,
                         QRect clip) {
    if (!scene.drawParticles) return;
    if (splatsParticles(scene)) {
        const QRect area = transform.toWidget(scene.left, scene.bottom, scene.right, scene.top)
                               .normalized()
                               .toAlignedRect()
                               .intersected(clip);
        painter.drawImage(area.topLeft(), splatParticles(scene, transform, area));
        return;
    }
    painter.setPen(Qt::NoPen);
    const double scale = transform.scale();
    for (std::size_t i = 0; i < scene.size(); ++i) {
        painter.setBrush(paletteColour(scene.colours, scene.value[i]));
        const double r = scene.radius[i] > 0 ? std::max(1.0, scale * scene.radius[i]) : kPointRadiusPx;
        painter.drawEllipse(transform.toWidget(scene.x[i], scene.y[i]), r, r);
    }
}

void paintSceneBodies(QPainter& painter, const ViewTransform& transform, const SceneView& scene,
                      std::optional<std::size_t> active) {
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF box = transform.toWidget(scene.left, scene.bottom, scene.right, scene.top);
    painter.setBrush(Qt::NoBrush);
    if (scene.drawBox) {
        painter.setPen(QPen(kWalls, 1.5));
        painter.drawRect(box);
    }
    if (!scene.xLabel.empty() || !scene.yLabel.empty()) paintAxes(painter, transform, scene, box);
    if (!scene.hint.empty()) {
        // The write-up's faint instruction: large, bold, 20 % opaque, out of the way once there is fluid.
        QFont font = painter.font();
        font.setBold(true);
        font.setPointSizeF(font.pointSizeF() * 2.2);
        painter.save();
        painter.setFont(font);
        painter.setPen(QColor(255, 255, 255, 51));
        // A thin box (the shock tube) has no room for it: the view's whole area has.
        const QRectF room = box.height() < 4 * painter.fontMetrics().height()
                                ? QRectF(QPointF(0, 0), QSizeF(transform.size()))
                                : box;
        painter.drawText(room, Qt::AlignCenter | Qt::TextWordWrap, coreText(scene.hint));
        painter.restore();
    }
    painter.save();
    painter.setClipRect(box.normalized()); // a body on a symmetry plane shows its half inside the domain
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
        const Obstacle& o = scene.obstacles[i];
        const bool highlighted = active == i;
        painter.setPen(QPen(kWalls, highlighted ? 2.0 : 1.0));
        painter.setBrush(highlighted ? kObstacleHover : kObstacleFill);
        if (o.shape == Obstacle::Shape::Disc)
            painter.drawEllipse(transform.toWidget(o.x, o.y), transform.scale() * o.radius,
                                transform.scale() * o.radius);
        else
            painter.drawRect(transform.toWidget(o.x - o.halfWidth, o.y - o.halfHeight, o.x + o.halfWidth,
                                                o.y + o.halfHeight));
    }
    painter.restore();
}

void paintScenePiston(QPainter& painter, const ViewTransform& transform, const SceneView& scene,
                      bool active) {
    if (!scene.pistonX) return;
    const QRectF box = transform.toWidget(scene.left, scene.bottom, scene.right, scene.top);
    const double x = transform.toWidget(*scene.pistonX, 0).x();
    painter.setPen(QPen(kWalls, active ? 6 : 4));
    painter.drawLine(QPointF(x, box.top()), QPointF(x, box.bottom()));
}

void paintScene(QPainter& painter, const SceneView& scene, QRect area) {
    ViewTransform transform;
    transform.fit(scene, area.size(), kSceneMarginPx);
    painter.save();
    painter.translate(area.topLeft());
    painter.setClipRect(QRect(QPoint(0, 0), area.size()));
    const auto& bg = scene.background;
    painter.fillRect(QRect(QPoint(0, 0), area.size()), QColor::fromRgbF(bg[0], bg[1], bg[2]));
    if (scene.field) paintField(painter, transform, *scene.field);
    painter.setRenderHint(QPainter::Antialiasing);
    paintSceneParticles(painter, transform, scene, QRect(QPoint(0, 0), area.size()));
    paintSceneBodies(painter, transform, scene);
    paintScenePiston(painter, transform, scene);
    paintLegends(painter, transform, scene);
    painter.restore();
}

QImage renderScene(const SceneView& scene, QSize size) {
    QImage image(size, QImage::Format_RGB32);
    QPainter painter(&image);
    paintScene(painter, scene, QRect(QPoint(0, 0), size));
    return image;
}

} // namespace pl::ui
