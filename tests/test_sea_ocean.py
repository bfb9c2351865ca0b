"""The ocean on FFT cascades: synthesis, statistics, kinematics, reproducibility."""

import json
import math
import os
import subprocess
import sys
import threading
import tracemalloc

import numpy as np
import pytest
from scipy import integrate, optimize

from marinesim.angles import wave_beta_from_compass
from marinesim.constants import G
from marinesim.errors import ParameterError
from marinesim.recent import Recent
from marinesim.sea import (
    Cos2s,
    Jonswap,
    LongCrested,
    Ocean,
    PiersonMoskowitz,
    RegularWave,
    SeaState,
    Tma,
    WaveSystem,
    choose_tiles,
)
from marinesim.sea.cascades import TILE_RATIO
from marinesim.sea.dispersion import omega_from_k
from marinesim.sea.fft import available_cpus, mirrored
from marinesim.sea.summary import surface_summary
from marinesim.sea.synthesis import Lane, _jacobian, _pack_cells
from conftest import close_angle_deg

FIELD_NAMES = ("height", "displacement_x", "displacement_y", "slope_x", "slope_y")
SAMPLE_NAMES = ("elevation", "displacement_x", "displacement_y", "slope_x", "slope_y")


def band_m0(ocean: Ocean) -> float:
    """Exact m0 of the represented band: integral of S(w) between the cascades' outer band edges."""
    sea = ocean.sea
    cascades = [t for t in ocean.tiles if t.wave_index is None]
    lo = float(omega_from_k(cascades[0].k_lo, sea.depth))
    hi = float(omega_from_k(cascades[-1].k_hi, sea.depth))
    wp = 2 * math.pi / sea.tp
    value, _ = integrate.quad(lambda w: sea.density(np.array([w]))[0], lo, hi, points=[wp], limit=400)
    return value


def surface_variance(ocean: Ocean, t: float) -> float:
    """Variance of the summed surface: the tiles carry disjoint wave numbers, so variances add."""
    return sum(float(np.mean(f.height.astype(float) ** 2)) for f in ocean.fields(t))


# -- 2. FFT synthesis equals direct summation ------------------------------------------------

@pytest.mark.parametrize("t", [0.0, 3.7, 5000.25])  # a late time checks the phase reduction
def test_fft_fields_equal_direct_summation(north_sea, t):
    ocean = Ocean(north_sea, seed=3, choppiness=1.3)
    fields = ocean.fields(t)
    for i, tile_fields in enumerate(fields):
        x, y = tile_fields.tile.coordinates()
        pick = (slice(3, None, 23), slice(5, None, 29))
        direct = ocean.sample(x[pick], y[pick], t, tiles=[i])
        for name, sample_name in zip(FIELD_NAMES, SAMPLE_NAMES):
            fft = getattr(tile_fields, name)[pick].ravel()
            ref = getattr(direct, sample_name)
            scale = np.sqrt(np.mean(ref**2))
            assert np.max(np.abs(fft - ref)) < 1e-5 * scale * 10, (i, name)  # float32 FFT vs float64 sum
            assert np.sqrt(np.mean((fft - ref) ** 2)) < 1e-5 * scale, (i, name)


def test_jacobian_is_that_of_the_displacement_map(north_sea):
    # an independent spectral derivative of the displacement fields gives the same Jacobian
    ocean = Ocean(north_sea, seed=2, choppiness=1.0)
    for f in ocean.fields(12.0):
        qx, qy = f.tile.wavenumbers()
        dx_hat, dy_hat = np.fft.fft2(f.displacement_x), np.fft.fft2(f.displacement_y)
        dxx = np.fft.ifft2(1j * qx * dx_hat).real
        dyy = np.fft.ifft2(1j * qy * dy_hat).real
        dxy = np.fft.ifft2(1j * qy * dx_hat).real
        dyx = np.fft.ifft2(1j * qx * dy_hat).real
        np.testing.assert_allclose(dxy, dyx, atol=1e-5)  # the map is a gradient: dDx/dy = dDy/dx
        expected = (1 + dxx) * (1 + dyy) - dxy * dyx
        assert np.max(np.abs(f.jacobian - expected)) < 1e-4


def test_numpy_fallback_equals_pyfftw(north_sea):
    a = Ocean(north_sea, seed=4, resolution=64, fft_backend="pyfftw").fields(9.0)
    b = Ocean(north_sea, seed=4, resolution=64, fft_backend="numpy").fields(9.0)
    for fa, fb in zip(a, b):
        np.testing.assert_allclose(fa.height, fb.height, atol=1e-6 * np.abs(fb.height).max())
        np.testing.assert_allclose(fa.jacobian, fb.jacobian, atol=1e-5)


