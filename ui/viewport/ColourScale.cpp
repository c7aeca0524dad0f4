// ColourScale: the rms of the colour values (a strided sample of at most 4096 particles) against the
// scene's colourRms, smoothed per frame so a step change of temperature re-scales in about a third of a
// second.
#include "ColourScale.h"

#include <algorithm>
#include <cmath>

namespace pl::ui {

namespace {
constexpr std::size_t kSampledParticles = 4096;
constexpr double kSmoothing = 0.2;         // share of the way to the target each frame
constexpr double kRescaleThreshold = 0.02; // growth below this keeps the model's top exactly
} // namespace

void ColourScale::apply(SceneView& scene) {
    if (!(scene.colourRms > 0) || scene.value.empty()) return;
    const std::size_t stride = std::max<std::size_t>(1, scene.value.size() / kSampledParticles);
    double sum = 0.0;
    std::size_t counted = 0;
    for (std::size_t i = 0; i < scene.value.size(); i += stride, ++counted)
        sum += double(scene.value[i]) * scene.value[i];
    const double rms = std::sqrt(sum / static_cast<double>(counted));
    if (!std::isfinite(rms)) return;
    factor_ += kSmoothing * (std::max(1.0, rms / scene.colourRms) - factor_);
    if (!automatic_ || factor_ < 1.0 + kRescaleThreshold) return;
    const float inverse = static_cast<float>(1.0 / factor_);
    for (float& v : scene.value) v *= inverse;
    scene.colourMax *= factor_;
}

} // namespace pl::ui
