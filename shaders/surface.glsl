// The vessel's own water, in the ocean's vertex and fragment shaders: up to two Kelvin wakes
// (two while a speed change blends) in the steady vessel frame, and the local solver's field
// on its Earth-fixed grid. Wake textures hold (elevation m, d/dx, d/dy, foam) on the wake grid.
uniform vec3 u_track;             // track point x, y (m, E frame) and heading (rad, math angle)
uniform sampler2D u_wake0;
uniform sampler2D u_wake1;
uniform vec4 u_wake_rect0;        // first column x, first row y, 1 / width, 1 / height (m, vessel frame)
uniform vec4 u_wake_rect1;
uniform vec2 u_wake_weight;       // 0 where a wake is not drawn
uniform sampler2D u_solver;       // elevation (m)
uniform vec4 u_solver_rect;       // origin x, y (m, E frame), 1 / extent, weight (0: no solver)
uniform float u_solver_cell;      // m

vec2 vessel_frame(vec2 xy) {      // E frame -> steady vessel frame (x forward, y to port)
    vec2 r = xy - u_track.xy;
    float c = cos(u_track.z), s = sin(u_track.z);
    return vec2(c * r.x + s * r.y, -s * r.x + c * r.y);
}

float inside(vec2 uv) {           // 1 inside the unit square, fading to 0 over its outer 5 %
    vec2 edge = min(uv, 1.0 - uv);
    return clamp(min(edge.x, edge.y) / 0.05, 0.0, 1.0);
}

// A wake grid's weight: fading over its outer 5 % astern and abeam; none at its front edge, where the field is at
// the still level already (the waves start at the bow, the local flow is tapered to it: render/wake_look.py).
float inside_wake(vec2 uv) {
    if (uv.x > 1.0) return 0.0;
    return clamp(min(uv.x, min(uv.y, 1.0 - uv.y)) / 0.05, 0.0, 1.0);
}

vec4 wake_sample(sampler2D wake, vec4 rect, vec2 v) {  // (h, dh/dx, dh/dy, foam) in the vessel frame
    vec2 uv = (v - rect.xy) * rect.zw;
    return texture(wake, uv) * inside_wake(uv);
}

vec3 solver_sample(vec2 xy) {      // (h, dh/dx, dh/dy) in the E frame
    if (u_solver_rect.w == 0.0) return vec3(0.0);
    vec2 uv = (xy - u_solver_rect.xy) * u_solver_rect.z;
    vec2 texel = vec2(u_solver_rect.z * u_solver_cell, u_solver_rect.z * u_solver_cell);
    float h = texture(u_solver, uv).r;
    float hx = texture(u_solver, uv + vec2(texel.x, 0.0)).r - texture(u_solver, uv - vec2(texel.x, 0.0)).r;
    float hy = texture(u_solver, uv + vec2(0.0, texel.y)).r - texture(u_solver, uv - vec2(0.0, texel.y)).r;
    return vec3(h, hx / (2.0 * u_solver_cell), hy / (2.0 * u_solver_cell)) * inside(uv) * u_solver_rect.w;
}

vec4 wakes(vec2 xy) {              // summed wakes in the vessel frame
    vec2 v = vessel_frame(xy);
    vec4 w = vec4(0.0);
    if (u_wake_weight.x > 0.0) w += u_wake_weight.x * wake_sample(u_wake0, u_wake_rect0, v);
    if (u_wake_weight.y > 0.0) w += u_wake_weight.y * wake_sample(u_wake1, u_wake_rect1, v);
    return w;
}

float local_height(vec2 xy) {
    return wakes(xy).x + solver_sample(xy).x;
}

// Slope (d/dx, d/dy, E frame) of the wakes and the solver, and the wake's foam.
vec3 local_slope_foam(vec2 xy) {
    vec4 w = wakes(xy);
    float c = cos(u_track.z), s = sin(u_track.z);
    vec2 wake_slope = vec2(c * w.y - s * w.z, s * w.y + c * w.z);  // vessel-frame gradient -> E frame
    return vec3(wake_slope + solver_sample(xy).yz, w.w);
}
