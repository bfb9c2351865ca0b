#version 430
// The wave step in k-space: Z'(k) = A(k) Z(k) + B(k) conj(Z(-k)) (marinesim/solver/spectral.py).
// Defines: SIZE, GROUP.
layout(local_size_x = GROUP, local_size_y = GROUP) in;

layout(std430, binding = 0) readonly buffer Source { vec2 source[]; };
layout(std430, binding = 1) writeonly buffer Target { vec2 target[]; };
layout(std430, binding = 2) readonly buffer Coefficients { vec4 coefficient[]; };  // A.re, A.im, B.re, B.im

#include "complex.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    uint j = gl_GlobalInvocationID.y;
    uint k = j * SIZE + i;
    uint mirror = ((SIZE - j) % SIZE) * SIZE + (SIZE - i) % SIZE;
    vec2 z = source[k];
    vec2 w = source[mirror];
    w.y = -w.y;
    vec4 c = coefficient[k];
    target[k] = cmul(c.xy, z) + cmul(c.zw, w);
}
