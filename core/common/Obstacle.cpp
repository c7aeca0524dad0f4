// Geometry of obstacles.
#include "Obstacle.h"

#include <cmath>
#include <numbers>

namespace pl {

bool Obstacle::contains(double px, double py, double margin) const {
    const double dx = px - x, dy = py - y;
    if (shape == Shape::Disc) {
        const double r = radius + margin;
        return dx * dx + dy * dy < r * r;
    }
    return std::abs(dx) < halfWidth + margin && std::abs(dy) < halfHeight + margin;
}

double Obstacle::grownArea(double margin) const {
    if (shape == Shape::Disc) return std::numbers::pi * (radius + margin) * (radius + margin);
    // Boxes grow by margin on every side (square corners), matching contains().
    return 4 * (halfWidth + margin) * (halfHeight + margin);
}

std::string shapeName(Obstacle::Shape shape) {
    return shape == Obstacle::Shape::Disc ? "disc" : "box";
}

} // namespace pl
