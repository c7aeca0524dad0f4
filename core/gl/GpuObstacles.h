// Obstacles in the std430 layout of resources/shaders/common/obstacles.glsl, uploaded to binding 15.
#pragma once

#include "GlProgram.h"
#include "common/Obstacle.h"

#include <cstdint>
#include <vector>

namespace pl::gl {

struct GpuObstacle {
    float centre[2], halfSize[2], velocity[2], radius;
    std::uint32_t shape; // 0 disc, 1 box
};

// Uploads the obstacles (when there are any) and binds the buffer where the shaders read them.
inline void uploadObstacles(Buffer& buffer, const std::vector<Obstacle>& obstacles) {
    if (obstacles.empty()) return;
    std::vector<GpuObstacle> list;
    list.reserve(obstacles.size());
    for (const auto& o : obstacles)
        list.push_back({{float(o.x), float(o.y)},
                        {float(o.halfWidth), float(o.halfHeight)},
                        {float(o.vx), float(o.vy)},
                        float(o.radius),
                        o.shape == Obstacle::Shape::Disc ? 0u : 1u});
    buffer.uploadVector(list);
    buffer.bind(15);
}

} // namespace pl::gl
