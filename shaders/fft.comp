#version 430
// One pass of a 2-D FFT: a radix-2 Stockham FFT of every row (or every column) of SIZE x SIZE complex
// fields, one work group per line (gl_WorkGroupID.x) and field (gl_WorkGroupID.y, fields batch_stride
// apart), the line held in shared memory. The one FFT of the GPU side, driven by marinesim/gl.py's GpuFFT: the
// local solver's transforms (marinesim/solver/gpu.py) and the ocean's cascades (render/layers/synthesis.py).
// Defines: SIZE (power of two), THREADS, and optionally (the solver's, one field)
//   ADD_DEPTH: add the displaced depth to the real part while loading (u = h + d, first pass),
//   FINISH:    on storing, h = u - d, both fields times the sponge/obstacle factor, non-finite
//              values zeroed and counted, h also written to the height image (last pass).
layout(local_size_x = THREADS) in;

layout(std430, binding = 0) readonly buffer Source { vec2 source[]; };
layout(std430, binding = 1) writeonly buffer Target { vec2 target[]; };
layout(std430, binding = 2) readonly buffer Twiddles { vec2 twiddle[]; };  // exp(-2 pi i m / SIZE), m < SIZE / 2
#if defined(ADD_DEPTH) || defined(FINISH)
layout(r32f, binding = 0) uniform readonly image2D depth;                 // displaced depth d, m
#endif
#ifdef FINISH
layout(std430, binding = 3) readonly buffer Keep { float keep[]; };       // sponge x obstacle factor
layout(std430, binding = 4) buffer Counter { uint nonfinite; };
layout(r32f, binding = 1) uniform writeonly image2D height;               // h, m
#endif

uniform uint line_stride;     // between lines: SIZE for rows, 1 for columns
uniform uint element_stride;  // along a line: 1 for rows, SIZE for columns
uniform uint batch_stride;    // between fields (SIZE * SIZE), 0 for one field
uniform bool inverse;         // conjugate twiddles: exp(+2 pi i n m / SIZE)
uniform float scale;          // every output times this (1 / SIZE per pass for a normalised inverse)

shared vec2 line[2][SIZE];

#include "complex.glsl"

void main() {
    uint first = gl_WorkGroupID.y * batch_stride + gl_WorkGroupID.x * line_stride;
    for (uint i = gl_LocalInvocationID.x; i < SIZE; i += THREADS) {
        vec2 value = source[first + i * element_stride];
#ifdef ADD_DEPTH
        value.x += imageLoad(depth, ivec2(i, gl_WorkGroupID.x)).x;
#endif
        line[0][i] = value;
    }
    barrier();

    // Stockham decimation in frequency: sub-transforms of n = SIZE / stride points, m = n / 2;
    // stride = 2^shift, so the butterfly's place is found with a mask and a shift.
    float conjugate = inverse ? -1.0 : 1.0;
    uint from = 0u;
    uint shift = 0u;
    for (uint m = SIZE / 2u; m > 0u; m >>= 1) {
        uint stride = 1u << shift;
        for (uint t = gl_LocalInvocationID.x; t < SIZE / 2u; t += THREADS) {
            uint q = t & (stride - 1u);
            uint p = t >> shift;
            vec2 w = twiddle[p << shift];
            w.y *= conjugate;
            vec2 a = line[from][q + (p << shift)];
            vec2 b = line[from][q + ((p + m) << shift)];
            line[1u - from][q + (p << (shift + 1u))] = a + b;
            line[1u - from][q + (p << (shift + 1u)) + stride] = cmul(a - b, w);
        }
        barrier();
        from = 1u - from;
        shift += 1u;
    }

    for (uint i = gl_LocalInvocationID.x; i < SIZE; i += THREADS) {
        uint index = first + i * element_stride;
        vec2 value = line[from][i] * scale;
#ifdef FINISH
        ivec2 cell = ivec2(i, gl_WorkGroupID.x);
        value.x -= imageLoad(depth, cell).x;
        value *= keep[index];
        if (any(isnan(value)) || any(isinf(value))) {
            value = vec2(0.0);
            atomicAdd(nonfinite, 1u);
        }
        imageStore(height, cell, vec4(value.x));
#endif
        target[index] = value;
    }
}
