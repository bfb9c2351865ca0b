"""The local wave solver on Mesa's software OpenGL and in NumPy: the GPU solver equals
the reference; deep-water dispersion; the Kelvin angle of a moving pressure point; the sponge; the
rings of a heaving hull; stability, scrolling and resets. The hull's displaced depth is in
test_solver_footprint.py."""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest
import trimesh

from marinesim.constants import G
from marinesim.errors import ParameterError
from marinesim.hull.mesh import make_hull
from marinesim.hull.shapes import box_hull, wigley_hull
from marinesim.pose import Pose
from marinesim.solver import ReferenceSolver, SolverConfig
from marinesim.solver.gpu import GpuSolver
from marinesim.wake.measure import KELVIN_HALF_ANGLE_DEG, kelvin_half_angle_deg


@pytest.fixture(scope="module")
def ctx(gl_context):
    return gl_context


def plane_packet(size: int, cell: float, mode: tuple[int, int], across: float = math.inf) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A Gaussian packet (1.5 wavelengths rms, at most a tenth of the grid; ``across`` m rms
    sideways) of the grid wave ``mode`` (cycles across the grid in x, y), travelling along its
    wavevector only: ``(h, phi, k0)``. phi is built per wavenumber from the dispersion relation, so
    no part of the packet travels backwards."""
    k0 = 2.0 * math.pi * np.array(mode) / (size * cell)
    sigma = min(1.5 * 2.0 * math.pi / np.linalg.norm(k0), 0.1 * size * cell)
    x = (np.arange(size) + 0.5) * cell
    xx, yy = np.meshgrid(x - x.mean(), x - x.mean())
    along = (xx * k0[0] + yy * k0[1]) / np.linalg.norm(k0)
    sideways = (yy * k0[0] - xx * k0[1]) / np.linalg.norm(k0)
    h = np.exp(-0.5 * (along / sigma) ** 2 - 0.5 * (sideways / across) ** 2) * np.cos(k0[0] * xx + k0[1] * yy)
    k1 = 2.0 * math.pi * np.fft.fftfreq(size, cell)
    kx, ky = np.meshgrid(k1, k1)
    k = np.hypot(kx, ky)
    forward = np.sign(kx * k0[0] + ky * k0[1])
    with np.errstate(divide="ignore", invalid="ignore"):
        phi_hat = np.where(k > 0, -1j * forward * np.sqrt(G * k) * np.fft.fft2(h) / k, 0.0)
    return h, np.fft.ifft2(phi_hat).real, k0


def travelling_energy(h: np.ndarray, phi: np.ndarray, cell: float, direction: np.ndarray) -> tuple[float, float]:
    """Energy (arbitrary units) of the waves travelling with and against ``direction``: each
    wavenumber's field split into ``exp(i(k.x - w t))`` (along +k) and ``exp(i(k.x + w t))`` parts."""
    size = h.shape[0]
    k1 = 2.0 * math.pi * np.fft.fftfreq(size, cell)
    kx, ky = np.meshgrid(k1, k1)
    k = np.hypot(kx, ky)
    omega = np.sqrt(G * k)
    omega[0, 0] = 1.0
    h_hat, phi_hat = np.fft.fft2(h), np.fft.fft2(phi)
    plus = 0.5 * (h_hat + 1j * k * phi_hat / omega)
    minus = 0.5 * (h_hat - 1j * k * phi_hat / omega)
    ahead = kx * direction[0] + ky * direction[1] > 0
    behind = kx * direction[0] + ky * direction[1] < 0
    forward = np.sum(np.abs(plus[ahead]) ** 2) + np.sum(np.abs(minus[behind]) ** 2)
    backward = np.sum(np.abs(plus[behind]) ** 2) + np.sum(np.abs(minus[ahead]) ** 2)
    return float(forward), float(backward)


def moving_wigley_pose(t: float) -> Pose:
    """4 m/s on a heading of 0.3 rad, heaving, rolling and pitching."""
    return Pose(4.0 * math.cos(0.3) * t, 4.0 * math.sin(0.3) * t, 0.3,
                    (0.0, 0.0, 0.15 * math.sin(2.0 * t), 0.08 * math.sin(1.3 * t), 0.04 * math.cos(1.7 * t), 0.0))


