// Collision response of Position-Based Fluids: positions projected out of the walls and obstacles (the
// paper's "collision detection and response" inside the solver loop), and the velocity rule that lets a
// dragged obstacle push the fluid (as in Müller's FLIP demo: in contact, a particle cannot move into the
// obstacle faster than the obstacle moves).
#pragma once

#include "common/Obstacle.h"
#include "common/Philox.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pl::fluid {

struct Box {
    double left = 0, bottom = 0, right = 1, top = 1; // where centres may be: the walls moved in by a radius
};

// Projects (x, y) out of obstacle o grown by margin. Returns true and the outward normal when it was inside.
inline bool projectOutOfObstacle(const Obstacle& o, double margin, double& x, double& y, double& nx,
                                 double& ny) {
    const double dx = x - o.x, dy = y - o.y;
    if (o.shape == Obstacle::Shape::Disc) {
        const double reach = o.radius + margin;
        const double d2 = dx * dx + dy * dy;
        if (d2 >= reach * reach) return false;
        const double d = std::sqrt(d2);
        nx = d > 0 ? dx / d : 0.0; // a particle exactly at the centre leaves upwards
        ny = d > 0 ? dy / d : 1.0;
        x = o.x + reach * nx;
        y = o.y + reach * ny;
        return true;
    }
    const double hx = o.halfWidth + margin, hy = o.halfHeight + margin;
    const double px = hx - std::abs(dx), py = hy - std::abs(dy); // penetration depths
    if (px <= 0 || py <= 0) return false;
    nx = ny = 0;
    if (px < py) {
        nx = dx >= 0 ? 1.0 : -1.0;
        x = o.x + nx * hx;
    } else {
        ny = dy >= 0 ? 1.0 : -1.0;
        y = o.y + ny * hy;
    }
    return true;
}

// A clamped coordinate is moved off the wall by a tiny random amount (as Taichi's PBF does with ε·rand):
// otherwise particles pushed into a corner land on one point, where no kernel gradient can part them.
// Drawn from Philox keyed by (step, particle), so runs repeat for any thread count.
struct WallJitter {
    std::uint64_t seed = 0, step = 0;
    double amount = 0; // [L]
    double draw(std::uint32_t particle, int word) const {
        if (amount == 0) return 0.0;
        return amount * unitOpen32(randomWords(seed, RngPurpose::WallJitter, particle, step)[word]);
    }
};

inline void clampToBox(const Box& box, const WallJitter& jitter, std::uint32_t particle, double& x,
                       double& y) {
    if (x < box.left) x = box.left + jitter.draw(particle, 0);
    if (x > box.right) x = box.right - jitter.draw(particle, 1);
    if (y < box.bottom) y = box.bottom + jitter.draw(particle, 2);
    if (y > box.top) y = box.top - jitter.draw(particle, 3);
}

// Walls, then every obstacle: the position a particle is allowed to take.
inline void confine(const Box& box, const std::vector<Obstacle>& obstacles, double margin,
                    const WallJitter& jitter, std::uint32_t particle, double& x, double& y) {
    clampToBox(box, jitter, particle, x, y);
    if (obstacles.empty()) return;
    double nx, ny;
    for (const Obstacle& o : obstacles) projectOutOfObstacle(o, margin, x, y, nx, ny);
    clampToBox(box, jitter, particle, x, y); // an obstacle against a wall must not push through it
}

// Velocity after the step of a particle at (x, y): relative to any obstacle it touches, the component into
// the obstacle is removed, so the fluid takes up the obstacle's motion instead of being left behind.
inline void obstacleVelocity(const std::vector<Obstacle>& obstacles, double margin, double x, double y,
                             double& vx, double& vy) {
    constexpr double kContact = 1e-6; // relative to the radius: "on the surface" after projection
    for (const Obstacle& o : obstacles) {
        double px = x, py = y, nx, ny;
        if (!projectOutOfObstacle(o, margin * (1 + kContact) + kContact, px, py, nx, ny)) continue;
        const double normal = (vx - o.vx) * nx + (vy - o.vy) * ny;
        if (normal < 0) {
            vx -= normal * nx;
            vy -= normal * ny;
        }
    }
}

// Akinci et al. 2013's splines of the surface forces, in q = r/h and scaled to 1 at their peaks. Cohesion,
// eq. 2 (32/(π h⁹) there): 64 (1 − q)³ q³ for ½ < q ≤ 1 and 2 · 64 (1 − q)³ q³ − 1 for 0 < q ≤ ½, which
// attracts beyond q ≈ 0.27 and repels closer, so an evenly surrounded particle feels no net pull.
inline double cohesionSpline(double q) {
    if (!(q > 0) || q >= 1) return 0.0;
    const double product = (1 - q) * q;
    const double spline = 64 * product * product * product;
    return q > 0.5 ? spline : 2 * spline - 1;
}

// Adhesion, eq. 7 (0.007/h^3.25 there): (−16 q² + 24 q − 8)^¼ for ½ < q ≤ 1, 1 at q = ¾.
inline double adhesionSpline(double q) {
    if (!(q > 0.5) || q >= 1) return 0.0;
    return std::sqrt(std::sqrt(-16 * q * q + 24 * q - 8));
}

// The walls' and obstacles' pull on a particle at (x, y): β A(d/h) towards the nearest point of each wall
// of the box [0, W] × [0, H] and of each obstacle, d its distance from it (eq. 6 with the boundary's
// particles merged into its surface).
struct Adhesion {
    double width, height, h, strength;

    void add(const std::vector<Obstacle>& obstacles, double x, double y, double& ax, double& ay) const {
        const double inverseH = 1.0 / h;
        ax += strength * (adhesionSpline((width - x) * inverseH) - adhesionSpline(x * inverseH));
        ay += strength * (adhesionSpline((height - y) * inverseH) - adhesionSpline(y * inverseH));
        for (const Obstacle& o : obstacles) {
            double dx = x - o.x, dy = y - o.y, d;
            if (o.shape == Obstacle::Shape::Disc) {
                const double centre = std::sqrt(dx * dx + dy * dy);
                d = centre - o.radius;
                if (!(centre > 0)) continue;
                dx /= centre;
                dy /= centre;
            } else { // the nearest point of the box's outline
                const double outX = std::max(std::abs(dx) - o.halfWidth, 0.0),
                             outY = std::max(std::abs(dy) - o.halfHeight, 0.0);
                d = std::sqrt(outX * outX + outY * outY);
                if (!(d > 0)) continue;
                dx = std::copysign(outX, dx) / d;
                dy = std::copysign(outY, dy) / d;
            }
            const double pull = strength * adhesionSpline(d * inverseH);
            ax -= pull * dx;
            ay -= pull * dy;
        }
    }
};

} // namespace pl::fluid
