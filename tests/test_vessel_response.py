"""Vessel response: what the motions must be, from the RAOs, the waves and rigid-body kinematics."""

import math

import numpy as np
import pytest

from conftest import ROOT, raw_wamit, synthetic_table
from marinesim.sea.build import wave_system
from marinesim.sea.ocean import Ocean
from marinesim.sea.seastate import SeaState
from marinesim.vessel import DOFS, Response, Track, read_rao
from marinesim.vessel.native import write_native

TANKER = ROOT / "rao" / "tanker" / "tanker.4"
S175 = ROOT / "rao" / "s175" / "input.re1"

CSV_UNIT = np.array([1.0, 1.0, 1.0, math.pi / 180, math.pi / 180, math.pi / 180])  # CSV -> m, rad


def regular_response(table, period, beta_rel_deg, speed=0.0, from_deg=200.0, points=None):
    """Response to a regular wave met at exactly ``beta_rel_deg``; also returns the component."""
    ocean = Ocean(SeaState((wave_system("regular", from_deg=from_deg, height=2.0, period=period),)), seed=5)
    c = ocean.components()
    assert len(c) == 1
    heading = math.atan2(c.ky[0], c.kx[0]) - math.radians(beta_rel_deg)
    return Response(table, c, Track(heading=heading, speed=speed, x0=13.0, y0=-7.0), points), c


def measured_transfer(response, omega_e, periods=20, per_period=64):
    """Complex amplitude of each DOF over that of the wave at the reference point (by projection)."""
    t = np.arange(periods * per_period) * (2 * math.pi / abs(omega_e)) / per_period
    frame = response.frame(t)
    basis = np.exp(-1j * omega_e * t)
    wave = np.mean(frame["wave_elevation_m"] * basis)
    names = response.columns[1:7]
    return np.array([np.mean(frame[name] * basis) for name in names]) * CSV_UNIT / wave


def assert_transfer(measured, expected, what):
    # 0.5 % in amplitude and 0.5 deg in phase where the DOF responds; near-zero DOFs within
    # 0.5 % of the largest value of their kind (translations m/m, rotations rad/m)
    for j in range(6):
        kind = slice(0, 3) if j < 3 else slice(3, 6)
        scale = np.abs(expected[kind]).max()
        if abs(expected[j]) > 0.05 * scale:
            assert abs(measured[j]) == pytest.approx(abs(expected[j]), rel=0.005), (what, DOFS[j])
            assert math.degrees(abs(np.angle(measured[j] / expected[j]))) < 0.5, (what, DOFS[j])
        else:
            assert abs(measured[j] - expected[j]) < 0.005 * scale, (what, DOFS[j])


@pytest.mark.parametrize("beta_deg,file_beta,mirror", [(180.0, 180.0, False), (150.0, 150.0, False),
                                                       (90.0, 90.0, False), (30.0, 30.0, False),
                                                       (0.0, 0.0, False), (240.0, 120.0, True),
                                                       (290.0, 70.0, True)])
def test_regular_wave_response_is_the_wamit_rao(beta_deg, file_beta, mirror):
    # the reference is the file's own RE/IM columns; mirrored headings flip sway, roll, yaw
    table = read_rao(TANKER)
    period = 10.44
    expected = raw_wamit(TANKER)[(period, file_beta)] * (np.array([1, -1, 1, -1, 1, -1]) if mirror else 1)
    response, c = regular_response(table, period, beta_deg)
    assert_transfer(measured_transfer(response, c.omega[0]), expected, f"tanker {beta_deg}")


@pytest.mark.parametrize("beta_deg", [180.0, 120.0, 60.0, 230.0])
def test_regular_wave_response_is_the_veres_rao_at_speed(beta_deg):
    # 10 kn is a tabulated speed, 0.5236 rad/s a tabulated frequency: the response at the
    # encounter frequency has the file's transfer function relative to the wave at the ship
    table = read_rao(S175)
    speed = table.speed[2]
    omega = 0.5235988
    heading_index = int(round((beta_deg if beta_deg <= 180 else 360 - beta_deg) / 10))
    frequency_index = int(np.argmin(abs(table.omega - omega)))
    expected = table.values[2, heading_index, frequency_index] * (
        np.array([1, -1, 1, -1, 1, -1]) if beta_deg > 180 else 1)
    response, c = regular_response(table, 2 * math.pi / omega, beta_deg, speed=speed)
    omega_e = c.omega[0] - speed * c.omega[0] ** 2 / 9.80665 * math.cos(math.radians(beta_deg))
    assert response.omega_e[0] == pytest.approx(omega_e, rel=1e-9)
    assert_transfer(measured_transfer(response, response.omega_e[0]), expected, f"S175 {beta_deg}")


