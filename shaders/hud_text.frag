#version 430
// HUD text: the atlas's coverage (R8) scales the glyph colour's alpha; quads sit on whole pixels,
// so each fragment reads exactly one texel.
in vec2 texel;
flat in vec4 color;

uniform sampler2D atlas;

out vec4 frag;

void main() {
    float coverage = texelFetch(atlas, ivec2(texel), 0).r;
    frag = vec4(color.rgb, color.a * coverage);
}
