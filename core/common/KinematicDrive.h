// Kinematic bodies driven by the user's tools: each step the model moves a dragged obstacle toward its
// target by at most v_max |h|, so the particles always meet a wall of finite, known velocity, however
// far the mouse jumped between two frames (the frame-rate blow-up of phetsims/states-of-matter#158).
#pragma once

#include "Obstacle.h"

#include <cstddef>
#include <vector>

namespace pl {

// One step of a body toward a target: Δ = (target − p) limited to |Δ| ≤ v_max |h|. Its velocity over
// the step is Δ / h (signed h: in reversed time the same displacement means the opposite velocity).
struct BoundedMove {
    double dx = 0.0, dy = 0.0;
    bool arrived = false; // the body reached the target in this move
};
BoundedMove boundedMove(double x, double y, double targetX, double targetY, double maxSpeed, double h);

// The targets of the obstacles being dragged or coasting to where they were let go.
class ObstacleDrive {
public:
    // Held: the obstacle heads for (x, y) until released.
    void drag(std::size_t index, double x, double y);
    // Let go: it goes on to its last target and stops there.
    void release(std::size_t index);
    // Ends the obstacle's drive where it is (it was placed by hand).
    void stop(std::size_t index);
    // Forgets a removed obstacle; later indices shift down as in the obstacle list.
    void erase(std::size_t index);
    void clear() { targets_.clear(); }
    bool moving() const { return !targets_.empty(); }

    // Moves every driven obstacle one step of length h [T] at up to maxSpeed [L/T] and sets its velocity
    // (what it imparts on reflection) to the step's displacement / h; a body that arrived is at rest.
    // Returns true when a released body arrived this step (the energy it gave is now part of the system).
    bool advance(std::vector<Obstacle>& obstacles, double maxSpeed, double h);

private:
    struct Target {
        std::size_t index;
        double x, y;
        bool held;
        bool settled = false; // released and at rest on its target: the drive is over
    };
    Target* find(std::size_t index);
    std::vector<Target> targets_;
};

// The piston as a driven body on its axis: a target (a mouse drag) or a constant drive (compress or
// expand at the scene's piston speed) between lower and upper ends.
class PistonDrive {
public:
    void dragTo(double x) { mode_ = Mode::Target, target_ = x; }
    void drive(int direction) { mode_ = direction == 0 ? Mode::Idle : Mode::Drive, direction_ = direction; }
    void stop() { mode_ = Mode::Idle; }
    int direction() const { return mode_ == Mode::Drive ? direction_ : 0; }
    bool moving() const { return mode_ != Mode::Idle; }

    // Moves x one step of length h [T] within [lower, upper]: toward the target at up to dragSpeed, or
    // at driveSpeed in the drive's direction. Returns the piston's velocity over the step [L/T]; the
    // drive ends (velocity 0 from the next step) at the target or at an end of its travel.
    double advance(double& x, double lower, double upper, double dragSpeed, double driveSpeed, double h);

private:
    enum class Mode { Idle, Target, Drive };
    Mode mode_ = Mode::Idle;
    double target_ = 0.0;
    int direction_ = 0;
};

} // namespace pl