def test_regular_wave_response_of_a_synthetic_table_between_grid_points(tmp_path):
    # Re/Im bilinear in omega and beta: linear interpolation is exact anywhere inside, so the
    # response at an off-grid frequency and heading must be the analytic value (written and
    # read back through the native format on the way)
    table, coefficient = synthetic_table()
    path = tmp_path / "synthetic.csv"
    write_native(table, path)
    table = read_rao(path)
    period, beta_deg = 7.3, 52.0
    omega = 2 * math.pi / period
    expected = coefficient * (1.5 - 0.5 * omega) * (1.0 + 0.3 * math.radians(beta_deg))
    response, c = regular_response(table, period, beta_deg)
    assert_transfer(measured_transfer(response, c.omega[0]), expected, "synthetic")


def test_the_table_asked_at_one_heading_for_many_frequencies_answers_each():
    """Frequencies and headings broadcast as numpy's do: one heading with five frequencies is the same heading five
    times, one frequency with five headings five answers (the interpolation reads one heading per frequency: a
    short list of headings would read past it)."""
    table = read_rao(TANKER)
    omega, beta = np.linspace(0.3, 1.5, 5), np.radians([0.0, 40.0, 95.0, 180.0, 270.0])
    assert np.array_equal(table(omega, np.array([1.0])), table(omega, np.full(5, 1.0)))
    assert np.array_equal(table(np.array([0.6]), beta), table(np.full(5, 0.6), beta))


def test_irregular_variance_equals_the_discrete_sum_over_components():
    # Long-crested, so distinct components have well-separated frequencies and a 4 h record
    # averages their cross terms out: var(x_j) = sum |H_j a|^2 / 2 within 0.5 % (a component lost,
    # doubled or given the wrong RAO would show at this level).
    table = read_rao(TANKER)
    sea = SeaState((wave_system("jonswap", from_deg=250.0, hs=4.0, tp=10.0),))
    t = np.arange(0.0, 4 * 3600.0, 0.5)
    for seed in range(3):
        ocean = Ocean(sea, tile_count=3, resolution=64, seed=seed)
        response = Response(table, ocean.components(), Track(heading=math.radians(30.0)))
        c = response.components
        discrete = np.sum(np.abs(response.transfer * c.amplitude[:, None]) ** 2, axis=0) / 2
        np.testing.assert_allclose(response.linear(t)[:, :6].var(axis=0), discrete, rtol=0.005)


def test_irregular_variance_scatters_about_the_spectral_integral():
    # Over seeds, the time variance of each DOF in a short-crested sea scatters about
    # m0_j = int int |H_j(w, theta - psi)|^2 S(w, theta) dw dtheta (quadrature on a fine polar grid).
    table = read_rao(TANKER)
    sea = SeaState((wave_system("jonswap", from_deg=250.0, hs=4.0, tp=10.0, spreading_s=8.0),))
    heading = math.radians(30.0)  # mean wave travels towards 70 deg math: beta_rel = 40 deg
    t = np.arange(0.0, 3600.0, 0.5)
    variances = []
    for seed in range(8):
        ocean = Ocean(sea, tile_count=3, resolution=64, seed=seed)
        variances.append(Response(table, ocean.components(), Track(heading=heading)).linear(t)[:, :6].var(axis=0))
    w = np.linspace(0.2, 3.0, 1200)
    theta = np.linspace(-math.pi, math.pi, 721)[:-1]
    W, TH = np.meshgrid(w, theta, indexing="ij")
    density = sea.systems[0].directional_density(W, TH)
    h = table(W.ravel(), TH.ravel() - heading).reshape(W.shape + (6,))
    m0 = np.sum(np.abs(h) ** 2 * density[..., None], axis=(0, 1)) * (w[1] - w[0]) * (theta[1] - theta[0])
    mean, spread = np.mean(variances, axis=0), np.std(variances, axis=0, ddof=1) / math.sqrt(len(variances))
    for j in range(6):
        assert abs(mean[j] - m0[j]) < 3 * spread[j] + 0.02 * m0[j], (DOFS[j], mean[j], m0[j], spread[j])
    assert 4 * math.sqrt(m0[2]) > 0.5  # heave is not trivially small in this sea


