"""The renderer's parts on their own: the wake's appearance (NumPy, no GL), the program wrapper's uniform
names, the shaders' shared parts (the GPU FFT, the work-group size, the includes), and the layers composed by
the Renderer, each given every uniform its program declares."""

from __future__ import annotations

import dataclasses
import math
import re

import numpy as np
import pytest

from conftest import DEFAULT
from marinesim.hull import wigley_hull
from marinesim.render.wake_look import BREAKING_SLOPE, WAKE_SLOPE_FOAM, wake_appearance
from marinesim.wake.compute import WakeGrid, compute_wake

G = 9.80665
LENGTH_M = 100.0


@pytest.fixture(scope="module")
def wigley():
    return wigley_hull(LENGTH_M, 10.0, 6.25)


@pytest.fixture(scope="module")
def computed(wigley):
    """Wigley's wake at Fn 0.3: its waves and the local flow about the hull."""
    return compute_wake(wigley, 0.3 * math.sqrt(G * LENGTH_M), WakeGrid(256, 128))


@pytest.fixture(scope="module")
def gentle(computed):
    """Wigley's waves at Fn 0.3 alone: the steepest (99.9th percentile slope 0.16) stand below breaking."""
    return dataclasses.replace(computed, local=np.zeros_like(computed.local))


@pytest.fixture(scope="module")
def steep(gentle):
    """The same wake four times as high, as thin-ship theory gives a full hull: slopes past breaking."""
    return dataclasses.replace(gentle, elevation=4.0 * gentle.elevation)


def slope(look: np.ndarray) -> np.ndarray:
    return np.hypot(look[..., 1].astype(float), look[..., 2].astype(float))


def raw_slope(wake) -> np.ndarray:
    spacing = float(wake.x[1] - wake.x[0])
    dhdy, dhdx = np.gradient(np.asarray(wake.elevation, float), spacing)
    return np.hypot(dhdx, dhdy)


def test_a_gentle_wake_is_drawn_as_computed_and_a_steep_one_is_capped_at_breaking(gentle, steep):
    assert np.percentile(raw_slope(gentle), 99.9) < BREAKING_SLOPE < np.percentile(raw_slope(steep), 99.9)
    look = wake_appearance(gentle)
    assert look.shape == (*gentle.elevation.shape, 4) and look.dtype == np.float32
    np.testing.assert_array_equal(look[..., 0], gentle.elevation)
    for factor in (1.0, 2.0, 10.0):
        wake = dataclasses.replace(steep, elevation=factor * steep.elevation)
        capped = wake_appearance(wake)
        steepest = np.percentile(slope(capped), 99.9)
        assert steepest <= BREAKING_SLOPE * (1.0 + 1e-5)
        assert steepest == pytest.approx(BREAKING_SLOPE, rel=1e-4), "scaled below breaking: the wake is flattened"
        finite = np.abs(wake.elevation) > 1e-3
        scale = capped[..., 0][finite] / wake.elevation[finite]  # one factor over the whole field: the pattern kept
        assert np.ptp(scale) < 1e-5 * scale.mean()


def test_the_wakes_foam_only_where_its_waves_near_breaking(gentle, steep):
    lo, hi = WAKE_SLOPE_FOAM
    for wake in (gentle, steep):
        look = wake_appearance(wake)
        foam, s = look[..., 3], slope(look)
        assert foam.min() >= 0.0 and look[..., 3].max() <= 1.0
        assert np.all(foam[s < lo * (1.0 - 1e-4)] == 0.0), "foam on water that is not near breaking"
    breaking = s > hi * (1.0 + 1e-4)
    assert breaking.any() and np.all(foam[breaking] == 1.0), "the steep wake's breaking crests carry no full foam"


