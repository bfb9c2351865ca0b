#version 430
// Orthographic view from above of the hull in grid units (marinesim/solver/footprint.py):
// corners arrive in cells, already snapped to the rasteriser's sub-pixel grid.
in vec2 in_cell;
in float in_z;       // world z of the corner, m
in float in_weight;  // +1, or -1 for a pose whose depth is subtracted

uniform float size;  // cells across the grid (a power of two: the mapping below is exact)

noperspective out float z;
flat out float weight;

void main() {
    gl_Position = vec4(in_cell * (2.0 / size) - 1.0, 0.0, 1.0);
    z = in_z;
    weight = in_weight;
}
