#version 430
// Foam memory per cascade texel: the cascade's Jacobian, held at its lowest and relaxing back
// to 1 as exp(-dt / tau), so a fold leaves foam that fades. The ocean's fragment shader
// multiplies the cascades' held Jacobians (the Jacobian of the summed map, to leading order
// when the scales separate) and turns the product into foam: a short cascade breaks where the
// long waves compress it, so its foam does not repeat with its tile. The held value and its
// square are stored, so that mip levels give the mean and the variance under a pixel's
// footprint. One texel per invocation. Defines: GROUP.
layout(local_size_x = GROUP, local_size_y = GROUP) in;
layout(rg32f, binding = 0) uniform image2DArray u_held;
uniform sampler2DArray u_cascades;   // alpha: Jacobian
uniform float u_decay;               // exp(-dt / tau)

void main() {
    ivec3 at = ivec3(gl_GlobalInvocationID.xy, gl_WorkGroupID.z);
    float jacobian = texelFetch(u_cascades, at, 0).a;
    float relaxed = 1.0 - (1.0 - imageLoad(u_held, at).r) * u_decay;
    float held = min(jacobian, relaxed);
    imageStore(u_held, at, vec4(held, held * held, 0.0, 0.0));
}
