#version 430
// The cascades' four transforms (after fft.comp) into the textures the ocean samples
// (marinesim/render/layers/cascades.py): fields = (Dx, Dy, height, Jacobian), slopes = (d eta/dx,
// d eta/dy), E frame, m; J = (1 + dDx/dx)(1 + dDy/dy) - (dDx/dy)^2. One texel per invocation.
// Defines: SIZE, GROUP.
layout(local_size_x = GROUP, local_size_y = GROUP) in;

layout(std430, binding = 0) readonly buffer Fields { vec2 transform[]; };  // [tile][4][iy][ix]
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_fields;
layout(rg32f, binding = 1) uniform writeonly image2DArray u_slopes;

void main() {
    uvec3 at = gl_GlobalInvocationID;
    uint plane = SIZE * SIZE;
    uint first = at.z * 4u * plane + at.y * SIZE + at.x;
    vec2 height_shear = transform[first];
    vec2 displacement = transform[first + plane];
    vec2 slopes = transform[first + 2u * plane];
    vec2 stretch = transform[first + 3u * plane];
    float jacobian = stretch.x * stretch.y - height_shear.y * height_shear.y;
    imageStore(u_fields, ivec3(at), vec4(displacement, height_shear.x, jacobian));
    imageStore(u_slopes, ivec3(at), vec4(slopes, 0.0, 0.0));
}
