#version 430
#include "sky.glsl"
in vec2 v_ndc;
uniform mat4 u_inverse_view_projection;
uniform vec3 u_eye;
out vec4 f_colour;

void main() {
    vec4 far_point = u_inverse_view_projection * vec4(v_ndc, 1.0, 1.0);
    vec3 d = normalize(far_point.xyz / far_point.w - u_eye);
    vec3 c = d.z >= 0.0 ? sky_colour(d) : haze_colour(d);  // below the horizon: sea beyond the grid, in haze
    float mu = dot(d, u_sun);
    c += SUN_COLOUR * 40.0 * smoothstep(0.999985, 0.999992, mu) * step(0.0, d.z);  // the disc, 0.27 deg
    f_colour = finish(c);
}
