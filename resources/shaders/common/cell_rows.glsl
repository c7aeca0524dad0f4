// Neighbour search on the sorted particles (needs common/cells.glsl): the 3×3 cells around cell c are
// three rows of three, and each row is one contiguous range [first, last) of the cell-ordered arrays.
layout(std430, binding = 8) readonly buffer CellStarts { uint cellStarts[]; };

uvec2 cellRowRange(ivec2 c, int dy) {
    const int y = c.y + dy;
    if (y < 0 || y >= cellDims.y) return uvec2(0u);
    const uint first = cellIndex(ivec2(max(c.x - 1, 0), y));
    const uint last = cellIndex(ivec2(min(c.x + 1, cellDims.x - 1), y));
    return uvec2(cellStarts[first], cellStarts[last + 1u]);
}