def test_fields_do_not_depend_on_how_the_tiles_are_split_into_lanes(north_sea):
    """One lane of four tiles, or three lanes (2 + 1 + 1) on threads, during a sea-state ramp:
    the same fields to float32 rounding. A lane reading another's cells, or a mirror cell left
    unconjugated, would change them by the order of the fields themselves."""
    calm, rough = ramp_pair(north_sea)

    def fields(threads: int):
        ocean = Ocean(calm, seed=6, resolution=64, threads=threads)
        ocean.ramp_to(rough, start=5.0, duration=10.0)
        return [(f.tile, f.height.copy(), f.displacement_x.copy(), f.slope_y.copy(), f.jacobian.copy())
                for f in ocean.fields(9.0)]

    one, three = fields(1), fields(3)
    assert [a[0] for a in one] == [b[0] for b in three]
    for a, b in zip(one, three):
        for x, y in zip(a[1:], b[1:]):
            np.testing.assert_allclose(x, y, rtol=0, atol=1e-6 * np.abs(x).max() + 1e-7)


@pytest.mark.skipif(not hasattr(os, "sched_setaffinity") or len(available_cpus()) < 2,
                    reason="needs two CPUs and thread affinity")
def test_each_lane_runs_on_a_cpu_of_its_own(north_sea, monkeypatch):
    """Two lanes run on two threads, neither the caller's, each pinned to a different CPU.
    Unpinned, a viewer calling once per frame got both lanes on one CPU in most frames, and an
    update took their sum."""
    ran_on = []

    def recording(lane, *args):
        ran_on.append((threading.get_ident(), frozenset(os.sched_getaffinity(0))))
        return run(lane, *args)

    run = Lane.run
    monkeypatch.setattr(Lane, "run", recording)
    Ocean(north_sea, seed=1, resolution=64, threads=2).fields(3.0)
    threads, cpus = zip(*ran_on)
    assert len(set(threads)) == 2 and threading.get_ident() not in threads
    assert sorted(map(min, cpus)) == available_cpus()[:2] and all(len(c) == 1 for c in cpus)


def test_lanes_give_the_same_fields_where_threads_cannot_be_pinned(north_sea, monkeypatch):
    """Pinning changes where a lane runs, never what it computes: without thread affinity (as on
    macOS or Windows) the ocean runs its lanes unpinned and gives the same bits."""
    ocean = Ocean(north_sea, seed=3, resolution=64, threads=2)
    pinned = [(f.height.copy(), f.jacobian.copy()) for f in ocean.fields(7.0)]
    monkeypatch.delattr(os, "sched_setaffinity", raising=False)
    free = Ocean(north_sea, seed=3, resolution=64, threads=2).fields(7.0)
    for (height, jacobian), f in zip(pinned, free, strict=True):
        np.testing.assert_array_equal(height, f.height)
        np.testing.assert_array_equal(jacobian, f.jacobian)


def test_changing_choppiness_on_a_running_ocean_rebuilds_every_lane(north_sea):
    """Choppiness set while running equals choppiness given at construction, in every lane:
    a lane keeping its old multipliers would keep the old displacement (off by the factor)."""
    running = Ocean(north_sea, seed=2, resolution=64, threads=2)
    running.fields(1.0)
    running.choppiness = 1.6
    built = Ocean(north_sea, seed=2, resolution=64, threads=2, choppiness=1.6)
    for a, b in zip(running.fields(4.0), built.fields(4.0)):
        np.testing.assert_array_equal(a.displacement_x, b.displacement_x)
        np.testing.assert_array_equal(a.jacobian, b.jacobian)


def test_live_changes_and_empty_lanes_reuse_the_compiled_loops():
    """A sea change, a new choppiness, or a lane with no cells (a short sea on a long sea's tiles)
    runs the per-frame loops numba compiled for the first frame: compiling another version for a
    new array layout would stall a running viewer for about half a second."""
    swell = SeaState((WaveSystem(Jonswap(4.0, 14.0, 3.3), 0.5, Cos2s(15.0)),))
    chop = SeaState((WaveSystem(Jonswap(1.0, 3.0, 3.3), 0.5, Cos2s(15.0)),))
    ocean = Ocean(chop, tiles=choose_tiles(swell, 4, 64), seed=1, resolution=64, threads=4)
    assert ocean.lane_count == 4 and not ocean.fields(1.0)[0].height.any()  # the longest tile's lane: no chop
    ocean.ramp_to(swell, start=2.0, duration=3.0)
    ocean.fields(3.0)
    ocean.choppiness = 1.5
    ocean.fields(9.0)
    assert len(_pack_cells.signatures) == 1 and len(_jacobian.signatures) == 1


