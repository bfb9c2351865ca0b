#version 430
// Scroll the field by whole cells: target(i, j) = source(i + di, j + dj), zero (at rest) where
// that lies outside the grid. Defines: SIZE, GROUP.
layout(local_size_x = GROUP, local_size_y = GROUP) in;

layout(std430, binding = 0) readonly buffer Source { vec2 source[]; };
layout(std430, binding = 1) writeonly buffer Target { vec2 target[]; };

uniform ivec2 shift;

void main() {
    ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    ivec2 from = cell + shift;
    bool inside = all(greaterThanEqual(from, ivec2(0))) && all(lessThan(from, ivec2(SIZE)));
    target[cell.y * SIZE + cell.x] = inside ? source[from.y * SIZE + from.x] : vec2(0.0);
}