def test_the_local_flow_is_drawn_on_the_waves_and_no_cap_on_them_flattens_it(computed):
    """The drawn elevation is the (capped) waves plus the local flow: a wave field steep enough to be capped leaves
    the bow's rise as computed; a local flow as steep as breaking (five times Wigley's, as a bluff bow's) foams
    there and nowhere gentle."""
    steep = dataclasses.replace(computed, elevation=8.0 * computed.elevation)
    waves_only = wake_appearance(dataclasses.replace(steep, local=np.zeros_like(steep.local)))
    look = wake_appearance(steep)
    np.testing.assert_allclose(look[..., 0] - waves_only[..., 0], computed.local, atol=1e-5)
    assert computed.local.max() > 0.05 * np.abs(computed.elevation).max()   # Fn 0.3: a bow wave worth drawing
    bluff = dataclasses.replace(computed, elevation=np.zeros_like(computed.elevation), local=5.0 * computed.local)
    local_slope = np.hypot(*np.gradient(bluff.local.astype(float), float(computed.x[1] - computed.x[0])))
    breaking = local_slope > WAKE_SLOPE_FOAM[1] * 1.001
    foam = wake_appearance(bluff)[..., 3]
    assert breaking.any() and np.all(foam[breaking] == 1.0) and np.all(foam[local_slope < WAKE_SLOPE_FOAM[0]] == 0)


def test_the_slopes_are_the_gradient_of_the_drawn_elevation(gentle, steep):
    """d/dx along the columns (x forward) and d/dy along the rows (y to port), of the capped elevation."""
    for wake in (gentle, steep):
        look = wake_appearance(wake).astype(float)
        spacing = float(wake.x[1] - wake.x[0])
        h = look[..., 0]
        dhdx = (h[:, 2:] - h[:, :-2]) / (2.0 * spacing)
        dhdy = (h[2:, :] - h[:-2, :]) / (2.0 * spacing)
        tolerance = 1e-5 * slope(look).max()
        np.testing.assert_allclose(look[:, 1:-1, 1], dhdx, rtol=0, atol=tolerance)
        np.testing.assert_allclose(look[1:-1, :, 2], dhdy, rtol=0, atol=tolerance)


VERTEX = """#version 430
in vec2 in_pos;
uniform vec2 u_offset;                 // m
uniform float u_scale, u_unused_scale;
void main() { gl_Position = vec4(in_pos * u_scale + u_offset, 0.0, 1.0); }
"""
FRAGMENT = """#version 430
uniform vec4 u_colours[2];
/* uniform float u_commented; */
uniform highp float u_unused;
out vec4 f_colour;
void main() { f_colour = u_colours[0] + u_colours[1]; }
"""


def test_a_declared_uniform_the_compiler_dropped_is_skipped_and_an_undeclared_name_raises(gl_context):
    from marinesim.gl import Program

    program = Program(gl_context, "test", vertex_shader=VERTEX, fragment_shader=FRAGMENT)
    try:
        assert program.declared == {"u_offset", "u_scale", "u_unused_scale", "u_colours", "u_unused"}
        assert "u_unused" not in program.gl and "u_unused_scale" not in program.gl, "the compiler kept them"
        program.update({"u_unused": 1.0, "u_unused_scale": 2.0, "u_scale": 3.0, "u_offset": (1.0, 2.0)})
        colours = np.arange(8, dtype=np.float32)
        program["u_colours"] = colours.tobytes()
        assert program.gl["u_scale"].value == 3.0 and program.gl["u_offset"].value == (1.0, 2.0)
        assert np.frombuffer(program.gl["u_colours"].read(), np.float32).tolist() == colours.tolist()
        for name in ("u_colour", "u_commented", "in_pos"):
            with pytest.raises(ValueError, match=f"the test program declares no uniform '{name}'"):
                program[name] = 1.0
    finally:
        program.release()


def test_a_shaders_uniforms_are_read_after_its_includes(gl_context):
    """ocean.frag declares some uniforms itself and gets others from surface.glsl and sky.glsl."""
    from marinesim.gl import Program

    program = Program.from_files(gl_context, "ocean", TILES=2, TILE_LOD="8.0", FOAM_J_START=0.9, FOAM_J_FULL=0.6)
    try:
        expected = {"u_tile_size", "u_hull_mask", "u_solver_cell", "u_wake_rect1", "u_sun", "u_visibility"}
        assert expected <= program.declared
        with pytest.raises(ValueError, match="ocean.*'u_solver_cells'"):
            program["u_solver_cells"] = 1.0
    finally:
        program.release()


