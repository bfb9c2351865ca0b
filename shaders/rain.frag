#version 430
// Rain: streaks of falling drops on cylinders around the eye (3 to 32 m out, one a pass, at its own depth so that
// the wheelhouse and the ship hide what is behind them), anchored in the Earth frame so that they stay upright when
// the ship rolls; falling at 7 m/s, leaning with the wind, as many as the rain's visible drops (u_drops).
// Each streak is drawn at least a pixel wide, fainter by the ratio of its true width, so distant rain reads as a
// veil rather than aliasing.
#include "sky.glsl"
in vec2 v_ndc;
uniform mat4 u_inverse_view_projection;
uniform mat4 u_view_projection;
uniform vec3 u_eye;
uniform int u_layer;       // 0..3: the cylinder 3 x 2.2^layer m out
uniform float u_time;      // s of simulated time
uniform float u_drops;     // share of streak cells with a drop: visible drops against a cloudburst's
uniform vec3 u_wind;       // unit vector the wind blows towards (E frame x, y), speed (m/s)
out vec4 f_colour;

const float FALL_M_S = 7.0;       // terminal velocity of a 2 mm drop
const float COLUMN_M = 0.35;      // streak columns around each cylinder
const float SPACING_M = 1.5;      // drops along a column, at the heaviest rain
const float STREAK_M = 0.25;      // a drop's path in a frame's exposure (1/30 s)
const float DROP_M = 0.004;       // its width

void main() {
    vec4 far_point = u_inverse_view_projection * vec4(v_ndc, 1.0, 1.0);
    vec3 d = normalize(far_point.xyz / far_point.w - u_eye);
    float horizontal = max(length(d.xy), 1e-3);
    float radius = 3.0 * pow(2.2, float(u_layer));
    vec3 at = u_eye + d * (radius / horizontal);           // where the ray meets this layer's cylinder
    if (at.z < 0.0) discard;                               // under the sea
    vec4 clip = u_view_projection * vec4(at, 1.0);
    gl_FragDepth = 0.5 + 0.5 * clip.z / clip.w;            // behind what is nearer (the wheelhouse, the ship)
    float azimuth = atan(d.y, d.x);
    vec2 tangent = vec2(-sin(azimuth), cos(azimuth));
    float lean = dot(u_wind.xy, tangent) * u_wind.z / FALL_M_S;      // the wind blows the drops sideways
    float u = (azimuth * radius + lean * (at.z - u_eye.z)) / COLUMN_M;  // a drop drifts downwind as it falls
    float column = floor(u);
    float seed = hash(vec2(column, float(u_layer) * 17.0));
    // the fall wrapped at 1200 spacings keeps the hash's inputs small (float32); an hour of fall is 14 of them, so
    // the hourly wrap of u_time is seamless
    float fallen = mod(u_time * FALL_M_S, 1200.0 * SPACING_M);
    float v = (at.z + fallen + 40.0 * seed) / SPACING_M;
    float falling = step(1.0 - u_drops, hash(vec2(column + 0.5, floor(v) + 31.0 * float(u_layer))));
    float along = fract(v) * SPACING_M;
    float centre = 0.5 + 0.6 * (seed - 0.5);
    float width = max(DROP_M / COLUMN_M, fwidth(u));
    float strength = min(4.0 * (DROP_M / COLUMN_M) / width, 1.0);
    float streak = falling * step(along, STREAK_M) * (1.0 - smoothstep(0.5 * width, width, abs(fract(u) - centre)));
    float steep = smoothstep(0.2, 0.5, horizontal);        // no streaks straight up or down (they would be arcs)
    vec3 drops = vec3(0.75, 0.78, 0.82) * (0.25 + u_sky) + u_sun_colour * 0.2;
    f_colour = vec4(finish(drops).rgb, clamp(streak * strength * steep * 0.35, 0.0, 0.6));
}
