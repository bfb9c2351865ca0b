#version 430
// The ocean grid: rings around the camera out to the horizon, displaced by the cascades
// (choppy x, y and height, mip level from the vertex spacing: waves shorter than the grid
// average out instead of aliasing), plus the Kelvin wake and the local solver's field.
// Defines: TILES (number of cascades).
layout(location = 0) in vec3 in_grid;  // x, y offset from the grid centre (m), vertex spacing (m)

uniform mat4 u_view_projection;
uniform vec2 u_centre;                 // m, E frame
uniform sampler2DArray u_cascades;     // per tile: displacement x, y, height, Jacobian (m, m, m, -)
uniform float u_tile_size[TILES];      // m
uniform float u_tile_spacing[TILES];   // m, size / N

#include "surface.glsl"

out vec2 v_xy;          // undisplaced position (m, E frame): where the fragment shader samples
out vec3 v_position;    // displaced position (m)
out float v_spacing;

void main() {
    vec2 xy = u_centre + in_grid.xy;
    vec3 displaced = vec3(xy, 0.0);
    for (int i = 0; i < TILES; ++i) {
        float lod = max(log2(in_grid.z / u_tile_spacing[i]), 0.0);
        displaced += textureLod(u_cascades, vec3(xy / u_tile_size[i], float(i)), lod).xyz;
    }
    displaced.z += local_height(xy);
    v_xy = xy;
    v_position = displaced;
    v_spacing = in_grid.z;
    gl_Position = u_view_projection * vec4(displaced, 1.0);
}
