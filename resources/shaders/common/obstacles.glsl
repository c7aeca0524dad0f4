// The obstacles as the compute shaders see them (core/gl/GpuObstacles.h uploads them): discs and
// axis-aligned boxes, with the velocity a dragged one imparts.
struct GpuObstacle {
    vec2 centre;   // [L]
    vec2 halfSize; // box half extents [L]
    vec2 velocity; // [L/T]
    float radius;  // disc radius [L]
    uint shape;    // 0 disc, 1 box
};
layout(std430, binding = 15) readonly buffer Obstacles { GpuObstacle obstacles[]; };
uniform uint obstacleCount;