# --- 1. GPU = reference -----------------------------------------------------------------------
def test_gpu_solver_equals_the_numpy_reference_after_500_steps_with_a_moving_hull(ctx):
    """Any difference in the shaders' numerics (FFT, rotation, depth render, sponge, scrolling)
    would show as an error far above float32 round-off (1e-4 of the peak)."""
    config = SolverConfig(size=128, cell_m=0.5, forcing="full")
    hull = wigley_hull(10.0, 1.5, 0.8, nx=20, nz=5)
    gpu = GpuSolver(config, hull, moving_wigley_pose(0.0), ctx=ctx)
    reference = ReferenceSolver(config, hull, moving_wigley_pose(0.0))
    frame = 1.0 / 30.0
    t = 0.0
    start = reference.origin
    while reference.steps < 500:
        t += frame
        gpu.step(frame, moving_wigley_pose(t))
        reference.step(frame, moving_wigley_pose(t))
    assert gpu.steps == reference.steps >= 500
    assert gpu.origin == reference.origin and reference.origin[0] - start[0] > 20.0  # the grid followed the hull
    h_gpu, h_reference = gpu.height(), reference.height()
    peak = np.abs(h_reference).max()
    assert peak > 0.05
    assert np.abs(h_gpu - h_reference).max() <= 1e-4 * peak
    depth_gpu, depth_reference = gpu.depth, reference.depth
    assert np.abs(depth_gpu - depth_reference).max() <= 1e-4 * depth_reference.max()
    texture = np.frombuffer(gpu.height_texture.read(), dtype=np.float32).reshape(h_gpu.shape)
    assert np.array_equal(texture, h_gpu.astype(np.float32))                   # what the renderer samples
    gpu.release()


# --- 2. dispersion ------------------------------------------------------------------------------
def measured_phase_speed(solver, mode: tuple[int, int]) -> tuple[float, float]:
    """``(measured, sqrt(g / k))``: the carrier's phase (projection on the grid wave) over three periods."""
    size, cell = solver.config.size, solver.config.cell_m
    h, phi, k0 = plane_packet(size, cell, mode)
    solver.set_fields(h, phi)
    x = (np.arange(size) + 0.5) * cell
    xx, yy = np.meshgrid(x, x)
    carrier = np.exp(-1j * (k0[0] * xx + k0[1] * yy))
    k = float(np.linalg.norm(k0))
    period = 2.0 * math.pi / math.sqrt(G * k)
    phases, times = [np.angle(np.sum(solver.height() * carrier))], [solver.time]
    while solver.time < 3.0 * period:
        solver.step(0.2 * period)
        phases.append(np.angle(np.sum(solver.height() * carrier)))
        times.append(solver.time)
    omega = -np.polyfit(times, np.unwrap(phases), 1)[0]
    return omega / k, math.sqrt(G / k)


@pytest.mark.parametrize("mode", [(32, 0), (16, 16), (6, 8), (4, 0)])   # 8, 11.3, 25.6, 64 cells; 0, 45, 53, 0 deg
def test_a_plane_packet_travels_at_the_deep_water_phase_speed(mode):
    """The carrier moves at sqrt(g / k) for every wavelength from 8 cells to a quarter of the grid
    and in any direction (a five-point Laplacian would be 10 % slow at 8 cells; a non-dispersive
    solver has one speed for all)."""
    solver = ReferenceSolver(SolverConfig(size=256, cell_m=0.5, sponge_cells=0, max_speed_m_s=1.0))
    measured, theory = measured_phase_speed(solver, mode)
    assert measured == pytest.approx(theory, rel=0.03)


def test_the_gpu_solver_has_the_same_phase_speed(ctx):
    solver = GpuSolver(SolverConfig(size=64, cell_m=0.5, sponge_cells=0, max_speed_m_s=1.0), ctx=ctx)
    measured, theory = measured_phase_speed(solver, (4, 4))
    assert measured == pytest.approx(theory, rel=0.03)
    solver.release()


