#version 430
// Water: normals from the cascades' slopes (mipmapped), Fresnel (Schlick, F0 = 0.02) between
// the sky's reflection and a subsurface tint, the sun's glitter, foam from the Jacobian with
// persistence (foam.comp) and along the wake, haze to the horizon. No water inside the hull.
// Defines: TILES, TILE_LOD (log2 of the cascades' resolution), FOAM_J_START, FOAM_J_FULL.
#include "sky.glsl"
in vec2 v_xy;
in vec3 v_position;
in float v_spacing;

uniform sampler2DArray u_slopes;   // per tile: d eta/dx, d eta/dy
uniform sampler2DArray u_foam;     // per tile: held Jacobian and its square (foam.comp)
uniform float u_tile_size[TILES];
uniform vec3 u_eye;
uniform sampler2D u_hull_mask;     // 1 inside the waterplane (vessel frame)
uniform vec4 u_hull_rect;          // as the wake rect
uniform vec4 u_wash;               // stern x, half beam (m, vessel frame), speed (m/s), 1: a hull to wash
uniform float u_foam_on;           // 0: draw no foam (comparisons)
uniform vec3 u_wind;               // unit vector the wind blows towards (E frame x, y), speed at 10 m (m/s)

#include "surface.glsl"

const vec3 DEEP = vec3(0.004, 0.030, 0.060);
const vec3 SCATTER = vec3(0.02, 0.11, 0.10);
const vec3 FOAM = vec3(0.85, 0.88, 0.90);
const float F0 = 0.02;
const float WASH_LIFETIME_S = 60.0;   // the white of the propeller wash fades as exp(-age / this)
const float WASH_FULL_SPEED = 3.0;    // m/s: the wash is fully white from this speed on

// The turbulent wake astern (vessel frame v): a band as wide as the beam at the stern that spreads as a
// self-propelled body's wake does, its width growing as the distance to the 1/5 power (Tennekes & Lumley),
// whose foam fades with the water's age since the stern passed; streaked along the track.
float wash_foam(vec2 v) {
    float speed = u_wash.z;
    float behind = u_wash.x - v.x;
    if (u_wash.w == 0.0 || speed <= 0.05 || behind <= 0.0) return 0.0;
    float half_width = u_wash.y * pow(1.0 + behind / u_wash.y, 0.2);
    float across = v.y / half_width;
    float fading = exp(-behind / (speed * WASH_LIFETIME_S));
    if (abs(across) > 2.5 || fading < 0.01) return 0.0;  // outside the band: no foam to draw
    float streaks = 0.55 + 0.9 * value_noise(vec2(v.x / 35.0, v.y / 1.8));
    float fresh = smoothstep(0.0, 0.5 * u_wash.y, behind);  // it boils up just behind the transom
    return clamp(exp(-2.0 * across * across) * fading * streaks * fresh, 0.0, 1.0)
           * min(speed / WASH_FULL_SPEED, 1.0);
}

// Foam blown in streaks along the wind (windrows): from Beaufort 7 (13.9 m/s, "foam begins to be blown in streaks")
// to 10 (24.5 m/s, "the surface takes a white appearance"): thin winding lines along the wind (the mid-level contour
// of a noise stretched 8 times along it), wider and whiter as the wind rises. Where a pixel's footprint spans
// several, their mean cover instead of aliasing.
float streak_foam(vec2 xy, float footprint_m) {
    float amount = clamp((u_wind.z - 13.9) / (24.5 - 13.9), 0.0, 1.0);
    if (amount <= 0.0) return 0.0;
    vec2 along = u_wind.xy, across = vec2(-u_wind.y, u_wind.x);
    vec2 p = vec2(dot(xy, along) / 64.0, dot(xy, across) / 8.0);
    float n = 0.6 * value_noise(p) + 0.4 * value_noise(p * vec2(2.1, 2.7) + 5.2);
    float ridge = 1.0 - abs(2.0 * n - 1.0);
    float edge = 0.975 - 0.1 * amount;
    float lines = smoothstep(edge, edge + 0.02, ridge);
    float mean_cover = 0.03 + 0.22 * amount;
    return mix(lines, mean_cover, smoothstep(1.0, 5.0, footprint_m)) * (0.4 + 0.6 * amount);
}

// Foam where the water meets the hull: a ring a few metres wide outside the waterline (the waterplane mask
// blurred by its mip levels), whiter with speed and at the bow, where the stem throws the water up, the more so
// in head seas (the wind sea meeting the bow: its wind against the heading, from Beaufort 4 to 8).
float contact_foam(vec2 v, vec2 mask_uv) {
    if (u_wash.w == 0.0 || any(lessThan(mask_uv, vec2(0.0))) || any(greaterThan(mask_uv, vec2(1.0)))) return 0.0;
    float near = textureLod(u_hull_mask, mask_uv, 3.0).r;
    float ring = smoothstep(0.02, 0.3, near) * (1.0 - smoothstep(0.3, 0.5, near));
    float bow = smoothstep(0.75, 0.95, (v.x - u_hull_rect.x) * u_hull_rect.z);  // the forward quarter
    float head_seas = max(-dot(u_wind.xy, vec2(cos(u_track.z), sin(u_track.z))), 0.0)
                    * smoothstep(5.5, 17.2, u_wind.z);
    return ring * clamp(0.15 + u_wash.z / 6.0 + (0.5 + head_seas) * bow, 0.0, 1.0);
}

