#version 430
#include "sky.glsl"
in vec3 v_position;
in vec3 v_normal;
in vec3 v_colour;
in vec3 v_body;
in vec3 v_body_normal;
uniform vec3 u_eye;
// The draft marks at the forward, midship and aft stations (render/draft_marks.py; body frame, m): their x, the
// keel line's z there (drafts are read from it), the highest mark's z (none below the keel) and the waterline's
// half-breadth. NUMERAL, STEP, GLYPH_W, ADVANCE and STROKE (m) are defined by draft_marks.GLYPH.
uniform vec3 u_marks_x;
uniform vec3 u_marks_keel;
uniform vec3 u_marks_top;
uniform vec3 u_marks_half;
out vec4 f_colour;

const vec3 MARK_PAINT = vec3(0.85, 0.85, 0.82);
// A digit's segments as bits: 1 top, 2 top right, 4 bottom right, 8 bottom, 16 bottom left, 32 top left, 64 middle.
const int SEGMENTS[10] = int[10](0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07, 0x7F, 0x6F);

// 1 where p lies in the box from lo to hi (edges included), else 0.
float in_box(vec2 p, vec2 lo, vec2 hi) {
    return float(all(greaterThanEqual(p, lo)) && all(lessThanEqual(p, hi)));
}

// 1 on a stroke of ``digit`` at p (m from the lower left corner of its GLYPH_W x NUMERAL box).
float digit_stroke(int digit, vec2 p) {
    int s = SEGMENTS[digit];
    float w = GLYPH_W, h = NUMERAL, t = STROKE, m = 0.5 * NUMERAL;
    float on = 0.0;
    if ((s & 1) != 0) on = max(on, in_box(p, vec2(0.0, h - t), vec2(w, h)));
    if ((s & 2) != 0) on = max(on, in_box(p, vec2(w - t, m), vec2(w, h)));
    if ((s & 4) != 0) on = max(on, in_box(p, vec2(w - t, 0.0), vec2(w, m)));
    if ((s & 8) != 0) on = max(on, in_box(p, vec2(0.0), vec2(w, t)));
    if ((s & 16) != 0) on = max(on, in_box(p, vec2(0.0), vec2(t, m)));
    if ((s & 32) != 0) on = max(on, in_box(p, vec2(0.0, m), vec2(t, h)));
    if ((s & 64) != 0) on = max(on, in_box(p, vec2(0.0, m - 0.5 * t), vec2(w, m + 0.5 * t)));
    return on;
}

float to_segment(vec2 p, vec2 a, vec2 b) {
    vec2 ab = b - a;
    return length(p - a - ab * clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0));
}

// 1 on a stroke of the letter M (the same box as a digit).
float letter_m(vec2 p) {
    float w = GLYPH_W, h = NUMERAL, t = STROKE;
    vec2 middle = vec2(0.5 * w, 0.4 * h);
    float on = max(in_box(p, vec2(0.0), vec2(t, h)), in_box(p, vec2(w - t, 0.0), vec2(w, h)));
    on = max(on, float(min(to_segment(p, vec2(0.5 * t, h - 0.5 * t), middle),
                           to_segment(p, vec2(w - 0.5 * t, h - 0.5 * t), middle)) < 0.5 * t));
    return on * in_box(p, vec2(0.0), vec2(w, h));
}

// 1 where the draft marks are painted at body point p on plating facing n (outwards, at least half the
// waterline's half-breadth out): "<metres>M" at whole metres, the decimetre between them, each numeral's lower
// edge at the draft it reads.
float draft_mark(vec3 p, vec3 n) {
    if (abs(n.y) < 0.5 || n.y * p.y <= 0.0) return 0.0;
    for (int i = 0; i < 3; ++i) {
        if (abs(p.x - u_marks_x[i]) > 0.2 || p.z < u_marks_keel[i] || p.z > u_marks_top[i]
            || abs(p.y) < 0.5 * u_marks_half[i]) continue;
        float draft = p.z - u_marks_keel[i];
        float k = floor(draft / STEP);
        vec2 q = vec2(0.0, draft - k * STEP);
        if (q.y > NUMERAL) return 0.0;
        int tenths = int(round(2.0 * k));
        int metres = tenths / 10, decimetre = tenths % 10;
        int chars = decimetre != 0 ? 1 : (metres >= 10 ? 3 : 2);
        float width = float(chars - 1) * ADVANCE + GLYPH_W;
        float side = n.y < 0.0 ? 1.0 : -1.0;  // seen from outside the text runs forward to starboard, aft to port
        float x = (p.x - u_marks_x[i]) * side + 0.5 * width;
        if (x < 0.0 || x > width) return 0.0;
        int c = int(floor(x / ADVANCE));
        q.x = x - float(c) * ADVANCE;
        if (q.x > GLYPH_W) return 0.0;
        if (decimetre != 0) return digit_stroke(decimetre, q);
        if (c == chars - 1) return letter_m(q);
        return digit_stroke(chars == 3 && c == 0 ? metres / 10 : metres % 10, q);
    }
    return 0.0;
}

void main() {
    vec3 n = normalize(v_normal);
    vec3 paint = v_colour;
    float footprint = length(fwidth(v_body));  // m per pixel: numerals under about five pixels are not drawn
    float legible = 1.0 - smoothstep(0.01, 0.025, footprint);
    if (legible > 0.0) paint = mix(paint, MARK_PAINT, legible * draft_mark(v_body, normalize(v_body_normal)));
    vec3 ambient = 0.35 * sky_colour(normalize(n + vec3(0.0, 0.0, 1.0)));
    vec3 direct = u_sun_colour * unclouded(u_sun) * max(dot(n, u_sun), 0.0)
                + u_moon_colour * unclouded(u_moon) * max(dot(n, u_moon), 0.0);
    vec3 colour = paint * (ambient + 0.9 * direct);
    f_colour = finish(with_haze(colour, normalize(v_position - u_eye), length(v_position - u_eye)));
}