# --- 3. Kelvin angle ------------------------------------------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("speed", [2.5, 5.0])
def test_a_moving_pressure_point_leaves_a_kelvin_wake_at_any_speed(speed):
    """A small hemisphere (radius 1 m, much smaller than the waves it makes) towed at 2.5 and at
    5 m/s: the cusp lines stand at 19.47 deg (+/- 2) at both. A non-dispersive solver would draw a
    Mach cone asin(c / U) whose angle halves when the speed doubles."""
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=1.0)
    point = make_hull(sphere.vertices, sphere.faces, "pressure point")
    config = SolverConfig(size=512, cell_m=0.5, forcing="full", max_speed_m_s=speed)
    solver = ReferenceSolver(config, point)
    frame = 0.1
    t = 0.0
    while speed * t < 0.9 * solver.extent_m:
        t += frame
        solver.step(frame, Pose(x=speed * t))
    x, y = solver.cell_centres()
    inner = slice(config.sponge_width, -config.sponge_width)        # the sponge is not open water
    wavelength = 2.0 * math.pi * speed ** 2 / G
    angle = kelvin_half_angle_deg(solver.height()[inner, inner], x[inner] - speed * t, y[inner], wavelength,
                                  hull_length=2.0, bow_x=1.0, along=1.0)
    assert angle == pytest.approx(KELVIN_HALF_ANGLE_DEG, abs=2.0)


