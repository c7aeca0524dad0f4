// Neighbour search on the sorted particles (needs common/cells.glsl): with cells of side ≥ range /
// cellReach, a particle's partners lie in the (2 reach + 1)² cells around its own, and each row of
// them is one contiguous range [first, last) of the cell-ordered arrays. Reach 2 with half-width cells
// scans 25/4 = 6.25 range² instead of 9 range² for reach 1: fewer candidates read.
layout(std430, binding = 8) readonly buffer CellStarts { uint cellStarts[]; };
uniform int cellReach;

uvec2 cellRowRange(ivec2 c, int dy) {
    const int y = c.y + dy;
    if (y < 0 || y >= cellDims.y) return uvec2(0u);
    const uint first = cellIndex(ivec2(max(c.x - cellReach, 0), y));
    const uint last = cellIndex(ivec2(min(c.x + cellReach, cellDims.x - 1), y));
    return uvec2(cellStarts[first], cellStarts[last + 1u]);
}
