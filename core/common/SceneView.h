// What a viewport draws of a scene: a world rectangle, particles with a colour value, obstacles, a
// piston and a legend. Models fill it; views only draw it, so every scene shares one viewport.
#pragma once

#include "Obstacle.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace pl {

enum class ColourMap {
    Thermal,  // the gas seed's 10-stop palette, value in [0, 1]
    BlueRed,  // the fluid seed's blue → red, value in [0, 1]
    Category, // value is a small integer: species or beam of origin
};

struct SceneView {
    // World rectangle shown [L]; the box outline when drawBox.
    double left = -1, bottom = -1, right = 1, top = 1;
    bool drawBox = true;
    std::string xLabel, yLabel; // axis names when the view is not physical space (e.g. "v_x [m/s]")
    std::array<float, 3> background{0.031f, 0.039f, 0.078f};

    // Particles: position [L], radius [L] (0: a point of a few pixels) and colour value.
    std::vector<float> x, y, radius, value;
    ColourMap colours = ColourMap::Thermal;
    std::string colourLabel;             // legend title, e.g. "speed"
    double colourMax = 1.0;              // the physical value at the top of the colour scale
    std::vector<std::string> categories; // legend entries for ColourMap::Category

    std::vector<Obstacle> obstacles;
    std::optional<double> pistonX; // a vertical wall from bottom to top at this x
    std::string hint;              // faint instruction across the view (e.g. while a tank is empty)

    std::size_t size() const { return x.size(); }
};

} // namespace pl