# -- 3. variance -----------------------------------------------------------------------------

def test_cell_variances_integrate_the_spectrum(north_sea, finite_depth_sea):
    # the tiles' expected variance is the band's m0 (a missing dw/dk Jacobian would be off x2+)
    for sea in (north_sea, finite_depth_sea):
        ocean = Ocean(sea, seed=0)
        assert ocean.represented_m0 == pytest.approx(band_m0(ocean), rel=0.002)


def test_long_crested_ray_carries_the_band(north_sea):
    sea = SeaState((WaveSystem(PiersonMoskowitz(3.0, 8.0), 0.4),))
    ocean = Ocean(sea, seed=0)
    assert ocean.represented_m0 == pytest.approx(band_m0(ocean), rel=0.01)


def test_surface_variance_over_seeds_and_times(north_sea):
    measured, expected = [], []
    for seed in range(16):
        ocean = Ocean(north_sea, seed=seed)
        per_time = [surface_variance(ocean, t) for t in (0.0, 11.3, 47.9)]
        measured.extend(per_time)
        # each realisation: spatial variance = sum |a|^2 / 2 (no energy lost or doubled in packing)
        assert np.mean(per_time) == pytest.approx(ocean.components().variance, rel=0.01)
        expected.append(band_m0(ocean))
    # the ensemble: variance = m0 of the represented band (Hs within 1.5%)
    assert np.mean(measured) == pytest.approx(np.mean(expected), rel=0.03)


def test_deterministic_amplitudes_carry_exact_variance(north_sea):
    ocean = Ocean(north_sea, seed=5, random_amplitudes=False)
    assert ocean.components().variance == pytest.approx(ocean.represented_m0, rel=1e-9)
    assert surface_variance(ocean, 3.0) == pytest.approx(ocean.represented_m0, rel=0.02)


@pytest.mark.parametrize("sea", [
    SeaState((WaveSystem(Jonswap(4.0, 10.0, 3.3), 0.3, Cos2s(15.0)),)),
    SeaState((WaveSystem(PiersonMoskowitz(1.0, 4.0), 2.0),)),
    SeaState((WaveSystem(Tma(3.0, 9.0, 3.3, depth=25.0), 1.0, Cos2s(5.0)),), depth=25.0),
    SeaState((WaveSystem(Jonswap(2.5, 7.0, 3.3), 0.0, Cos2s(10.0)),
              WaveSystem(Jonswap(1.5, 15.0, 5.0), 2.0, Cos2s(60.0)))),
], ids=["jonswap", "pm-long-crested", "tma", "wind-sea+swell"])
@pytest.mark.parametrize("count", [3, 4])
def test_tiles_carry_99_percent_of_m0(sea, count):
    ocean = Ocean(sea, tile_count=count, seed=0)
    assert ocean.m0_fraction >= 0.99
    assert ocean.m0_fraction <= 1.001


