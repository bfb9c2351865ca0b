#version 430
// HUD text (marinesim/render/hud.py): one instance per glyph, a quad of one atlas cell drawn as a
// 4-vertex triangle strip; positions in pixels with the origin at the top-left of the target.
in vec2 in_pos;     // top-left corner of the glyph's cell, px
in float in_glyph;  // cell index in the atlas (character code - 32)
in vec4 in_color;

uniform vec2 viewport;  // target size, px
uniform ivec2 cell;     // glyph cell size, px (the monospace advance x the line height)
uniform int columns;    // cells per atlas row

out vec2 texel;         // atlas position, texels (row 0 = top of the atlas image)
flat out vec4 color;

void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    int glyph = int(in_glyph);
    vec2 p = in_pos + corner * vec2(cell);
    texel = (vec2(glyph % columns, glyph / columns) + corner) * vec2(cell);
    color = in_color;
    gl_Position = vec4(2.0 * p.x / viewport.x - 1.0, 1.0 - 2.0 * p.y / viewport.y, 0.0, 1.0);
}
