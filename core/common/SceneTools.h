// What the mouse tools may do to a scene between steps: drag, add and remove obstacles, move a piston,
// spawn particles, heat or cool. A model offers it through Model::tools(); scenes without interaction
// (a 0D DSMC cell) return nullptr.
#pragma once

#include "Obstacle.h"

#include <cstddef>
#include <string>
#include <vector>

namespace pl {

class SceneTools {
public:
    virtual ~SceneTools() = default;

    virtual const std::vector<Obstacle>& obstacles() const = 0;
    virtual void addObstacle(const Obstacle& obstacle) = 0;
    virtual void removeObstacle(std::size_t index) = 0;
    // Moves an obstacle; velocity [L/T] is what it imparts on the particles it pushes.
    virtual void moveObstacle(std::size_t index, double x, double y, double vx, double vy) = 0;

    virtual bool hasPiston() const = 0;
    virtual void movePiston(double x, double velocity) = 0;

    // Fills a rectangle (or a point when x0 == x1, y0 == y1) with particles at the scene's current
    // temperature. Returns a sentence for the status bar: how many were added and why others were refused.
    virtual std::string spawnInRectangle(double x0, double y0, double x1, double y1) = 0;
    // Multiplies the kinetic energy of every particle by factor (> 0): the heat / cool control.
    virtual void scaleKineticEnergy(double factor) = 0;
};

} // namespace pl
