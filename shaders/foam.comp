#version 430
// Foam with persistence: where a cascade's surface folds (Jacobian below J_START) foam appears,
// fully at J_FULL; elsewhere it decays as exp(-dt / tau). One texel per invocation.
layout(local_size_x = 16, local_size_y = 16) in;
layout(r32f, binding = 0) uniform image2DArray u_foam;
uniform sampler2DArray u_cascades;   // alpha: Jacobian
uniform float u_decay;               // exp(-dt / tau)
uniform float u_j_start;
uniform float u_j_full;

void main() {
    ivec3 at = ivec3(gl_GlobalInvocationID.xy, gl_WorkGroupID.z);
    float jacobian = texelFetch(u_cascades, at, 0).a;
    float fresh = clamp((u_j_start - jacobian) / (u_j_start - u_j_full), 0.0, 1.0);
    float old = imageLoad(u_foam, at).r * u_decay;
    imageStore(u_foam, at, vec4(max(old, fresh)));
}