out vec4 f_colour;

// Glitter of a light towards l off facets of normal n, seen along v: a Beckmann lobe of the roughness, lit side only.
float glitter(vec3 n, vec3 l, vec3 v, float roughness) {
    vec3 h = normalize(l + v);
    float spec = exp(-pow(tan(acos(clamp(dot(n, h), 0.0, 1.0))) / roughness, 2.0)) / (roughness * roughness);
    return spec * max(dot(n, l), 0.0);
}

void main() {
    vec2 v_frame = vessel_frame(v_xy);
    vec2 mask_uv = (v_frame - u_hull_rect.xy) * u_hull_rect.zw;
    if (all(greaterThan(mask_uv, vec2(0.0))) && all(lessThan(mask_uv, vec2(1.0)))
        && textureLod(u_hull_mask, mask_uv, 0.0).r > 0.5) discard;

    vec2 slope = vec2(0.0);
    // The surface's Jacobian is the product of the cascades' held ones, each over its tile mean
    // (holding biases it low). Foam covers the part of the pixel's footprint where it is below
    // FOAM_J_START: a Gaussian of the footprint's mean and variance (from the mip levels) seen
    // through the linear breaking ramp, which widens the ramp by about one deviation.
    float folded = 1.0;
    float spread = 0.0;
    for (int i = 0; i < TILES; ++i) {
        vec3 uvw = vec3(v_xy / u_tile_size[i], float(i));
        slope += texture(u_slopes, uvw).xy;
        vec2 held = texture(u_foam, uvw).rg;          // mean of J and of J^2 under the footprint
        vec2 whole = textureLod(u_foam, uvw, 16.0).rg;  // ... over the whole tile
        // A footprint of more than 1/128 of its tile would show the tile's period: take the tile's
        // own statistics there, so that only the longer cascades place the foam.
        held = mix(held, whole, smoothstep(TILE_LOD - 7.0, TILE_LOD - 5.0, textureQueryLod(u_foam, uvw.xy).y));
        float tile_mean = max(whole.x, 0.5);  // a very steep sea holds its J low everywhere
        folded *= held.x / tile_mean;
        spread += max(held.y - held.x * held.x, 0.0) / (tile_mean * tile_mean);
    }
    vec3 local = local_slope_foam(v_xy);
    slope += local.xy;
    float deviation = sqrt(spread);
    float breaking = clamp((FOAM_J_START + deviation - folded) / (FOAM_J_START - FOAM_J_FULL + 2.0 * deviation),
                           0.0, 1.0);
    float vessel = max(local.z, max(wash_foam(v_frame), contact_foam(v_frame, mask_uv)));
    float streaks = streak_foam(v_xy, v_spacing);
    float foam = u_foam_on * (1.0 - (1.0 - breaking) * (1.0 - vessel) * (1.0 - streaks));

    vec3 to_eye = u_eye - v_position;
    float distance_m = length(to_eye);
    vec3 v = to_eye / distance_m;
    vec3 n = normalize(vec3(-slope, 1.0));
    n = normalize(n + v * max(0.0, 0.02 - dot(n, v)));  // no normals facing away from the eye
    float cos_theta = clamp(dot(n, v), 0.0, 1.0);
    float fresnel = F0 + (1.0 - F0) * pow(1.0 - cos_theta, 5.0);

    vec3 r = reflect(-v, n);
    r.z = abs(r.z);
    vec3 reflected = sky_colour(r);
    float crest = clamp(v_position.z * 0.25 + 0.3, 0.0, 1.0);
    vec3 sun = u_sun_colour * unclouded(u_sun);
    vec3 moon = u_moon_colour * unclouded(u_moon);
    float sun_in = max(dot(n, u_sun), 0.0);
    vec3 refracted = (DEEP + SCATTER * crest * (0.4 + 0.6 * sun_in) * pow(1.0 - cos_theta, 2.0)) * u_sky;
    float roughness = 0.06 + 0.002 * v_spacing;  // distant glitter spreads: unresolved waves
    vec3 lights = sun * glitter(n, u_sun, v, roughness);
    if (moon != vec3(0.0)) lights += moon * glitter(n, u_moon, v, roughness);
    vec3 colour = mix(refracted, reflected, fresnel) + fresnel * 0.25 * lights;
    colour = mix(colour, FOAM * (0.35 * u_sky + 0.7 * sun * sun_in + 0.7 * moon * max(dot(n, u_moon), 0.0)), foam);
    f_colour = finish(with_haze(colour, -v, distance_m));
}