def test_tiles_split_wavenumbers_once(north_sea):
    tiles = choose_tiles(north_sea, 4, 256)
    for a, b in zip(tiles, tiles[1:]):
        assert a.k_hi == b.k_lo  # touching bands: no gap, no double counting
        assert a.size / b.size == pytest.approx(TILE_RATIO)
    assert all(t.k_hi <= (t.resolution // 4) * t.dk * (1 + 1e-12) for t in tiles)


# -- 4. phase speed ----------------------------------------------------------------------------

def phase_speed_measured(depth: float, period: float) -> tuple[float, float]:
    beta = 0.0  # towards east: the wave vector lies on the x axis of its tile
    sea = SeaState((RegularWave(1.0, period, beta),), depth=depth)
    ocean = Ocean(sea, resolution=64)
    tile = ocean.tiles[0]
    k = math.hypot(*tile.wave_index) * tile.dk
    x = tile.coordinates()[0][0]
    dt = 0.2 * period
    phases = []
    for t in (10.0, 10.0 + dt):
        row = ocean.fields(t)[0].height[0].astype(float)
        phases.append(np.angle(np.sum(row * np.exp(1j * k * x))))
    # sum eta e^{ikx} has phase +w t for a wave travelling +x: the crest moved +x by this much
    # (a wave running the wrong way would read as 2 pi - w dt, four times the speed)
    shift = (phases[1] - phases[0]) % (2 * math.pi) / k
    return shift / dt, k


@pytest.mark.parametrize("depth", [math.inf, 12.0, 4.0])
def test_single_component_travels_at_phase_speed(depth):
    period = 8.0
    speed, k = phase_speed_measured(depth, period)
    omega = 2 * math.pi / period
    if math.isinf(depth):
        expected = G / omega  # deep water c = g / w = 12.49 m/s at 8 s
    else:
        kk = optimize.brentq(lambda kk: G * kk * math.tanh(kk * depth) - omega**2, 1e-6, 10.0)
        expected = omega / kk
        assert expected < 0.9 * G / omega  # the test would notice deep-water dispersion
    assert speed == pytest.approx(expected, rel=1e-3)
    assert omega / k == pytest.approx(expected, rel=1e-9)  # the period survives placing it on a tile


def test_regular_wave_in_any_direction_is_exact():
    beta = wave_beta_from_compass(37.0)
    sea = SeaState((RegularWave(2.0, 9.0, beta),))
    ocean = Ocean(sea, resolution=128)
    c = ocean.components()
    assert len(c) == 1
    assert math.degrees(abs(math.atan2(c.ky[0], c.kx[0]) - beta)) < 0.2
    assert c.omega[0] == pytest.approx(2 * math.pi / 9.0, rel=1e-12)
    assert abs(c.amplitude[0]) == pytest.approx(1.0)
    # the crest passes the origin at t = 0 (phase 0): eta(0, 0, 0) = H / 2
    assert ocean.sample(np.array([0.0]), np.array([0.0]), 0.0).elevation[0] == pytest.approx(1.0)


# -- 5. direction ------------------------------------------------------------------------------

@pytest.mark.parametrize("from_deg, spreading", [(30.0, Cos2s(15.0)), (250.0, LongCrested()), (135.0, Cos2s(4.0))])
def test_mean_direction_from_slopes(from_deg, spreading):
    sea = SeaState((WaveSystem(Jonswap(3.0, 9.0, 3.3), wave_beta_from_compass(from_deg), spreading),))
    measured = surface_summary(Ocean(sea, seed=7), t=20.0)["mean_from_deg_surface"]
    assert close_angle_deg(measured, from_deg) < 3.0  # travelling the wrong way would be 180 off


# -- 6. choppy waves are trochoids ---------------------------------------------------------------

def test_choppy_long_crested_component_is_a_trochoid():
    height, period = 4.0, 6.0
    sea = SeaState((RegularWave(height, period, 0.0),))
    ocean = Ocean(sea, resolution=256, choppiness=1.0)
    tile = ocean.tiles[0]
    k = math.hypot(*tile.wave_index) * tile.dk
    f = ocean.fields(1.3)[0]
    x = tile.coordinates()[0][0] + f.displacement_x[0]
    z = f.height[0]
    a = height / 2
    # Gerstner: the horizontal motion is a sin(theta) where eta = a cos(theta): points on
    # the surface are x0 + a sin(theta), crests are sharper than troughs
    order = np.argsort(x)
    x_sorted, z_sorted = x[order], z[order]
    fine = np.linspace(x_sorted[0], x_sorted[0] + tile.size * 0.999, 200_000)
    above = np.mean(np.interp(fine, x_sorted, z_sorted) > 0)
    assert above == pytest.approx(0.5 - k * a / math.pi, abs=0.002)  # 0.5 + ... if the sign were wrong
    assert above < 0.5 - 0.05
    # the displacement is in phase quadrature, |D| = a
    assert np.max(np.abs(f.displacement_x)) == pytest.approx(a, rel=1e-3)
    assert np.max(np.abs(f.displacement_y)) < 1e-4


# -- 7. reproducibility ----------------------------------------------------------------------------

def test_same_seed_bit_identical_different_seed_differs(north_sea):
    a = Ocean(north_sea, seed=11, resolution=64)
    b = Ocean(north_sea, seed=11, resolution=64)
    a.fields(30.0)  # calling at another time first must not matter: fields are a function of t
    fa = [f.height.copy() for f in a.fields(7.5)]
    fb = [f.height.copy() for f in b.fields(7.5)]
    assert all(np.array_equal(x, y) for x, y in zip(fa, fb))
    ca, cb = a.components(), b.components()
    assert np.array_equal(ca.amplitude, cb.amplitude)
    c = Ocean(north_sea, seed=12, resolution=64)
    assert not np.allclose(c.fields(7.5)[0].height, fa[0])


def test_separate_runs_give_the_same_bits(tmp_path):
    """Three runs in fresh processes sharing a cache give bit-identical fields. FFTW_MEASURE times
    its candidate algorithms, so without the saved plans (wisdom) about half of such runs round
    differently, and a rerun of a scenario would not reproduce its frames. A damaged wisdom file
    is ignored and replaced."""
    (tmp_path / "fftw-wisdom.json").write_text('{"single": "(fftw-3 half a')
    script = (
        "import hashlib\n"
        "from marinesim.sea import Cos2s, Jonswap, Ocean, SeaState, WaveSystem\n"
        "sea = SeaState((WaveSystem(Jonswap(3.0, 8.0, 3.3), 1.0, Cos2s(10.0)),))\n"
        "digest = hashlib.sha256()\n"
        "for f in Ocean(sea, seed=3).fields(12.3):\n"
        "    digest.update(f.height.tobytes() + f.jacobian.tobytes())\n"
        "print(digest.hexdigest())\n")
    env = {**os.environ, "MARINESIM_CACHE_DIR": str(tmp_path)}
    runs = {subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True,
                           check=True).stdout for _ in range(3)}
    assert len(runs) == 1, runs
    assert "fftwf_wisdom" in json.loads((tmp_path / "fftw-wisdom.json").read_text())["single"]


# -- components -------------------------------------------------------------------------------------

def test_component_list_keeps_a_variance_fraction(north_sea):
    ocean = Ocean(north_sea, seed=1)
    full = ocean.components()
    kept = ocean.components(variance_fraction=0.999)
    assert kept.variance >= 0.999 * full.variance
    assert len(kept) < 0.6 * len(full)
    assert np.all(np.isin(kept.kx + 1j * kept.ky, full.kx + 1j * full.ky))
    np.testing.assert_allclose(full.omega, omega_from_k(np.hypot(full.kx, full.ky)), rtol=1e-12)


# -- ramps ---------------------------------------------------------------------------------------------

def ramp_pair(north_sea):
    calm = SeaState((WaveSystem(Jonswap(2.0, 10.0, 3.3), north_sea.systems[0].beta, Cos2s(15.0)),))
    rough = SeaState((WaveSystem(Jonswap(5.0, 10.0, 3.3), north_sea.systems[0].beta + 0.5, Cos2s(15.0)),))
    return calm, rough


def test_ramp_changes_sea_state_without_jumps(north_sea):
    calm, rough = ramp_pair(north_sea)
    steady = Ocean(calm, seed=2, resolution=128)
    ocean = Ocean(calm, seed=2, resolution=128)
    ocean.ramp_to(rough, start=10.0, duration=20.0)
    # before the ramp nothing changed
    np.testing.assert_allclose(ocean.fields(5.0)[0].height, steady.fields(5.0)[0].height, atol=1e-6)
    # after it, the variance is that of the new sea (Hs 2 -> 5 m)
    after = Ocean(rough, seed=2, resolution=128)
    assert ocean.components(40.0).variance == pytest.approx(after.components().variance, rel=1e-9)
    # and the surface is the new sea's itself (same tiles and noise), not a blend that stopped short
    np.testing.assert_allclose(ocean.fields(40.0)[0].height, after.fields(40.0)[0].height, rtol=0, atol=1e-6)
    # no jump anywhere: the change over 1 ms is small at the start, middle and end of the ramp
    for t in (10.0, 20.0, 30.0):
        h0 = np.concatenate([f.height.ravel().copy() for f in ocean.fields(t - 1e-3)])
        h1 = np.concatenate([f.height.ravel() for f in ocean.fields(t + 1e-3)])
        assert np.max(np.abs(h1 - h0)) < 0.02  # m, with ~2 m/s vertical speeds at most


def test_a_ramp_onto_cells_no_earlier_state_used(north_sea):
    """A long-crested sea turned by 30 degrees lies on a new ray of cells: the ocean must grow its
    per-cell arrays for them, or the turned sea would be drawn without its waves."""
    beta = north_sea.systems[0].beta
    before = SeaState((WaveSystem(Jonswap(3.0, 9.0, 3.3), beta, LongCrested()),))
    turned = SeaState((WaveSystem(Jonswap(3.0, 9.0, 3.3), beta + math.radians(30.0), LongCrested()),))
    ocean = Ocean(before, seed=5, resolution=64)
    ocean.fields(1.0)
    ocean.ramp_to(turned, start=2.0, duration=3.0)
    fresh = Ocean(turned, seed=5, resolution=64, tiles=ocean.tiles)
    for a, b in zip(ocean.fields(8.0), fresh.fields(8.0), strict=True):
        assert np.abs(b.height).max() > 0.1
        np.testing.assert_allclose(a.height, b.height, rtol=0, atol=1e-6 * np.abs(b.height).max())
        np.testing.assert_allclose(a.jacobian, b.jacobian, rtol=0, atol=1e-5)


def test_many_live_changes_keep_memory_flat_and_the_past_exact(north_sea):
    """Thirty sea changes, as in a long training session: the ocean's memory does not grow with
    them (each ramp used to keep its amplitude grid, 4 x 64^2 complex here, 4 MB at 256^2), and a
    time inside the second ramp, whose states were dropped, gives the same bits as before."""
    calm, rough = ramp_pair(north_sea)
    ocean = Ocean(calm, seed=3, resolution=64)
    grid_mb = ocean.amplitudes(0.0).nbytes / 2**20
    for i in range(2):
        ocean.ramp_to(rough if i % 2 == 0 else calm, start=10.0 * i, duration=5.0)
    past = [(f.height.copy(), f.jacobian.copy()) for f in ocean.fields(12.5)]  # the newest two states, as computed
    past_components = ocean.components(12.5, variance_fraction=0.999)
    tracemalloc.start()
    held = []
    for i in range(2, 30):
        ocean.ramp_to(rough if i % 2 == 0 else calm, start=10.0 * i, duration=5.0)
        held.append(tracemalloc.get_traced_memory()[0] / 2**20)  # every buffer now allocated while traced
    tracemalloc.stop()
    assert held[-1] - held[4] < grid_mb  # keeping 23 more grids would add 23 x grid_mb
    for (height, jacobian), f in zip(past, ocean.fields(12.5), strict=True):
        np.testing.assert_array_equal(f.height, height)
        np.testing.assert_array_equal(f.jacobian, jacobian)
    again = ocean.components(12.5, variance_fraction=0.999)
    np.testing.assert_array_equal(again.amplitude, past_components.amplitude)
    np.testing.assert_array_equal(again.omega, past_components.omega)
    # and the newest sea is still the one asked for last (i = 29: calm)
    assert ocean.components(400.0).variance == pytest.approx(Ocean(calm, seed=3, resolution=64).components().variance)


def test_reading_the_past_in_order_computes_each_state_once():
    """A blend reads a state and the one before it, and a scan over the past (a recording, a
    chart) reads them in order. Keeping a single older state made every step recompute both,
    150 ms each at 4 x 256^2, in every frame that showed an old blend."""
    computed = []

    def square(index: int) -> int:
        computed.append(index)
        return index * index

    history = Recent(square)
    newest = 10
    for index in range(newest + 1):  # the history grows, its newest two kept
        history.get(index, index)
    computed.clear()
    for index in range(1, newest - 1):
        assert history.get(index, newest) == index**2 and history.get(index - 1, newest) == (index - 1) ** 2
    assert computed == [1, 0, *range(2, newest - 1)]  # each once, in the order first asked for


def test_bad_ramps_are_refused(north_sea):
    calm, rough = ramp_pair(north_sea)
    ocean = Ocean(calm, seed=2, resolution=64)
    ocean.ramp_to(rough, start=10.0, duration=20.0)
    with pytest.raises(ParameterError, match="previous"):
        ocean.ramp_to(calm, start=9.0, duration=5.0)  # before the previous ramp's start: out of time order
    with pytest.raises(ParameterError, match="depth"):
        ocean.ramp_to(SeaState(calm.systems, depth=30.0), start=40.0, duration=5.0)
    with pytest.raises(ParameterError, match="-1"):
        ocean.ramp_to(calm, start=40.0, duration=-1.0)


def third_sea(north_sea) -> SeaState:
    """A swell from another direction than both ``ramp_pair`` seas, so a blend of three is told apart."""
    return SeaState((WaveSystem(Jonswap(3.0, 12.0, 3.3), north_sea.systems[0].beta - 1.0, Cos2s(30.0)),))


def test_a_ramp_started_during_another_starts_from_the_blend_of_the_moment(north_sea):
    """A second sea change halfway through the first: the ocean must go on from the half-blended sea
    without a jump, end on the new sea, and leave the past untouched. Starting from either end of the
    first ramp would jump by the size of the amplitudes; ending short of the new sea would leave its
    variance off; a change to the past would make a replay differ from the live run."""
    calm, rough = ramp_pair(north_sea)
    swell = third_sea(north_sea)
    ocean = Ocean(calm, seed=2, tile_count=2, resolution=32)
    once = Ocean(calm, seed=2, tile_count=2, resolution=32)
    for o in (ocean, once):
        o.ramp_to(rough, start=10.0, duration=20.0)
    past = {t: once.amplitudes(t).copy() for t in (0.0, 10.0, 14.0, 19.999, 20.0)}
    past_fields = [f.height.copy() for f in once.fields(17.0)]
    ocean.ramp_to(swell, start=20.0, duration=10.0)
    # before the second ramp's start: the same bits as an ocean that never got it
    for t, amplitude in past.items():
        np.testing.assert_array_equal(ocean.amplitudes(t), amplitude, err_msg=f"t = {t} s")
    for height, f in zip(past_fields, ocean.fields(17.0), strict=True):
        np.testing.assert_array_equal(f.height, height)
    # no jump at its start: 2 ms move the amplitudes by O(dt) (smoothstep rate <= 1.5 / 10 s), while
    # the half blend is far from the calm and the rough sea it would have jumped to
    scale = np.abs(past[20.0]).max()
    just_before, just_after = ocean.amplitudes(20.0 - 1e-3), ocean.amplitudes(20.0 + 1e-3)
    assert np.abs(just_after - just_before).max() < 1e-3 * scale
    for end in (once.amplitudes(0.0), once.amplitudes(30.0)):
        assert np.abs(end - past[20.0]).max() > 0.1 * scale
    # halfway: halfway between the frozen blend and the swell (smoothstep(1/2) = 1/2)
    fresh = Ocean(swell, seed=2, tiles=ocean.tiles)
    np.testing.assert_allclose(ocean.amplitudes(25.0), 0.5 * (past[20.0] + fresh.amplitudes(0.0)),
                               rtol=0, atol=1e-12 * scale)
    # from its end on: the swell itself, variance and all, though the first ramp would still run to 30 s
    for t in (30.0, 40.0):
        np.testing.assert_array_equal(ocean.amplitudes(t), fresh.amplitudes(0.0))
        assert ocean.components(t).variance == pytest.approx(fresh.components().variance, rel=1e-12)
    assert ocean._settled(30.0) and not ocean._settled(29.0)
    for a, b in zip(ocean.fields(35.0), fresh.fields(35.0), strict=True):  # the settled spectrum is the swell's
        np.testing.assert_array_equal(a.height, b.height)


def test_blend_states_of_overlapping_ramps_are_the_amplitudes_and_keep_their_meaning(north_sea):
    """The GPU synthesis uploads ``spectrum_state(id)`` once per id and blends two of them by ``blend(t)``'s
    weight: that must give the CPU's amplitudes at t inside overlapping ramps, and an id must mean the same
    state after its amplitudes were dropped from memory and recomputed, or a replay would draw another sea."""
    calm, rough = ramp_pair(north_sea)
    seas = (rough, third_sea(north_sea), calm)
    ocean = Ocean(calm, seed=4, tile_count=2, resolution=32)
    for i in range(6):  # each starts 2 s into the previous 5 s ramp
        ocean.ramp_to(seas[i % 3], start=10.0 + 2.0 * i, duration=5.0)

    def spectrum(amplitude):
        plus, minus = 0.5 * mirrored(amplitude), 0.5 * np.conj(amplitude)
        return np.stack([(plus + minus).real, (plus + minus).imag, (1j * (plus - minus)).real,
                         (1j * (plus - minus)).imag], axis=-1)

    times = (11.0, 13.0, 17.5, 21.0, 30.0)
    seen = {}
    for t in times:
        before, after, weight = ocean.blend(t)
        assert isinstance(before, int) and isinstance(after, int)
        first, second = ocean.spectrum_state(before), ocean.spectrum_state(after)
        expected = spectrum(ocean.amplitudes(t))
        np.testing.assert_allclose(first + weight * (second - first), expected, rtol=0,
                                   atol=1e-6 * np.abs(expected).max(), err_msg=f"t = {t} s")
        seen.update({before: first, after: second})
    assert len(seen) > 4  # frozen blends among them, not only the seas
    for i in range(6, 20):  # more live changes drop the old states from memory
        ocean.ramp_to(seas[i % 3], start=10.0 + 2.0 * i, duration=5.0)
    for state, uploaded in seen.items():
        np.testing.assert_array_equal(ocean.spectrum_state(state), uploaded, err_msg=f"state {state}")


def test_a_ramp_started_at_the_previous_ones_start_replaces_it(north_sea):
    """Two changes at the same instant: the later one wins from the start, from the sea of that instant."""
    calm, rough = ramp_pair(north_sea)
    swell = third_sea(north_sea)
    ocean = Ocean(calm, seed=1, tile_count=2, resolution=32)
    ocean.ramp_to(rough, start=10.0, duration=20.0)
    ocean.ramp_to(swell, start=10.0, duration=4.0)
    direct = Ocean(calm, seed=1, tile_count=2, resolution=32)
    direct.ramp_to(swell, start=10.0, duration=4.0)
    for t in (5.0, 10.0, 12.0, 14.0, 20.0):
        np.testing.assert_array_equal(ocean.amplitudes(t), direct.amplitudes(t), err_msg=f"t = {t} s")


# -- 8. bad input -------------------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, value", [
    ({"resolution": 100}, "100"),
    ({"resolution": 8}, "8"),
    ({"tile_count": 0}, "0"),
    ({"seed": -1}, "-1"),
    ({"choppiness": float("nan")}, "nan"),
    ({"fft_backend": "cuda"}, "cuda"),
    ({"threads": 0}, "threads must be a positive integer, got 0"),
    ({"threads": 1.5}, "1.5"),
])
def test_bad_ocean_parameters(north_sea, kwargs, value):
    with pytest.raises(ParameterError, match=value):
        Ocean(north_sea, **kwargs)


