#version 430
#include "sky.glsl"
in vec2 v_ndc;
uniform mat4 u_inverse_view_projection;
uniform vec3 u_eye;
out vec4 f_colour;

const float SUN_DISC = 0.999989;   // cos of the sun's and the moon's angular radius, 0.27 deg
const float DISC_EDGE = 0.000004;

void main() {
    vec4 far_point = u_inverse_view_projection * vec4(v_ndc, 1.0, 1.0);
    vec3 d = normalize(far_point.xyz / far_point.w - u_eye);
    vec3 c = d.z >= 0.0 ? sky_colour(d) : haze_colour(d);  // below the horizon: sea beyond the grid, in haze
    float above = step(0.0, d.z);
    float clear = 1.0 - cloud_along(d);
    c += u_sun_colour * 40.0 * smoothstep(SUN_DISC - DISC_EDGE, SUN_DISC + DISC_EDGE, dot(d, u_sun)) * above * clear;
    c += u_moon_colour * 60.0 * smoothstep(SUN_DISC - DISC_EDGE, SUN_DISC + DISC_EDGE, dot(d, u_moon)) * above * clear;
    // stars: about one in three square degrees where the sky is dark enough, twinkling neither in time nor with the view
    if (u_sky < 0.01 && d.z > 0.0) {
        vec2 cell = floor(vec2(atan(d.y, d.x) * 600.0, d.z * 600.0));
        float star = step(0.9965, hash(cell)) * hash(cell + 7.0);
        c += vec3(0.9, 0.92, 1.0) * star * 0.05 * (1.0 - smoothstep(0.002, 0.01, u_sky)) * clear * smoothstep(0.0, 0.1, d.z);
    }
    f_colour = finish(c);
}
