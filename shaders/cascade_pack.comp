#version 430
// The cascades' spectra at time t (marinesim/render/layers/synthesis.py; the same numerics as
// marinesim/sea/synthesis.py on the CPU): per cell q of every tile,
//   C[q] = even cos(w t) + odd sin(w t),   even, odd blended between two sea states by u_weight,
// times the four packing multipliers (height + i dDx/dy, Dx + i Dy, slopes, 1 + dDx/dx + i(1 + dDy/dy)),
// written as the four transforms' inputs [tile][transform][iy][ix]. The phase w t is reduced to
// [-pi, pi] in double precision, so a long run keeps float32 trigonometry exact.
// Defines: SIZE (cells a side, power of two), TILES, GROUP (work-group side, marinesim/gl.py).
layout(local_size_x = GROUP, local_size_y = GROUP) in;

layout(std430, binding = 0) readonly buffer Before { vec4 before[]; };  // even.re, even.im, odd.re, odd.im, m
layout(std430, binding = 1) readonly buffer After { vec4 after[]; };
layout(std430, binding = 2) readonly buffer Omega { double omega[]; };  // rad/s per cell
layout(std430, binding = 3) writeonly buffer Spectra { vec2 spectra[]; };

uniform double u_time;        // s
uniform float u_weight;       // of the after state, 0..1 (smoothstep of the ramp)
uniform float u_choppiness;   // lambda
uniform float u_dk[TILES];    // 2 pi / tile size, rad/m

const double TWO_PI = 6.283185307179586LF;

#include "complex.glsl"

void main() {
    uvec3 at = gl_GlobalInvocationID;
    uint cell = (at.z * SIZE + at.y) * SIZE + at.x;
    vec4 state = before[cell] + u_weight * (after[cell] - before[cell]);
    double phase = omega[cell] * u_time;
    float p = float(phase - round(phase / TWO_PI) * TWO_PI);  // [-pi, pi]: where GPUs' sin and cos are exact
    vec2 c = state.xy * cos(p) + state.zw * sin(p);

    ivec2 n = ivec2(at.xy) - ivec2(greaterThanEqual(at.xy, uvec2(SIZE / 2))) * int(SIZE);  // fftfreq order
    vec2 q = vec2(n) * u_dk[at.z];
    float k = length(q);
    vec2 unit = q / (k > 0.0 ? k : 1.0);
    float lambda = u_choppiness;

    uint plane = SIZE * SIZE;
    uint first = at.z * 4u * plane + at.y * SIZE + at.x;
    spectra[first] = cmul(vec2(1.0, -lambda * q.x * unit.y), c);
    spectra[first + plane] = cmul(lambda * vec2(-unit.y, unit.x), c);
    spectra[first + 2u * plane] = cmul(vec2(-q.y, q.x), c);
    vec2 stretch = cmul(-lambda * vec2(q.x * unit.x, q.y * unit.y), c);
    spectra[first + 3u * plane] = stretch + (cell == at.z * plane ? vec2(1.0) : vec2(0.0));  // the ones at DC
}
