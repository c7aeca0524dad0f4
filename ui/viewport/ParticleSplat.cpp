// ParticleSplat: 2 × 2 pixel blocks in a premultiplied ARGB image, colours from a 256-entry table.
#include "ParticleSplat.h"

#include "Palette.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pl::ui {

bool splatsParticles(const SceneView& scene) {
    return scene.drawParticles && !scene.gpu && scene.size() >= kSplatParticles && scene.radius[0] == 0.0f;
}

QImage splatParticles(const SceneView& scene, const ViewTransform& transform, QRect area) {
    QImage image(area.size(), QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    if (area.isEmpty()) return image;
    const bool categorical = isCategorical(scene.colours);
    std::array<QRgb, 256> table{};
    if (!categorical)
        for (std::size_t k = 0; k < table.size(); ++k)
            table[k] = paletteColour(scene.colours, static_cast<double>(k) / 255.0).rgba();
    const int width = image.width(), height = image.height();
    const auto stride = static_cast<std::size_t>(image.bytesPerLine() / 4);
    auto* pixels = reinterpret_cast<QRgb*>(image.bits());
    for (std::size_t i = 0; i < scene.size(); ++i) {
        const QPointF p = transform.toWidget(scene.x[i], scene.y[i]);
        // The block's top-left pixel, so that its centre lies on the particle.
        const int px = static_cast<int>(std::floor(p.x() - 0.5)) - area.left();
        const int py = static_cast<int>(std::floor(p.y() - 0.5)) - area.top();
        if (px < -1 || py < -1 || px >= width || py >= height) continue;
        const QRgb colour = categorical ? paletteColour(scene.colours, scene.value[i]).rgba()
                                        : table[static_cast<std::size_t>(
                                              std::lround(std::clamp(scene.value[i], 0.0f, 1.0f) * 255.0f))];
        for (int y = std::max(py, 0); y <= std::min(py + 1, height - 1); ++y)
            for (int x = std::max(px, 0); x <= std::min(px + 1, width - 1); ++x)
                pixels[static_cast<std::size_t>(y) * stride + static_cast<std::size_t>(x)] = colour;
    }
    return image;
}

} // namespace pl::ui
