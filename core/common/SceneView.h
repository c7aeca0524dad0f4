// What a viewport draws of a scene: a world rectangle, particles with a colour value, obstacles, a
// piston and a legend. Models fill it; views only draw it, so every scene shares one viewport.
#pragma once

#include "Obstacle.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace pl {

enum class ColourMap {
    Thermal,  // the gas write-up's 10-stop palette, value in [0, 1]
    BlueRed,  // the fluid write-up's blue → red, value in [0, 1]
    Category, // value is a small integer: species or beam of origin
};

// Particles that stay in GPU buffers (OpenGL names) of a context the viewport shares: drawn from there,
// without a copy through the CPU. Layouts are those of the compute shaders (std430).
struct GpuParticles {
    unsigned positions = 0;        // vec2 per particle [L]
    unsigned velocities = 0;       // vec2 per particle [L/T]
    unsigned accelerations = 0;    // vec2 per particle, 0 when none: true velocity = v + pendingKick · a
    unsigned tags = 0;             // uint per particle with the species in bit 0; 0 when one species
    float pendingKick = 0.0f;      // [T]
    std::array<float, 2> radius{}; // per species [L]
    float inverseColourMax = 1.0f; // colour value = |v| · this
    std::size_t count = 0;
};

// A sampled field drawn under the particles as a colour map over the world rectangle: cell (i, j) of
// nx × ny, row-major (j·nx + i), value in [0, 1] on the colour scale, NaN where nothing was sampled
// (drawn as background).
struct SceneFieldImage {
    int nx = 0, ny = 0;
    double left = 0, bottom = 0, right = 1, top = 1; // [L]
    std::vector<float> value;
    ColourMap colours = ColourMap::Thermal;
    std::string label;               // legend title with unit, e.g. "Mach number"
    double minimum = 0, maximum = 1; // physical values at the ends of the colour scale
    long long sampledSteps = 0;      // steps the values average over
    long long window = 0;            // a moving window's length in steps; 0: since sampling began
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
    std::string colourLabel; // legend title, e.g. "speed"
    double colourMax = 1.0;  // the physical value at the top of the colour scale
    // The rms colour value the top was chosen for (the gas: 1/2.8, its top at 2.8 × the initial rms
    // speed): a viewport may raise the top as the rms grows past it (a heated gas). 0: a fixed scale.
    double colourRms = 0.0;
    std::vector<std::string> categories; // legend entries for ColourMap::Category

    std::vector<Obstacle> obstacles;
    std::optional<double> pistonX;   // a vertical wall from bottom to top at this x
    std::string hint;                // faint instruction across the view (e.g. while a tank is empty)
    bool dragPours = false;          // with the Drag tool, dragging empty space spawns (the fluid write-up)
    std::optional<GpuParticles> gpu; // set instead of x, y, radius, value by sceneViewSharingGpu()
    std::optional<SceneFieldImage> field; // a colour map under the particles (the wind tunnel's fields)
    bool drawParticles = true;            // false while a field hides them

    // The particles every array describes: a kind that fills one array short (a forgotten radius) draws
    // fewer particles instead of reading past its end; tst_model_contract requires equal lengths.
    std::size_t size() const { return std::min({x.size(), y.size(), radius.size(), value.size()}); }
};

} // namespace pl
