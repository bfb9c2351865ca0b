#version 430
// HUD panels and lines: flat colour, alpha-blended by the caller's blend state.
flat in vec4 color;

out vec4 frag;

void main() {
    frag = color;
}
