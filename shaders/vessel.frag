#version 430
#include "sky.glsl"
in vec3 v_position;
in vec3 v_normal;
in vec3 v_colour;
uniform vec3 u_eye;
out vec4 f_colour;

void main() {
    vec3 n = normalize(v_normal);
    vec3 ambient = 0.35 * sky_colour(normalize(n + vec3(0.0, 0.0, 1.0)));
    vec3 direct = u_sun_colour * unclouded(u_sun) * max(dot(n, u_sun), 0.0)
                + u_moon_colour * unclouded(u_moon) * max(dot(n, u_moon), 0.0);
    vec3 colour = v_colour * (ambient + 0.9 * direct);
    f_colour = finish(with_haze(colour, normalize(v_position - u_eye), length(v_position - u_eye)));
}
