// The analytic sky, sun and haze shared by the sky pass, the water's reflection and the vessel.
// Colours are linear radiance in arbitrary units; finish() tone-maps and gamma-encodes them.
uniform vec3 u_sun;         // unit vector towards the sun (E frame, z up)
uniform float u_visibility; // m: meteorological visibility, where haze leaves 5 % of a dark object's contrast

// Koschmieder: the contrast of an object against the horizon falls as exp(-sigma d); the visibility is
// where it reaches the threshold 0.05, so the extinction coefficient sigma = ln(1 / 0.05) / visibility.
const float KOSCHMIEDER = 2.995732;

const vec3 ZENITH = vec3(0.08, 0.22, 0.55);
const vec3 HORIZON = vec3(0.60, 0.72, 0.86);
const vec3 SUN_COLOUR = vec3(1.00, 0.92, 0.78);

vec3 sky_colour(vec3 d) {
    float up = clamp(d.z, 0.0, 1.0);
    vec3 c = mix(HORIZON, ZENITH, pow(up, 0.45));
    float mu = max(dot(d, u_sun), 0.0);
    return c + SUN_COLOUR * (0.20 * pow(mu, 6.0) + 0.50 * pow(mu, 200.0));
}

// The haze colour seen along the horizontal direction of d (what the far sea fades into).
vec3 haze_colour(vec3 d) {
    vec3 flat_d = normalize(vec3(d.xy, 0.0) + vec3(0.0, 0.0, 1e-4));
    return 0.82 * sky_colour(flat_d);
}

vec3 with_haze(vec3 colour, vec3 d, float distance_m) {
    return mix(colour, haze_colour(d), 1.0 - exp(-KOSCHMIEDER * distance_m / u_visibility));
}

vec4 finish(vec3 c) {
    c = vec3(1.0) - exp(-1.6 * c);  // exposure tone map
    return vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