def test_point_forward_sees_heave_minus_x_pitch_and_exact_derivatives():
    table = read_rao(TANKER)
    sea = SeaState((wave_system("jonswap", from_deg=170.0, hs=5.0, tp=11.0, spreading_s=10.0),))
    ocean = Ocean(sea, tile_count=3, resolution=64, seed=2)
    points = {"fwd": (50.0, 0.0, 0.0), "deck": (-40.0, 12.0, 18.0)}
    response = Response(table, ocean.components(), Track(heading=math.radians(80.0), speed=3.0), points)
    dt = 0.02
    frame = next(response.frames(100.0, dt, 5000))
    heave, pitch = frame["heave_m"], np.radians(frame["pitch_deg"])
    # small angles: z = heave - x pitch (pitch bow down positive); second order is ~ 50 * pitch^2 / 2
    small = heave - 50.0 * pitch
    assert np.max(np.abs(frame["fwd_z_m"] - small)) < 0.5 * 50.0 * np.max(pitch ** 2) + 1e-4
    assert np.std(frame["fwd_z_m"] - heave) > 0.1 * np.std(heave)  # pitch matters at 50 m
    for name in points:
        z = frame[f"{name}_z_m"]
        vz = np.gradient(z, dt, edge_order=2)
        az = np.gradient(vz, dt, edge_order=2)
        inner = slice(5, -5)
        assert np.max(np.abs(vz[inner] - frame[f"{name}_vz_m_s"][inner])) < 2e-3 * np.max(np.abs(vz))
        assert np.max(np.abs(az[inner] - frame[f"{name}_az_m_s2"][inner])) < 5e-3 * np.max(np.abs(az))
    # DOF velocities and accelerations are the derivatives of the displacements
    roll = frame["roll_deg"]
    assert np.max(np.abs(np.gradient(roll, dt)[5:-5] - frame["roll_vel_deg_s"][5:-5])) < 2e-3 * np.max(np.abs(frame["roll_vel_deg_s"]))
    # relative motion = vertical motion minus the wave at the point: at the reference point the
    # wave column is the same sum, so a point at the origin sees heave - eta
    origin = Response(table, ocean.components(), response.track, {"o": (0.0, 0.0, 0.0)})
    f0 = next(origin.frames(100.0, dt, 500))
    np.testing.assert_allclose(f0["o_relative_m"], f0["heave_m"] - f0["wave_elevation_m"], atol=1e-9)


def test_head_seas_at_speed_respond_at_the_encounter_frequency():
    # A long-crested head sea met at 15 kn: the dominant (mean) frequency of the recorded heave and
    # pitch is that of S(w) |H(w)|^2 mapped to w_e = w + w^2 U / g, 40 % above the wave frequency's.
    table = read_rao(TANKER)
    sea = SeaState((wave_system("jonswap", from_deg=0.0, hs=3.0, tp=12.0, gamma=6.0),))
    ocean = Ocean(sea, tile_count=3, resolution=128, seed=4, random_amplitudes=False)
    speed = 15 * 1852 / 3600
    response = Response(table, ocean.components(), Track(heading=math.pi / 2, speed=speed))  # bow north
    dt, steps = 0.25, 2 ** 16
    frames = list(response.frames(0.0, dt, steps))
    w = np.linspace(0.2, 2.5, 4000)
    for column, j in (("heave_m", 2), ("pitch_deg", 4)):
        record = np.concatenate([f[column] for f in frames])
        spectrum = np.abs(np.fft.rfft(record * np.hanning(steps))) ** 2
        frequency = 2 * math.pi * np.fft.rfftfreq(steps, dt)
        measured = np.sum(frequency * spectrum) / np.sum(spectrum)
        weight = sea.density(w) * np.abs(table(w, np.full(w.size, math.pi), speed)[:, j]) ** 2
        encounter = np.sum((w + w ** 2 * speed / 9.80665) * weight) / np.sum(weight)
        wave = np.sum(w * weight) / np.sum(weight)
        assert measured == pytest.approx(encounter, rel=0.03), column
        assert encounter > 1.3 * wave  # the wave-frequency answer is far off


@pytest.mark.parametrize("beta_rel_deg", [180.0, 135.0, 90.0])
def test_two_identical_vessels_side_by_side_lag_by_the_wave_travel_between_them(beta_rel_deg):
    """Two tankers on the same heading, 60 m apart across their beam, in a long-crested regular sea: each heaves and
    rolls as the RAO says, and the one the wave reaches later lags by k d sin(beta) exactly (the phase the
    components carry in space, eta = a cos(w t - k . x)). Another body whose motions were in phase with own-ship's
    (or lagged by the wrong amount) would show a crane operator or a helicopter pilot a deck that does not move as
    the sea does between them."""
    table = read_rao(TANKER)
    response, c = regular_response(table, 10.0, beta_rel_deg)
    heading = response.track.heading
    apart = 60.0  # to port of the first
    offset = apart * np.array([-math.sin(heading), math.cos(heading)])
    other = Response(table, c, Track(heading=heading, x0=13.0 + offset[0], y0=-7.0 + offset[1]))
    omega = float(c.omega[0])
    t = np.arange(20 * 64) * (2 * math.pi / omega) / 64
    lag = float(c.kx[0] * offset[0] + c.ky[0] * offset[1])  # k . d: the phase the second is behind by (rad)
    expected_lag = (2 * math.pi / 10.0) ** 2 / 9.80665 * apart * math.sin(math.radians(beta_rel_deg))
    assert lag == pytest.approx(expected_lag, rel=1e-3, abs=1e-9)  # deep water: k = w^2 / g
    basis = np.exp(-1j * omega * t)
    first, second = response.frame(t), other.frame(t)
    for name in ("heave_m", "roll_deg", "pitch_deg"):
        a, b = np.mean(first[name] * basis), np.mean(second[name] * basis)
        if abs(a) < 1e-6 * abs(np.mean(first["heave_m"] * basis)) + 1e-12:
            continue  # no such motion in this sea (roll in head seas)
        assert abs(b) == pytest.approx(abs(a), rel=1e-9)  # identical vessels, the same amplitude
        assert np.angle(b / a) == pytest.approx(np.angle(np.exp(-1j * lag)), abs=1e-6)
