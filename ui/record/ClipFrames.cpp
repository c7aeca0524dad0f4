// ClipFrames: scene on the left, plot on the right (drawn by QCustomPlot into the frame), captions last.
#include "ClipFrames.h"

#include "viewport/Palette.h"
#include "viewport/ScenePainter.h"

#include <QPainter>
#include <cmath>
#include <qcustomplot.h>

namespace pl::ui {

namespace {
constexpr double kCaptionHeightShare = 0.035; // caption font height, of the frame's height
constexpr double kTitleHeightShare = 0.06;
constexpr int kHintsPerScale = 24; // colours taken from a continuous colour scale

QString timeText(double time, const QString& unit) {
    // Four significant digits, as the readouts elsewhere; a fixed width would flicker less but
    // hides the scale of a DSMC run (10⁻⁵ s).
    return QStringLiteral("t = %1 %2").arg(QString::number(time, 'g', 4), unit).trimmed();
}

void paintCaption(QPainter& painter, const QRect& area, const QString& text, double heightShare, int flags,
                  QSize frame) {
    QFont font = painter.font();
    font.setPixelSize(std::max(10, static_cast<int>(std::lround(heightShare * frame.height()))));
    font.setBold(true);
    painter.setFont(font);
    const int pad = font.pixelSize() / 2;
    QRect bounds = painter.fontMetrics().boundingRect(area.adjusted(pad, pad, -pad, -pad), flags, text);
    bounds.adjust(-pad / 2, -pad / 4, pad / 2, pad / 4);
    painter.fillRect(bounds, QColor(0, 0, 0, 150));
    painter.setPen(Qt::white);
    painter.drawText(bounds, Qt::AlignCenter, text);
}
} // namespace

QImage plotPicture(QCustomPlot* plot, QSize frameSize) {
    const int plotWidth = static_cast<int>(std::lround(kClipPlotShare * frameSize.width()));
    QImage picture(plotWidth, frameSize.height(), QImage::Format_RGB32);
    picture.fill(Qt::white);
    {
        QCPPainter plotPainter(&picture); // ended before the picture is handed on
        plot->toPainter(&plotPainter, plotWidth, frameSize.height());
    }
    return picture;
}

QImage clipFrame(const ClipLook& look, const SceneView& scene, double time, long long index) {
    QImage image(look.size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QRect sceneArea(QPoint(0, 0), look.size);
    const QImage plotImage = !look.plotImage.isNull() ? look.plotImage
                             : look.plot              ? plotPicture(look.plot, look.size)
                                                      : QImage();
    if (!plotImage.isNull()) {
        sceneArea.setWidth(look.size.width() - plotImage.width());
        QPainter painter(&image);
        painter.drawImage(sceneArea.width(), 0, plotImage);
    }
    QPainter painter(&image);
    paintScene(painter, scene, sceneArea);
    if (look.captions) {
        painter.setRenderHint(QPainter::Antialiasing);
        paintCaption(painter, sceneArea, timeText(time, look.timeUnit), kCaptionHeightShare,
                     Qt::AlignLeft | Qt::AlignBottom, look.size);
        if (index < look.fps && !look.title.isEmpty())
            paintCaption(painter, sceneArea, look.title, kTitleHeightShare, Qt::AlignHCenter | Qt::AlignTop,
                         look.size);
    }
    return image;
}

std::vector<QRgb> colourScaleHints(const SceneView& scene) {
    std::vector<QRgb> hints;
    const auto add = [&hints](ColourMap map) {
        if (isCategorical(map)) {
            for (const QColor& c : paletteStops(map)) hints.push_back(c.rgb());
            return;
        }
        for (int i = 0; i < kHintsPerScale; ++i)
            hints.push_back(paletteColour(map, (i + 0.5) / kHintsPerScale).rgb());
    };
    if (scene.drawParticles) add(scene.colours);
    if (scene.field) add(scene.field->colours);
    return hints;
}

} // namespace pl::ui
