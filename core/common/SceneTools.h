// What the mouse tools may do to a scene: drag, add and remove obstacles, drive a piston, spawn
// particles, heat or cool. A model offers it through Model::tools(); scenes without interaction (a 0D
// DSMC cell) return nullptr. A dragged body is kinematic: the tool only sets where it should go, and the
// model moves it there every step at no more than toolSpeed(), so what the particles feel does not
// depend on the frame rate or the machine's speed.
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
    // While held, the obstacle heads for (x, y) [L] at up to toolSpeed(); released, it goes on to its
    // last target and stops there.
    virtual void dragObstacle(std::size_t index, double x, double y) = 0;
    virtual void releaseObstacle(std::size_t index) = 0;
    // Puts an obstacle at (x, y) at rest at once: an edit while time stands still.
    virtual void placeObstacle(std::size_t index, double x, double y) = 0;

    virtual bool hasPiston() const { return false; }
    virtual double pistonX() const { return 0.0; }
    // The piston heads for x [L] at up to toolSpeed() and stops there (a mouse drag).
    virtual void dragPiston(double /*x*/) {}
    // Drives the piston at the scene's piston speed: −1 compresses (leftwards), +1 expands, 0 stops. It
    // stops by itself at either end of its travel.
    virtual void drivePiston(int /*direction*/) {}
    virtual int pistonDirection() const { return 0; }
    // Puts the piston at x at rest at once (time stands still).
    virtual void placePiston(double /*x*/) {}

    // The fastest a dragged body moves [L/T] (the scene's tool_speed, or tool_speed_factor × its scale, in
    // model units).
    virtual double toolSpeed() const = 0;
    // Whether a body is still on its way to a target (the view keeps drawing it as held).
    virtual bool bodiesMoving() const = 0;

    // Fills a rectangle (or a point when x0 == x1, y0 == y1) with particles at the scene's current
    // temperature. Returns a sentence for the status bar: how many were added and why others were refused.
    virtual std::string spawnInRectangle(double x0, double y0, double x1, double y1) = 0;
    // Multiplies the kinetic energy of every particle by factor (> 0): the heat / cool control.
    virtual void scaleKineticEnergy(double factor) = 0;
};

} // namespace pl
