#version 430
// A puff of spray as a point sprite: E-frame position (m), diameter (m), opacity at its centre.
layout(location = 0) in vec3 in_position;
layout(location = 1) in float in_size;
layout(location = 2) in float in_opacity;
uniform mat4 u_view_projection;
uniform float u_pixels_per_m;   // pixels a metre spans at a distance of one metre (the projection's scale)
out vec3 v_position;
out float v_opacity;

void main() {
    gl_Position = u_view_projection * vec4(in_position, 1.0);
    float size = in_size * u_pixels_per_m / max(gl_Position.w, 0.1);
    gl_PointSize = clamp(size, 1.0, 256.0);
    v_position = in_position;
    v_opacity = in_opacity * min(size * size / 4.0, 1.0);  // a puff under two pixels fades rather than flickers
}
