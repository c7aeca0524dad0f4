// The gas as the viewport and the mouse tools see it: disks coloured by speed, obstacles, the piston;
// spawning at the gas's current temperature (heat / cool is SceneModelBase's).
#include "GasModel.h"

#include <cmath>
#include <stdexcept>

namespace pl {

namespace {
// The write-up's V_COLOR_MAX: the top of the palette at 2.8 × the initial rms speed, so the Maxwell–Boltzmann
// tail still shows as the warmest colours.
constexpr double kColourScaleOverRms = 2.8;
} // namespace

SceneView GasModel::sceneView() const {
    pullState();
    SceneView view = sceneFrame();
    const std::size_t n = state_.size();
    view.x.resize(n);
    view.y.resize(n);
    view.radius.resize(n);
    view.value.resize(n);
    const float radius[2] = {static_cast<float>(0.5 * params_.a.diameter),
                             static_cast<float>(0.5 * params_.b.diameter)};
    const double inverseMax = 1.0 / view.colourMax;
    for (std::size_t i = 0; i < n; ++i) {
        view.x[i] = static_cast<float>(state_.x[i]);
        view.y[i] = static_cast<float>(state_.y[i]);
        view.radius[i] = radius[state_.species[i]];
        view.value[i] = static_cast<float>(std::hypot(state_.vx[i], state_.vy[i]) * inverseMax);
    }
    return view;
}

SceneView GasModel::sceneFrame() const {
    SceneView view;
    view.left = params_.left();
    view.right = 0.5 * params_.boxWidth; // the whole box, also when the piston closes part of it
    view.bottom = params_.bottom();
    view.top = params_.top();
    view.colourMax = kColourScaleOverRms * initialRmsSpeed();
    view.colourRms = 1.0 / kColourScaleOverRms;
    view.colours = ColourMap::Thermal;
    view.colourLabel = "speed";
    view.obstacles = obstacles_;
    if (params_.pistonEnabled) view.pistonX = pistonX_;
    return view;
}

std::string GasModel::spawnInRectangle(double x0, double y0, double x1, double y1) {
    // New disks join at the gas's current temperature (the initial one when the box is empty), so
    // spawning adds particles without heating or cooling what is there.
    pullState();
    double kinetic = 0;
    for (std::size_t i = 0; i < state_.size(); ++i)
        kinetic += 0.5 * params_.species(state_.species[i]).mass *
                   (state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i]);
    const double fallback = params_.initVelocity == GasInitVelocity::MaxwellBoltzmann
                                ? params_.initKT
                                : 0.5 * params_.a.mass * params_.initSpeed * params_.initSpeed;
    const double kT = state_.size() > 0 ? kinetic / static_cast<double>(state_.size()) : fallback;
    return spawnRectangle(x0, y0, x1, y1, 0, kT).message();
}

} // namespace pl
