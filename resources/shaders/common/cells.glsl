// The uniform grid of the counting-sort cell list (core/gl/GpuCellGrid): cell side ≥ the interaction
// range, so a particle's partners lie in its own and the 8 surrounding cells.
uniform vec2 cellOrigin;      // lower-left corner of the grid [L]
uniform float cellInverseSide; // 1 / cell side [1/L]
uniform ivec2 cellDims;       // cells along x and y

ivec2 cellCoord(vec2 p) {
    // Clamped: a particle that left the box (a blow-up being reported) still has a cell.
    vec2 c = clamp((p - cellOrigin) * cellInverseSide, vec2(0.0), vec2(cellDims - 1));
    return ivec2(c);
}

uint cellIndex(ivec2 c) {
    return uint(c.y * cellDims.x + c.x);
}
