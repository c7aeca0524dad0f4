// Walls, piston and obstacles acting on one disk centre after a drift (gather form: touches only that
// disk). The common case, a disk inside the box away from obstacles, costs four comparisons.
#pragma once

#include "GasKernels.h"
#include "common/Obstacle.h"

#include <cstdint>
#include <vector>

namespace pl::gas {

struct Boundaries {
    double left, right, bottom, top; // the box, with the piston as its right wall [L]
    double pistonVelocity;           // [L/T]
    double h;                        // the drift's signed time step [T]
    double timeSign;                 // a crossing in backward time undoes a forward one
    bool thermal, thermalRight;      // thermal walls (the piston never is one)
    double wallKT;
    double mass[2], radius[2];
    std::uint64_t seed, drawIndex;
    const std::vector<Obstacle>* obstacles;

    // Reflects the disk off whatever it crossed, adds the normal momentum given to the box walls to
    // impulse, and returns false when it is still outside the box after one mirror (a blow-up).
    inline bool apply(double& x, double& y, double& vx, double& vy, int species, std::uint32_t id,
                      double& impulse) const {
        const bool inside = x > left && x < right && y > bottom && y < top;
        if (inside && obstacles->empty()) return true;
        bool ok = true;
        if (!inside) ok = reflectOffWalls(x, y, vx, vy, species, id, impulse);
        if (!obstacles->empty()) collideWithObstacles(x, y, vx, vy, species);
        return ok;
    }

    bool reflectOffWalls(double& x, double& y, double& vx, double& vy, int species, std::uint32_t id,
                         double& impulse) const;
    void collideWithObstacles(double& x, double& y, double& vx, double& vy, int species) const;
};

} // namespace pl::gas
