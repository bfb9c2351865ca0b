#version 430
// Orthographic view from above of the hull in grid units (marinesim/solver/footprint.py): the body
// vertices through the placement's map in double precision, snapped to the rasteriser's sub-pixel
// grid (round half to even, as NumPy's rint), so the GPU and the NumPy render see the same corners.
// Defines: SUBPIXEL (sub-pixel steps per cell).
in dvec3 in_body;        // body-frame vertex, m

uniform dmat4 to_grid;   // body -> (x, y in grid units * SUBPIXEL, world z in m, 1)
uniform float weight_in; // +1, or -1 for a pose whose depth is subtracted
uniform float size;      // cells across the grid (a power of two: the mapping below is exact)

noperspective out float z;
flat out float weight;

void main() {
    dvec4 grid = to_grid * dvec4(in_body, 1.0LF);
    vec2 cell = vec2(roundEven(grid.xy)) / float(SUBPIXEL);
    gl_Position = vec4(cell * (2.0 / size) - 1.0, 0.0, 1.0);
    z = float(grid.z);
    weight = weight_in;
}