@pytest.mark.parametrize("n, fields, normalised", [(32, 3, False), (1024, 1, True)])
def test_the_gpu_fft_is_numpys_transform_of_every_field(gl_context, n, fields, normalised):
    """A row and a column pass of GpuFFT make NumPy's 2-D DFT of each field of a batch; the inverse passes give
    the fields back, times n^2 unless normalised (the cascades' unnormalised inverse, the solver's normalised one).
    1024 points take more than one sweep of the work group's threads."""
    from marinesim.gl import GpuFFT

    rng = np.random.default_rng(3)
    z = (rng.standard_normal((fields, n, n)) + 1j * rng.standard_normal((fields, n, n))).astype(np.complex64)
    fft = GpuFFT(gl_context, n, fields=fields, normalised=normalised)
    first, second = gl_context.buffer(z.tobytes()), gl_context.buffer(reserve=z.nbytes)
    try:
        fft.lines(first, second, rows=True)
        fft.lines(second, first, rows=False)
        spectrum = np.frombuffer(first.read(), np.complex64).reshape(z.shape)
        expected = np.fft.fft2(z.astype(complex))
        assert np.abs(spectrum - expected).max() <= 1e-5 * np.abs(expected).max()
        fft.lines(first, second, rows=True, inverse=True)
        fft.lines(second, first, rows=False, inverse=True)
        back = np.frombuffer(first.read(), np.complex64).reshape(z.shape)
        assert np.abs(back - z * (1 if normalised else n * n)).max() <= 1e-5 * np.abs(z).max() * (1 if normalised
                                                                                                 else n * n)
    finally:
        for thing in (fft, first, second):
            thing.release()


def test_every_compute_shader_takes_its_work_group_size_from_python():
    """No literal work-group size in a compute shader: GROUP (gl.py) or the FFT's THREADS, both injected."""
    from marinesim.gl import SHADER_DIR

    shaders = sorted(SHADER_DIR.glob("*.comp"))
    assert len(shaders) >= 6
    for path in shaders:
        layout = re.search(r"layout\(([^)]*local_size[^)]*)\)\s*in;", path.read_text()).group(1)
        assert not re.search(r"=\s*\d", layout), f"{path.name}: {layout}"


def test_no_glsl_function_is_defined_in_two_shader_files():
    """A function several shaders need lives in one include (complex.glsl, sky.glsl, surface.glsl)."""
    from marinesim.gl import SHADER_DIR

    defined: dict[str, list[str]] = {}
    for path in sorted(SHADER_DIR.iterdir()):
        for name in re.findall(r"^\w+\s+(\w+)\s*\([^)]*\)\s*\{", path.read_text(), re.MULTILINE):
            defined.setdefault(name, []).append(path.name)
    repeated = {name: files for name, files in defined.items() if len(files) > 1 and name != "main"}
    assert not repeated
    assert len(defined["cmul"]) == 1 and len(defined["main"]) >= 20


def test_every_layer_gives_its_program_every_uniform_it_declares(gl_context, monkeypatch):
    """One update and draw of the default scenario: the sky, ocean, vessel and foam programs are given every
    uniform they declare (images are bound by their layout instead), and the ocean's samplers distinct units."""
    from marinesim.gl import Program
    from marinesim.render.camera import OrbitCamera
    from marinesim.render.renderer import Renderer
    from marinesim.scenario import load_scenario
    from marinesim.session.timeline import Simulation

    given: dict[str, dict[str, object]] = {}
    setter = Program.__setitem__

    def record(program, name, value):
        given.setdefault(program.name, {})[name] = value
        setter(program, name, value)

    monkeypatch.setattr(Program, "__setitem__", record)
    sim = Simulation(load_scenario(DEFAULT), wake=False)
    renderer = Renderer(gl_context, sim)
    target = gl_context.simple_framebuffer((64, 36))
    try:
        target.use()
        sim.advance(0.5)
        renderer.update()
        renderer.draw(OrbitCamera(distance_m=500.0).eye(sim.pose()), (64, 36))
        assert gl_context.error == "GL_NO_ERROR"
        programs = {layer.program.name: layer.program for layer in (renderer.sky, renderer.ocean, renderer.vessel,
                                                                    renderer.foam)}
        for name, program in programs.items():
            assert program.declared - {"u_held"} == set(given[name]), name
        samplers = ("u_cascades", "u_slopes", "u_foam", "u_wake0", "u_wake1", "u_solver", "u_hull_mask")
        assert sorted(given["ocean"][s] for s in samplers) == list(range(len(samplers)))
    finally:
        target.release()
        renderer.release()
        sim.close()
