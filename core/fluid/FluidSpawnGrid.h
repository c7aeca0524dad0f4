// The fluid's square spawn grid: where spawnLattice() puts particles, and how many a reset makes, from
// the parameters alone (the registry counts a preset's particles without building a model).
#pragma once

#include "FluidBoundaries.h"
#include "FluidParams.h"
#include "common/Obstacle.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace pl::fluid {

// Where particle centres may be: the walls moved in by a particle radius.
inline Box confinementBox(const FluidParams& p) {
    const double r = p.particleRadius;
    return {r, r, p.boxWidth - r, p.boxHeight - r};
}

// A grid of spacing d centred in the rectangle [x0, x1] × [y0, y1] (a point: one grid point).
struct SpawnGrid {
    long long columns = 1, rows = 1;
    double startX = 0, startY = 0, spacing = 1;

    static SpawnGrid centred(double x0, double y0, double x1, double y1, double d) {
        if (x1 < x0) std::swap(x0, x1);
        if (y1 < y0) std::swap(y0, y1);
        SpawnGrid g;
        g.spacing = d;
        g.columns = std::max<long long>(1, static_cast<long long>(std::floor((x1 - x0) / d + 1e-6)));
        g.rows = std::max<long long>(1, static_cast<long long>(std::floor((y1 - y0) / d + 1e-6)));
        g.startX = 0.5 * (x0 + x1) - 0.5 * d * static_cast<double>(g.columns - 1);
        g.startY = 0.5 * (y0 + y1) - 0.5 * d * static_cast<double>(g.rows - 1);
        return g;
    }
    double x(long long column) const { return startX + spacing * static_cast<double>(column); }
    double y(long long row) const { return startY + spacing * static_cast<double>(row); }
};

// Whether a grid point lies where no particle may be: confine() would move it (a point on the wall
// itself counts as inside).
inline bool outsideFluidDomain(const Box& box, const std::vector<Obstacle>& obstacles, double radius,
                               double spacing, double x, double y) {
    double cx = x, cy = y;
    confine(box, obstacles, radius, {}, 0, cx, cy);
    return std::hypot(cx - x, cy - y) > 1e-9 * spacing;
}

// The grid's indices whose coordinate start + spacing·k lies in [low, high] (a point on the edge counts),
// as [first, last); empty when none does.
inline std::pair<long long, long long> indicesWithin(double start, double spacing, long long count,
                                                     double low, double high) {
    const double slack = 1e-9 * spacing;
    const double first = std::ceil((low - slack - start) / spacing),
                 last = std::floor((high + slack - start) / spacing);
    const auto clamp = [count](double k) {
        return static_cast<long long>(std::clamp(k, 0.0, double(count)));
    };
    return {clamp(first), clamp(last + 1.0)};
}

// Particles a reset spawns into the initial fill: the grid points inside the domain, up to the cap. Only
// the points inside the box are walked, and the walk ends at the cap, so a fill far larger than the box
// is counted at once (the count picks the backend before the parameters are checked).
inline long long initialFillCount(const FluidParams& p, const std::vector<Obstacle>& obstacles) {
    if (!p.hasFill()) return 0;
    const SpawnGrid g = SpawnGrid::centred(p.fillX0, p.fillY0, p.fillX1, p.fillY1, p.spacing());
    const Box box = confinementBox(p);
    const long long cap = p.drain ? 2 * p.maxParticles : p.maxParticles;
    const auto [c0, c1] = indicesWithin(g.startX, g.spacing, g.columns, box.left, box.right);
    const auto [r0, r1] = indicesWithin(g.startY, g.spacing, g.rows, box.bottom, box.top);
    long long inside = 0;
    for (long long r = r0; r < r1 && inside < cap; ++r)
        for (long long c = c0; c < c1 && inside < cap; ++c)
            if (!outsideFluidDomain(box, obstacles, p.particleRadius, g.spacing, g.x(c), g.y(r))) ++inside;
    return inside;
}

} // namespace pl::fluid
