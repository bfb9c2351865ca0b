#version 430
// HUD panels (triangles) and lines: vertices in pixels, origin at the top-left of the target.
in vec2 in_pos;  // px
in vec4 in_color;

uniform vec2 viewport;  // target size, px

flat out vec4 color;

void main() {
    color = in_color;
    gl_Position = vec4(2.0 * in_pos.x / viewport.x - 1.0, 1.0 - 2.0 * in_pos.y / viewport.y, 0.0, 1.0);
}
