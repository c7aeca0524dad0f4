// Static-or-dragged obstacles shared by the particle scenes: discs and axis-aligned boxes.
#pragma once

#include <string>

namespace pl {

struct Obstacle {
    enum class Shape { Disc, Box };
    Shape shape = Shape::Disc;
    double x = 0.0, y = 0.0;                  // centre [L]
    double radius = 0.1;                      // disc radius [L]
    double halfWidth = 0.1, halfHeight = 0.1; // box half extents [L]
    double vx = 0.0, vy = 0.0;                // velocity while dragged [L/T]; imparted on reflection

    // True when point (px, py) lies inside the obstacle grown by margin (a particle's radius).
    bool contains(double px, double py, double margin) const;
    // Area of the obstacle grown by margin [L²].
    double grownArea(double margin) const;
};

std::string shapeName(Obstacle::Shape shape);

} // namespace pl
