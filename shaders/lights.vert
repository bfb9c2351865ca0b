#version 430
// A navigation light as a point sprite: E-frame position (m), colour, glow diameter (px), strength 0..1.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_colour;
layout(location = 2) in float in_size;
layout(location = 3) in float in_strength;
uniform mat4 u_view_projection;
out vec3 v_colour;
out float v_strength;
out float v_size;

void main() {
    gl_Position = u_view_projection * vec4(in_position, 1.0);
    gl_PointSize = in_size;
    v_colour = in_colour;
    v_strength = in_strength;
    v_size = in_size;
}