@pytest.mark.parametrize("make, value", [
    (lambda: SeaState((), ), "at least one"),
    (lambda: SeaState((RegularWave(1.0, 8.0, 0.0),), depth=-2.0), "-2.0"),
    (lambda: SeaState((RegularWave(1.0, 8.0, 0.0),), depth=float("nan")), "nan"),
    (lambda: RegularWave(-1.0, 8.0, 0.0), "-1.0"),
    (lambda: RegularWave(1.0, 0.0, 0.0), "0.0"),
    (lambda: SeaState((WaveSystem(Tma(2.0, 8.0, depth=20.0), 0.0),), depth=30.0), "20"),
])
def test_bad_sea_states(make, value):
    with pytest.raises(ParameterError, match=value):
        make()


def test_spectrum_plus_regular_wave_share_the_ocean(north_sea):
    # a regular wave rides on its own tile beside the cascades; both are in the component list
    wave = RegularWave(1.0, 12.0, 0.5, phase=0.3)
    sea = SeaState(north_sea.systems + (wave,))
    ocean = Ocean(sea, seed=1)
    assert len(ocean.tiles) == 5 and ocean.tiles[-1].wave_index is not None
    c = ocean.components()
    regular = c.tile == 4
    assert np.count_nonzero(regular) == 1
    assert c.amplitude[regular][0] == pytest.approx(0.5 * np.exp(0.3j))
    assert ocean.represented_m0 == pytest.approx(band_m0(ocean) + wave.variance, rel=0.002)
    assert ocean.m0_fraction >= 0.99


