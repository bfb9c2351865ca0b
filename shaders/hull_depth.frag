#version 430
// Displaced depth by additive blending: + min(z, 0) for faces looking up, - min(z, 0) for faces
// looking down (counter-clockwise from above = outward normal up).
noperspective in float z;
flat in float weight;

out float depth;

void main() {
    depth = (gl_FrontFacing ? 1.0 : -1.0) * weight * min(z, 0.0);
}
