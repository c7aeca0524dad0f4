// Bounded-speed motion of dragged obstacles and of the piston (see KinematicDrive.h).
#include "KinematicDrive.h"

#include <algorithm>
#include <cmath>

namespace pl {

BoundedMove boundedMove(double x, double y, double targetX, double targetY, double maxSpeed, double h) {
    const double dx = targetX - x, dy = targetY - y;
    const double distance = std::hypot(dx, dy);
    const double reach = maxSpeed * std::abs(h);
    if (distance <= reach) return {dx, dy, true};
    const double s = reach / distance;
    return {s * dx, s * dy, false};
}

ObstacleDrive::Target* ObstacleDrive::find(std::size_t index) {
    for (Target& t : targets_)
        if (t.index == index) return &t;
    return nullptr;
}

void ObstacleDrive::drag(std::size_t index, double x, double y) {
    if (Target* t = find(index)) {
        *t = {index, x, y, true, false};
        return;
    }
    targets_.push_back({index, x, y, true, false});
}

void ObstacleDrive::release(std::size_t index) {
    if (Target* t = find(index)) t->held = false;
}

void ObstacleDrive::stop(std::size_t index) {
    std::erase_if(targets_, [index](const Target& t) { return t.index == index; });
}

void ObstacleDrive::erase(std::size_t index) {
    stop(index);
    for (Target& t : targets_)
        if (t.index > index) --t.index;
}

bool ObstacleDrive::advance(std::vector<Obstacle>& obstacles, double maxSpeed, double h) {
    bool settled = false;
    for (Target& t : targets_) {
        if (t.index >= obstacles.size()) continue;
        Obstacle& o = obstacles[t.index];
        const BoundedMove move = boundedMove(o.x, o.y, t.x, t.y, maxSpeed, h);
        // The velocity over this step: the disks it meets during the drift are reflected in its frame.
        o.vx = h != 0.0 ? move.dx / h : 0.0;
        o.vy = h != 0.0 ? move.dy / h : 0.0;
        if (move.arrived) {
            o.x = t.x; // exactly: the next step's displacement is 0 and the body rests
            o.y = t.y;
        } else {
            o.x += move.dx;
            o.y += move.dy;
        }
        t.settled = !t.held && move.dx == 0.0 && move.dy == 0.0;
        settled = settled || t.settled;
    }
    std::erase_if(targets_, [&](const Target& t) { return t.settled || t.index >= obstacles.size(); });
    return settled;
}

double PistonDrive::advance(double& x, double lower, double upper, double dragSpeed, double driveSpeed,
                            double h) {
    if (mode_ == Mode::Idle || h == 0.0) return 0.0;
    const double goal =
        mode_ == Mode::Target ? std::clamp(target_, lower, upper) : (direction_ < 0 ? lower : upper);
    const double speed = mode_ == Mode::Target ? dragSpeed : driveSpeed;
    const double reach = speed * std::abs(h);
    const double dx = std::clamp(goal - x, -reach, reach);
    if (std::abs(goal - x) <= reach) {
        x = goal; // arrived: at rest from the next step on
        mode_ = Mode::Idle;
    } else {
        x += dx;
    }
    return dx / h;
}

} // namespace pl
