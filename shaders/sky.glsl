// The analytic sky, sun, moon, clouds and haze shared by the sky pass, the water's reflection and the vessel.
// Colours are linear radiance in arbitrary units (a clear day's sky near 1); finish() tone-maps and
// gamma-encodes them. marinesim/render/daylight.py sets the uniforms and states their laws.
uniform vec3 u_sun;         // unit vector towards the sun (E frame, z up)
uniform vec3 u_moon;        // ... towards the moon
uniform vec3 u_sun_colour;  // the sun's direct light through the air (0 once it has set), before clouds
uniform vec3 u_moon_colour; // the moon's, by its lit fraction
uniform float u_sky;        // the sky's brightness against a clear day (twilight, night, overcast)
uniform float u_cloud;      // cloud cover, 0..1 (oktas / 8)
uniform float u_visibility; // m: meteorological visibility, where haze leaves 5 % of a dark object's contrast

// Koschmieder: the contrast of an object against the horizon falls as exp(-sigma d); the visibility is
// where it reaches the threshold 0.05, so the extinction coefficient sigma = ln(1 / 0.05) / visibility.
const float KOSCHMIEDER = 2.995732;

const vec3 ZENITH = vec3(0.08, 0.22, 0.55);
const vec3 HORIZON = vec3(0.60, 0.72, 0.86);
const vec3 NIGHT = vec3(0.35, 0.45, 0.80);   // the night sky's blue (scaled by u_sky)
const vec3 DUSK = vec3(1.00, 0.45, 0.15);    // the glow on the horizon under the sun around sunset
const vec3 OVERCAST = vec3(0.62, 0.65, 0.68);

float hash(vec2 p) {
    p = fract(p * vec2(443.897, 441.423));
    p += dot(p, p.yx + 19.19);
    return fract((p.x + p.y) * p.x);
}

float value_noise(vec2 p) {
    vec2 i = floor(p), f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash(i), hash(i + vec2(1.0, 0.0)), u.x), mix(hash(i + vec2(0.0, 1.0)), hash(i + vec2(1.0)), u.x), u.y);
}

// How much cloud lies along direction d (0..1): fractal noise on a cloud deck 1.5 km up, its cover thresholded
// so that the covered part of the sky is u_cloud. Flat near the horizon, where the deck's far end is hazed.
float cloud_along(vec3 d) {
    if (u_cloud <= 0.0) return 0.0;
    vec2 p = d.xy / max(d.z, 0.02) * 0.6;
    float n = 0.0, amplitude = 0.5;
    for (int i = 0; i < 5; ++i) {
        n += amplitude * value_noise(p);
        p = p * 2.03 + vec2(17.1, 3.7);
        amplitude *= 0.5;
    }
    // the sum is about normal (mean 0.431, deviation 0.148 over the sky): its logistic approximation of the
    // normal CDF makes it about uniform over 0..1, so a threshold at 1 - cover covers that share of the sky
    n = 1.0 / (1.0 + exp(-1.702 * (n - 0.431) / 0.148));
    float threshold = 1.0 - u_cloud;
    float cover = smoothstep(threshold - 0.05, threshold + 0.05, n);
    return mix(u_cloud, cover, smoothstep(0.0, 0.15, d.z));
}

// The sky without its clouds along d, and then with them.
vec3 clear_sky(vec3 d) {
    float up = clamp(d.z, 0.0, 1.0);
    vec3 day = mix(HORIZON, ZENITH, pow(up, 0.45));
    float sun_up = clamp(u_sun.z * 6.0, 0.0, 1.0);                 // 0 below the horizon, 1 above ~10 deg
    vec3 c = mix(NIGHT * mix(HORIZON, ZENITH, 0.6), day, sun_up) * u_sky;
    float mu = max(dot(d, u_sun), 0.0);
    c += u_sun_colour * (0.20 * pow(mu, 6.0) + 0.50 * pow(mu, 200.0));
    // around sunset the horizon under the sun glows: strongest for a sun just below it, gone by -10 deg
    float below = (u_sun.z + 0.03) / 0.09;
    float glow = exp(-below * below);
    if (glow > 1e-3) {
        vec2 flat_d = normalize(d.xy + 1e-6), flat_sun = normalize(u_sun.xy + 1e-6);
        float towards = pow(max(0.5 + 0.5 * dot(flat_d, flat_sun), 0.0), 3.0);  // pow of a negative is undefined
        c += DUSK * glow * towards * pow(1.0 - up, 6.0) * 0.6;
    }
    return c;
}

vec3 sky_colour(vec3 d) {
    vec3 c = clear_sky(d);
    float cloud = cloud_along(d);
    vec3 lit_by = u_sun_colour * 0.35 * (1.0 - 0.6 * u_cloud) + vec3(u_sky) * 0.55;
    vec3 deck = OVERCAST * mix(1.0, 0.55, u_cloud * u_cloud) * lit_by
              + u_sun_colour * 0.5 * pow(max(dot(d, u_sun), 0.0), 8.0) * (1.0 - u_cloud);  // silver linings
    return mix(c, deck, cloud);
}

// The share of direct sun (or moon) that reaches the sea: what the clouds along its direction let through.
float unclouded(vec3 towards) {
    return 1.0 - cloud_along(towards);
}

// The haze colour seen along the horizontal direction of d (what the far sea fades into).
vec3 haze_colour(vec3 d) {
    vec3 flat_d = normalize(vec3(d.xy, 0.0) + vec3(0.0, 0.0, 1e-4));
    return 0.82 * mix(clear_sky(flat_d), OVERCAST * mix(1.0, 0.55, u_cloud * u_cloud) * u_sky, u_cloud);
}

vec3 with_haze(vec3 colour, vec3 d, float distance_m) {
    return mix(colour, haze_colour(d), 1.0 - exp(-KOSCHMIEDER * distance_m / u_visibility));
}

vec4 finish(vec3 c) {
    c = vec3(1.0) - exp(-1.6 * c);  // exposure tone map
    return vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