def test_height_on_grid_is_the_summed_surface(north_sea):
    # the plot's map of the whole surface (bilinear on each tile) matches direct summation
    from marinesim.sea.plot import height_on_grid

    ocean = Ocean(north_sea, seed=6)
    rng = np.random.default_rng(0)
    x, y = rng.uniform(0, 2000, 300), rng.uniform(0, 2000, 300)
    mapped = height_on_grid(ocean.fields(4.0), x, y)
    direct = ocean.sample(x, y, 4.0).elevation
    sigma = north_sea.hs / 4
    assert np.sqrt(np.mean((mapped - direct) ** 2)) < 0.05 * sigma  # bilinear on 2x oversampled tiles
    at_origin = height_on_grid(ocean.fields(4.0), np.array(0.0), np.array(0.0))
    assert at_origin == pytest.approx(ocean.sample(np.array([0.0]), np.array([0.0]), 4.0).elevation[0], abs=1e-4)


def test_the_fft_order_mirror_is_minus_k():
    """``mirrored`` (the ocean's cell pairing and the solver's conj Z(-k)) is the field at index -i mod n on
    both axes, for one field and a stack of them; an off-by-one would pair every wave with a wrong partner."""
    from marinesim.sea.fft import mirrored

    field = np.random.default_rng(1).normal(size=(3, 8, 6))
    expected = np.array([[[field[t, -i % 8, -j % 6] for j in range(6)] for i in range(8)] for t in range(3)])
    assert np.array_equal(mirrored(field), expected) and np.array_equal(mirrored(field[1]), expected[1])
