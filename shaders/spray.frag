#version 430
#include "sky.glsl"
// A puff: white water lit like the foam (sky, sun and moon from above), soft-edged, hazed with distance.
in vec3 v_position;
in float v_opacity;
uniform vec3 u_eye;
out vec4 f_colour;

const vec3 SPRAY = vec3(0.92, 0.95, 0.97);

void main() {
    vec2 p = gl_PointCoord * 2.0 - 1.0;
    float r2 = dot(p, p);
    if (r2 > 1.0) discard;
    float blob = exp(-4.0 * r2) - exp(-4.0);  // a soft blob, nothing at the sprite's edge
    vec2 seed = vec2(float(gl_PrimitiveID) * 7.31, float(gl_PrimitiveID) * 3.17);
    float clumps = value_noise(p * 2.5 + seed) * 0.65 + value_noise(p * 6.0 - seed) * 0.35;
    float density = blob * smoothstep(0.35, 0.75, clumps);  // drops in clumps and strands, not a disc
    vec3 sun = u_sun_colour * unclouded(u_sun);
    vec3 moon = u_moon_colour * unclouded(u_moon);
    vec3 lit = SPRAY * (0.45 * u_sky + 0.6 * sun * (0.5 + 0.5 * u_sun.z) + 0.6 * moon * (0.5 + 0.5 * u_moon.z));
    vec3 to_puff = v_position - u_eye;
    float distance_m = length(to_puff);
    f_colour = vec4(finish(with_haze(lit, to_puff / distance_m, distance_m)).rgb, v_opacity * density);
}