# --- 4. sponge ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("cells", [4, 8, 16, 32])
def test_the_sponge_reflects_at_most_three_percent(cells):
    """A packet sent into the default sponge (32 cells at 256), wavelengths 4 cells to the sponge's
    width: the amplitude coming back (waves travelling the other way) stays under 3 % of the
    incident one, and what passes through to the other side (the grid is periodic) under 3 % too."""
    size, cell = 256, 1.0
    solver = ReferenceSolver(SolverConfig(size=size, cell_m=cell, damping_s=None, max_speed_m_s=1.0))
    assert solver.config.sponge_width == 32
    h, phi, k0 = plane_packet(size, cell, (size // cells, 0))
    solver.set_fields(h, phi)
    direction = k0 / np.linalg.norm(k0)
    incident, _ = travelling_energy(h, phi, cell, direction)
    k = float(np.linalg.norm(k0))
    group_speed = 0.5 * math.sqrt(G / k)
    sigma = min(1.5 * cells, 0.1 * size) * cell
    reflected = 0.0
    while solver.time < 1.5 * (0.5 * size * cell + 4.0 * sigma) / group_speed:
        solver.step(10 * solver.substep)
        _, backward = travelling_energy(*solver.fields(), cell, direction)
        reflected = max(reflected, math.sqrt(backward / incident))
    through, _ = travelling_energy(*solver.fields(), cell, direction)
    assert reflected <= 0.03
    assert math.sqrt(through / incident) <= 0.03


# --- 5. radiation -----------------------------------------------------------------------------------
def test_a_heaving_hull_radiates_rings_of_the_deep_water_wavelength():
    """A 6 x 3 x 1 m box heaving 0.1 m at 2.5 rad/s: the phase of the radiated field (demodulated at
    the heave frequency) grows along x, y and the diagonal at k = w^2 / g, i.e. the rings are
    2 pi g / w^2 = 9.86 m apart (3 %)."""
    omega = 2.5
    config = SolverConfig(size=256, cell_m=0.5, max_speed_m_s=1.0)
    solver = ReferenceSolver(config, box_hull(6.0, 3.0, 1.0))
    period = 2.0 * math.pi / omega
    frame = period / 16.0
    t = 0.0

    def heave(t: float) -> Pose:
        return Pose(motion=(0.0, 0.0, 0.1 * math.sin(omega * t), 0.0, 0.0, 0.0))

    while t < 30.0:                                   # the rings reach the sponge and settle
        t += frame
        solver.step(frame, heave(t))
    harmonic = np.zeros((config.size, config.size), dtype=complex)
    for _ in range(32):
        t += frame
        solver.step(frame, heave(t))
        harmonic += solver.height() * np.exp(1j * omega * solver.time)
    x, _ = solver.cell_centres()
    centre = config.size // 2
    reach = 0.5 * solver.extent_m - config.sponge_width * config.cell_m
    expected = 2.0 * math.pi * G / omega ** 2
    for line, distance in ((harmonic[:, centre], x), (harmonic[centre, :], x), (np.diagonal(harmonic), x * math.sqrt(2.0))):
        sel = (distance > 6.0) & (distance < reach)
        slope = np.polyfit(distance[sel], np.unwrap(np.angle(line[sel])), 1)[0]
        assert 2.0 * math.pi / abs(slope) == pytest.approx(expected, rel=0.03)


# --- 6. stability, scrolling, resets ------------------------------------------------------------------
def random_sea(size: int, seed: int = 1) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    return 0.1 * rng.normal(size=(size, size)), 0.1 * rng.normal(size=(size, size))


@pytest.mark.slow
def test_without_damping_100000_steps_conserve_energy_and_stay_bounded_with_an_obstacle():
    """Damping and sponge off, white noise (every wavenumber the grid holds) for 10^5 sub-steps:
    the energy stays what it was (1e-6: the rotation is exact). With a quay in the water (surface
    held still inside, which is not exactly energy-conserving: the kinetic energy is non-local)
    it stays bounded: never above its start at any of 1000 checks."""
    config = SolverConfig(size=32, cell_m=1.0, damping_s=None, sponge_cells=0, max_speed_m_s=1.0)
    quay = np.array([[12.0, 12.0], [18.0, 12.0], [18.0, 20.0], [12.0, 20.0]])
    for obstacles in ((), (quay,)):
        solver = ReferenceSolver(config, obstacles=obstacles)
        solver.set_fields(*random_sea(config.size))
        solver.step(solver.substep)
        start, largest = solver.energy(), 0.0
        for _ in range(1000):
            solver.step(100 * solver.substep)
            largest = max(largest, solver.energy())
        assert solver.steps >= 100_000 and solver.resets == 0
        assert np.all(np.isfinite(solver.height()))
        if obstacles:
            assert largest <= start * (1.0 + 1e-9)
        else:
            assert largest == pytest.approx(start, rel=1e-6)
            assert solver.energy() == pytest.approx(start, rel=1e-6)


@pytest.mark.slow
def test_the_gpu_solver_stays_finite_and_bounded_over_100000_float32_steps(ctx):
    """The same on the GPU in float32: rounding never pumps energy in (never 1e-4 above the start at
    any of 100 checks) and takes little out (under 5 % in 10^5 steps; about 1e-7 per step is
    float32 round-off)."""
    config = SolverConfig(size=16, cell_m=1.0, damping_s=None, sponge_cells=0, max_speed_m_s=1.0)
    solver = GpuSolver(config, ctx=ctx)
    solver.set_fields(*random_sea(config.size))
    start = solver.energy()
    for _ in range(100):
        solver.step(1000 * solver.substep)
        assert solver.energy() <= start * (1.0 + 1e-4)
    assert solver.steps >= 100_000 and solver.resets == 0
    assert np.all(np.isfinite(solver.height()))
    assert solver.energy() >= 0.95 * start
    solver.release()


@pytest.mark.parametrize("backend", ["gpu", "reference"])
def test_a_vessel_on_a_steady_course_drives_the_solver_only_in_full_forcing(ctx, backend):
    """A Wigley hull at 20 m/s on a turning course without motions, the grid scrolling 240 cells:
    with unsteady forcing (the Kelvin field carries the steady wake) the water stays exactly at
    rest, so the steady wake is not drawn twice; with full forcing the same run makes a wake."""
    hull = wigley_hull(10.0, 1.5, 0.8, nx=20, nz=5)
    peaks = {}
    for forcing in ("unsteady", "full"):
        config = SolverConfig(size=64, cell_m=0.5, forcing=forcing)
        solver = GpuSolver(config, hull, ctx=ctx) if backend == "gpu" else ReferenceSolver(config, hull)
        t, frame = 0.0, 1.0 / 60.0
        while t < 6.0:
            t += frame
            solver.step(frame, Pose(20.0 * t, 0.5 * t * t, 0.2 * t))
        assert solver.origin[0] > 100.0
        h = solver.height() + solver.depth           # the surface minus the hull's static hollow
        peaks[forcing] = np.abs(h[config.sponge_width:-config.sponge_width, config.sponge_width:-config.sponge_width]).max()
    assert peaks["unsteady"] == 0.0
    assert peaks["full"] > 0.05


def test_a_vessel_that_jumps_finds_the_water_at_rest_where_it_lands(caplog):
    """A scenario reset moves the vessel 2 km in one frame: the grid is placed there and the water
    starts at rest about the hull (h = -d), instead of the hull being dragged 2 km through it."""
    config = SolverConfig(size=64, cell_m=0.5, forcing="full")
    solver = ReferenceSolver(config, wigley_hull(10.0, 1.5, 0.8, nx=20, nz=5))
    for n in range(1, 31):
        solver.step(1.0 / 30.0, Pose(x=8.0 * n / 30.0, motion=(0.0, 0.0, 0.1, 0.0, 0.0, 0.0)))
    with caplog.at_level(logging.INFO, logger="marinesim.solver"):
        solver.step(1.0 / 30.0, Pose(x=2000.0, y=5.0))
    assert "jumped" in caplog.text
    assert abs(solver.origin[0] + 0.5 * solver.extent_m - 2000.0) <= 0.5 * config.cell_m
    assert np.array_equal(solver.height(), -solver.depth * solver.sponge)
    assert solver.depth.sum() > 0.0


def test_the_gpu_solver_is_reproducible(ctx):
    """The same run twice on the GPU gives the same field bit for bit."""
    config = SolverConfig(size=64, cell_m=0.5, forcing="full")
    hull = wigley_hull(10.0, 1.5, 0.8, nx=20, nz=5)
    fields = []
    for _ in range(2):
        solver = GpuSolver(config, hull, moving_wigley_pose(0.0), ctx=ctx)
        for n in range(1, 31):
            solver.step(1.0 / 30.0, moving_wigley_pose(n / 30.0))
        fields.append(solver.height())
        solver.release()
    assert np.abs(fields[0]).max() > 0.01
    assert np.array_equal(fields[0], fields[1])


@pytest.mark.parametrize("backend, tolerance", [("reference", 1e-8), ("gpu", 1e-5)])
def test_scrolling_moves_the_field_without_changing_it(ctx, backend, tolerance):
    """A packet in a grid that scrolls about 20 cells sideways equals the same packet in a grid that
    stays, at the same world positions (float64: 1e-8 of the peak, where the packet's far tails meet
    the moved sponge at 1e-9; float32 over 60 sub-steps of FFTs of differently placed data: 1e-5).
    A scroll that dropped or doubled a row, or moved the water, would differ by the wave itself."""
    config = SolverConfig(size=128, cell_m=0.5, sponge_cells=8, max_speed_m_s=5.0)
    h, phi, _ = plane_packet(config.size, config.cell_m, (16, 0), across=2.0)
    make = (lambda: GpuSolver(config, ctx=ctx)) if backend == "gpu" else (lambda: ReferenceSolver(config))
    still, moving = make(), make()
    for solver in (still, moving):
        solver.set_fields(h, phi)
    for frame in range(1, 11):
        still.step(0.2)
        moving.step(0.2, Pose(y=1.0 * frame))
    shift = round((moving.origin[1] - still.origin[1]) / config.cell_m)
    assert shift >= 15
    a, b = still.height()[shift:], moving.height()[:-shift]
    assert np.abs(a - b).max() <= tolerance * np.abs(a).max()


@pytest.mark.parametrize("backend", ["gpu", "reference"])
def test_a_non_finite_value_resets_the_field_to_rest_and_is_reported(ctx, backend, caplog):
    """One NaN would spread through the whole grid in one FFT; instead the field is reset to rest
    (about the hull: h = -d under it, 0 elsewhere), counted, and logged."""
    config = SolverConfig(size=64, cell_m=0.5, forcing="full")
    hull = wigley_hull(10.0, 1.5, 0.8, nx=20, nz=5)
    solver = GpuSolver(config, hull, ctx=ctx) if backend == "gpu" else ReferenceSolver(config, hull)
    h, phi = random_sea(config.size)
    h[5, 7] = np.nan
    solver.set_fields(h, phi)
    with caplog.at_level(logging.WARNING, logger="marinesim.solver"):
        solver.step(0.1)
    assert solver.resets == 1
    assert "non-finite" in caplog.text
    assert solver.depth.max() > 0.5
    assert np.abs(solver.height() + solver.depth).max() <= 1e-6
    solver.step(0.1)
    assert solver.resets == 1


def test_stepping_is_independent_of_the_frame_rate_and_reproducible():
    """Fixed sub-steps: the same motion shown at 60, 7 and 2 frames per second gives the same field
    (the pose is linear in time, so every sub-step sees the same hull); the same run twice is
    bit-identical."""
    config = SolverConfig(size=64, cell_m=0.5, forcing="full")
    hull = wigley_hull(10.0, 1.5, 0.8, nx=20, nz=5)
    fields = []
    for frame in (1.0 / 60.0, 1.0 / 7.0, 0.5, 0.5):
        solver = ReferenceSolver(config, hull)
        t = 0.0
        while t < 3.0 - 1e-9:
            t += frame
            solver.step(frame, Pose(x=12.3 * t, y=-3.1 * t))   # never exactly on a cell boundary, where rounding picks the grid
        fields.append((solver.time, solver.height()))
    times = [time for time, _ in fields]
    assert max(times) - min(times) < 1e-9
    peak = np.abs(fields[0][1]).max()
    for _, h in fields[1:]:
        assert np.abs(h - fields[0][1]).max() <= 1e-9 * peak
    assert np.array_equal(fields[2][1], fields[3][1])


def test_sub_steps_follow_from_the_speed_limit_and_the_fastest_wave():
    """At most half a cell of hull travel and a quarter period of the fastest grid wave per sub-step."""
    config = SolverConfig(size=64, cell_m=0.5)
    solver = ReferenceSolver(config)
    omega_max = math.sqrt(G * math.pi * math.sqrt(2.0) / config.cell_m)
    assert solver.substep * config.max_speed_m_s <= 0.5 * config.cell_m + 1e-12
    assert solver.substep * omega_max <= 0.5 * math.pi + 1e-12
    slow = ReferenceSolver(SolverConfig(size=64, cell_m=0.5, max_speed_m_s=0.5))
    assert slow.substep * omega_max == pytest.approx(0.5 * math.pi)


# --- bad input ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("options, named", [
    (dict(size=500), "power of two"), (dict(size=4096), "power of two"), (dict(cell_m=0.0), "cell size"),
    (dict(cell_m=float("nan")), "cell size"), (dict(damping_s=-1.0), "damping"), (dict(sponge_cells=200), "sponge"),
    (dict(max_speed_m_s=25.0), "maximum speed"), (dict(forcing="steady"), "forcing"),
])
def test_bad_solver_settings_are_refused_by_name(options, named):
    with pytest.raises(ParameterError, match=named):
        SolverConfig(**options)


def test_bad_steps_poses_fields_and_obstacles_are_refused():
    solver = ReferenceSolver(SolverConfig(size=32, cell_m=1.0))
    for dt in (0.0, -0.1, float("nan")):
        with pytest.raises(ParameterError, match="time step"):
            solver.step(dt)
    with pytest.raises(ParameterError, match="pose"):
        solver.step(0.1, Pose(x=float("nan")))
    with pytest.raises(ParameterError, match="fields"):
        solver.set_fields(np.zeros((16, 16)), np.zeros((16, 16)))
    with pytest.raises(ParameterError, match="obstacle"):
        ReferenceSolver(SolverConfig(size=32, cell_m=1.0), obstacles=(np.zeros((2, 2)),))

