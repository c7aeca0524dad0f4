// The model bases' checks and the heat / cool rescale, shared by every model (see ModelBase.h).
#include "ModelBase.h"

#include <cmath>
#include <stdexcept>

namespace pl::model_base {

void requireTimeDirection(int direction, bool reversible) {
    if (direction != 1 && direction != -1)
        throw std::invalid_argument("the direction of time is +1 or -1, not " + std::to_string(direction));
    if (direction < 0 && !reversible)
        throw std::logic_error("this scene cannot run backwards: its dynamics are not reversible");
}

void requireObstacleIndex(std::size_t index, std::size_t count) {
    if (index >= count) throw std::out_of_range("no obstacle " + std::to_string(index));
}

void requireCentresInside(const Area& area, const std::vector<Obstacle>& obstacles) {
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
        const Obstacle& o = obstacles[i];
        if (!(o.x >= area.left && o.x <= area.right && o.y >= area.bottom && o.y <= area.top))
            throw PresetError("obstacles[" + std::to_string(i) + "]",
                              "obstacles[" + std::to_string(i) + "] has its centre outside the box");
    }
}

// Probes per side of the room check: a free gap narrower than 1/64 of the box can be missed, and such
// a gap is no room for a scene's particles either.
constexpr int kRoomProbes = 64;

void requireRoomOutside(const Area& area, const std::vector<Obstacle>& obstacles) {
    if (obstacles.empty()) return;
    const double width = area.right - area.left, height = area.top - area.bottom;
    const auto free = [&](double x, double y) {
        for (const Obstacle& o : obstacles)
            if (o.contains(x, y, 0.0)) return false;
        return true;
    };
    for (int i = 0; i < kRoomProbes; ++i)
        for (int j = 0; j < kRoomProbes; ++j)
            if (free(area.left + (i + 0.5) / kRoomProbes * width,
                     area.bottom + (j + 0.5) / kRoomProbes * height))
                return;
    throw PresetError("obstacles",
                      "the obstacles cover the whole box: no room is left for the particles; make "
                      "them smaller or fewer");
}

void refuseObstacles(const std::string& kind, const std::vector<Obstacle>& obstacles) {
    if (!obstacles.empty()) throw PresetError("obstacles", "the " + kind + " scene has no obstacles");
}

void refuseMissingPiston(const std::string& why) {
    throw std::logic_error(why);
}

void checkKineticFactor(double factor) {
    if (!(factor > 0) || !std::isfinite(factor))
        throw std::invalid_argument("kinetic energy factor must be positive and finite");
}

void scaleVelocities(std::vector<double>& vx, std::vector<double>& vy, double factor) {
    checkKineticFactor(factor);
    const double s = std::sqrt(factor);
    for (std::size_t i = 0; i < vx.size(); ++i) {
        vx[i] *= s;
        vy[i] *= s;
    }
}

} // namespace pl::model_base
