"""The sky's functions (shaders/sky.glsl), run on a real OpenGL context.

The haze the picture is drawn in obeys the meteorological definition of visibility
(Koschmieder, WMO): a dark object's contrast against the horizon sky falls as exp(-sigma d) and reaches the
threshold 0.05 at the visibility, so sigma = ln(20) / V. Run on a real OpenGL context: the shader's own
with_haze() on a black object at distances d, against its haze_colour()."""

from __future__ import annotations

import math

import numpy as np
import pytest

from marinesim.gl import SHADER_DIR
from marinesim.render.daylight import light_at
from marinesim.scenario.model import EnvironmentOptions

VERTEX = """#version 430
void main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2); gl_Position = vec4(2.0 * p - 1.0, 0, 1); }
"""
FRAGMENT = """#version 430
{sky}
uniform float u_distance;
out vec4 f_colour;
void main() {{
    vec3 d = normalize(vec3(1.0, 0.2, -0.01));  // towards the horizon
    f_colour = vec4(with_haze(vec3(0.0), d, u_distance).g, haze_colour(d).g, 0.0, 1.0);
}}
"""


def contrast(ctx, visibility_m: float, distance_m: float) -> float:
    """(L_object - L_haze) / L_haze of a black object seen at ``distance_m``, in linear radiance."""
    sky = (SHADER_DIR / "sky.glsl").read_text()
    program = ctx.program(vertex_shader=VERTEX, fragment_shader=FRAGMENT.format(sky=sky))
    light = light_at(EnvironmentOptions(visibility_m=visibility_m))
    for name, value in light.uniforms().items():
        if name in program:
            program[name].value = value
    program["u_distance"].value = distance_m
    target = ctx.simple_framebuffer((1, 1), components=4, dtype="f4")
    target.use()
    ctx.vertex_array(program, []).render(vertices=3)
    obj, haze = np.frombuffer(target.read(components=4, dtype="f4"), np.float32)[:2]
    program.release()
    target.release()
    return float((obj - haze) / haze)


@pytest.mark.parametrize("visibility_m", [1_000.0, 10_000.0, EnvironmentOptions().visibility_m])
def test_a_dark_object_keeps_five_percent_of_its_contrast_at_the_visibility(gl_context, visibility_m):
    """At the visibility the contrast is -0.05 (not -exp(-1) = -0.37, which an e-folding length would give: the
    same figure then drew the air four times as clear); at half of it, sqrt(0.05)."""
    assert contrast(gl_context, visibility_m, visibility_m) == pytest.approx(-0.05, rel=1e-4)
    assert contrast(gl_context, visibility_m, visibility_m / 2) == pytest.approx(-math.sqrt(0.05), rel=1e-4)
    assert contrast(gl_context, visibility_m, 0.0) == pytest.approx(-1.0, rel=1e-6)


CLOUD_PROGRAM = """#version 430
{sky}
uniform int u_columns;
out vec4 f_colour;
void main() {{
    // pixel (i, j) looks at azimuth 2 pi i / columns and at elevation from 10 to 80 deg, evenly in sin
    float azimuth = 6.2831853 * (gl_FragCoord.x / float(u_columns));
    float z = mix(0.17, 0.98, gl_FragCoord.y / 64.0);
    vec3 d = vec3(sqrt(1.0 - z * z) * cos(azimuth), sqrt(1.0 - z * z) * sin(azimuth), z);
    f_colour = vec4(cloud_along(d), 0.0, 0.0, 1.0);
}}
"""


def cloud_share(ctx, oktas: float) -> float:
    """The share of the sky between 10 and 80 deg up that the clouds of sky.glsl cover (solid-angle weighted)."""
    program = ctx.program(vertex_shader=VERTEX,
                          fragment_shader=CLOUD_PROGRAM.format(sky=(SHADER_DIR / "sky.glsl").read_text()))
    for name, value in light_at(EnvironmentOptions(cloud_cover_oktas=oktas)).uniforms().items():
        if name in program:
            program[name].value = value
    program["u_columns"].value = 512
    target = ctx.simple_framebuffer((512, 64), components=4, dtype="f4")
    target.use()
    ctx.vertex_array(program, []).render(vertices=3)
    cover = np.frombuffer(target.read(components=4, dtype="f4"), np.float32).reshape(64, 512, 4)[..., 0]
    program.release()
    target.release()
    return float(cover.mean())


@pytest.mark.parametrize("oktas", [0, 1, 2, 4, 6, 7, 8])
def test_the_clouds_cover_the_share_of_the_sky_the_oktas_say(gl_context, oktas):
    """An observer reports cover in eighths of the sky: the drawn clouds cover oktas / 8 of it within an eighth."""
    assert cloud_share(gl_context, oktas) == pytest.approx(oktas / 8.0, abs=0.1)


FINITE_PROGRAM = """#version 430
{sky}
out vec4 f_colour;
void main() {{
    // column i: azimuth 2 pi i / 720 (0.5 deg steps, the sun's own azimuth and its opposite among them); row j:
    // elevation from -10 to 80 deg
    float azimuth = 6.2831853 * floor(gl_FragCoord.x) / 720.0;
    float elevation = radians(mix(-10.0, 80.0, gl_FragCoord.y / 64.0));
    vec3 d = vec3(cos(elevation) * cos(azimuth), cos(elevation) * sin(azimuth), sin(elevation));
    f_colour = vec4(sky_colour(d), 1.0);
}}
"""


@pytest.mark.parametrize("air", [{}, {"sun_elevation_deg": -3.0, "sun_azimuth_deg": 270.0},
                                 {"sun_elevation_deg": 12.0, "sun_azimuth_deg": 240.0, "cloud_cover_oktas": 7.0},
                                 {"sun_elevation_deg": -40.0, "cloud_cover_oktas": 8.0}])
def test_the_sky_is_finite_and_positive_in_every_direction(gl_context, air):
    """Every direction, straight away from the sun included (where a rounding below -1 in a dot product once made
    pow() of a negative number: black pixels in a line across the picture), has a finite, positive colour."""
    program = gl_context.program(vertex_shader=VERTEX,
                                 fragment_shader=FINITE_PROGRAM.format(sky=(SHADER_DIR / "sky.glsl").read_text()))
    for name, value in light_at(EnvironmentOptions(**air)).uniforms().items():
        if name in program:
            program[name].value = value
    target = gl_context.simple_framebuffer((720, 64), components=4, dtype="f4")
    target.use()
    gl_context.vertex_array(program, []).render(vertices=3)
    colour = np.frombuffer(target.read(components=4, dtype="f4"), np.float32).reshape(64, 720, 4)[..., :3]
    program.release()
    target.release()
    assert np.isfinite(colour).all() and (colour > 0.0).all()
