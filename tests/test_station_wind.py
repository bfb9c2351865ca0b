"""The wind on a vessel keeping station: the NPD spectrum, the gusts synthesised from it (their spectrum, variance
and mean against the NPD's, within the statistical bands a record of that length allows), Blendermann's
coefficients against the source, the loads' signs, and the coefficient file reader."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scipy import integrate, signal, stats

from conftest import ROOT
from marinesim.errors import FileFormatError, ParameterError
from marinesim.station.wind import (BLENDERMANN, GUST_F_HIGH, GUST_F_LOW, RHO_AIR, BlendermannCoefficients, Gusts,
                                    TabulatedCoefficients, WindLoads, npd_mean_speed, npd_spectrum,
                                    read_wind_coefficients, relative_wind, wind_force)

SEMISUB = ROOT / "configs" / "wind" / "semisub.csv"
OSV = dict(frontal_area=160.7, lateral_area=434.8, length=48.0)
"""MSS's example vessel's areas (m^2) and length (m) (exWindForce.m)."""


def _band_integral(u0: float, low: float, high: float) -> float:
    """The NPD spectrum's integral over ``low .. high`` Hz (m^2/s^2)."""
    points = [p for p in (1e-3, 3e-3, 1e-2, 3e-2, 1e-1) if low < p < high]
    value, _ = integrate.quad(lambda f: float(npd_spectrum(f, u0)), low, high, points=points, limit=500)
    return value


def _welch_dof(window: np.ndarray, step: int, segments: int, bins: np.ndarray) -> float:
    """The chi-square degrees of freedom of the mean, over the Welch bins ``bins``, of the estimates from ``segments``
    windowed segments ``step`` samples apart, for a Gaussian process with a spectrum flat over the bins:
    ``nu = 2 E^2 / Var`` of the quadratic form, from the windowed exponentials' inner products (overlapping
    segments and neighbouring bins are correlated: counting them as independent would overstate nu)."""
    length = len(window)
    exps = np.exp(-2j * np.pi * np.outer(bins, np.arange(length)) / length) * window  # (bins, samples)
    trace = segments * np.sum(np.abs(exps) ** 2)
    square = segments * (np.sum(np.abs(exps.conj() @ exps.T) ** 2) + np.sum(np.abs(exps @ exps.T) ** 2))
    for lag in range(1, segments):
        shift = lag * step
        if shift >= length:
            break
        head, tail = exps[:, shift:], exps[:, :length - shift]
        overlap = np.sum(np.abs(head.conj() @ tail.T) ** 2) + np.sum(np.abs(head @ tail.T) ** 2)
        square += 2 * (segments - lag) * overlap
    return 2.0 * trace**2 / square


# --- the NPD spectrum -------------------------------------------------------------------------------------------


def test_npd_spectrum_matches_its_formula_at_known_points():
    """At f = 0 the spectrum is 320 (U0/10)^2 (z/10)^0.45; where f~ = 1 it is that over 2^(5/(3n)); far up it falls
    as f^(-5/3) (Kolmogorov). Otherwise a constant or an exponent of ISO 19901-1's formula is mistyped."""
    assert npd_spectrum(0.0, 10.0) == pytest.approx(320.0)
    assert npd_spectrum(0.0, 20.0, z=40.0) == pytest.approx(320.0 * 4.0 * 4.0**0.45)
    f_unit = 1.0 / 172.0 * (20.0 / 10.0) ** 0.75  # f~ = 1 at 20 m/s, 10 m
    assert npd_spectrum(f_unit, 20.0) == pytest.approx(1280.0 / 2.0 ** (5.0 / (3.0 * 0.468)))
    f = np.array([1e6, 2e6])
    slope = np.diff(np.log(npd_spectrum(f, 15.0))) / np.diff(np.log(f))
    assert slope[0] == pytest.approx(-5.0 / 3.0, rel=2e-3)


def test_npd_mean_speed_profile_and_gust_factor():
    """The profile is U0 at 10 m for the hour, grows with height, and a shorter average is gustier (ISO 19901-1:
    the 3 s gust at 10 m in 20 m/s is 1 - 0.41 I_u ln(3/3600) = 1.32 times the mean). Otherwise the averaging time
    or the height enters the wrong way round."""
    assert npd_mean_speed(20.0) == pytest.approx(20.0)
    assert npd_mean_speed(20.0, z=50.0) > npd_mean_speed(20.0, z=20.0) > 20.0
    intensity = 0.06 * (1.0 + 0.043 * 20.0)
    assert npd_mean_speed(20.0, averaging_s=3.0) == pytest.approx(20.0 * (1.0 - 0.41 * intensity * math.log(3 / 3600)))
    assert 1.3 < npd_mean_speed(20.0, averaging_s=3.0) / 20.0 < 1.35


# --- gusts ------------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("seed", [0, 1])
def test_gust_spectrum_is_the_npd_spectrum_within_its_statistical_band(seed):
    """Three hours at 2 Hz, Welch (Hann, 1024 s segments, half overlapping): in each log-spaced band from 4 mHz to
    0.45 Hz the mean ratio estimate / NPD lies within the 99 % chi-square band of its degrees of freedom (derived
    from the window and the overlap). A factor 2 in the amplitudes (one- vs two-sided), frequencies in rad/s
    taken for Hz, or a spectrum of the wrong speed would put bands far outside."""
    u0, fs, nperseg = 15.0, 2.0, 2048
    duration = 3 * 3600.0
    gusts = Gusts(u0, seed, duration)
    times = np.arange(int(duration * fs)) / fs
    record = gusts.speeds(times)
    f, estimate = signal.welch(record, fs=fs, window="hann", nperseg=nperseg, noverlap=nperseg // 2)
    segments = (len(record) - nperseg) // (nperseg // 2) + 1
    window = signal.get_window("hann", nperseg)
    edges = np.geomspace(4 * fs / nperseg, 0.45, 9)
    for low, high in zip(edges[:-1], edges[1:]):
        bins = np.nonzero((f >= low) & (f < high))[0]
        ratio = float(np.mean(estimate[bins] / npd_spectrum(f[bins], u0)))
        dof = _welch_dof(window, nperseg // 2, segments, bins)
        lower, upper = stats.chi2.ppf([0.005, 0.995], dof) / dof
        assert lower < ratio < upper, (f"{low:.4f}..{high:.4f} Hz: estimate/NPD = {ratio:.3f} outside the 99 % "
                                       f"band {lower:.3f}..{upper:.3f} (nu = {dof:.0f})")


@pytest.mark.parametrize("u0", [5.0, 15.0, 30.0])
def test_gust_variance_is_the_spectrum_integral_over_the_band(u0):
    """The cosines' variance sum a_i^2/2 equals the NPD spectrum's integral over 1/3600 .. 0.5 Hz within 1 %
    (each bin's expected share is its integral exactly; the jitter leaves a fraction of a per cent). Amplitudes
    sqrt(S df) instead of sqrt(2 S df) would be 50 % short."""
    gusts = Gusts(u0, 3, 3600.0)
    assert gusts.variance == pytest.approx(_band_integral(u0, GUST_F_LOW, GUST_F_HIGH), rel=0.01)


def test_hourly_records_have_the_spectrum_variance():
    """The variance of an hour's record, about its own mean, averaged over 20 seeds, is the spectrum's integral
    less what the hour's mean takes (sum p_i sinc^2(f_i T)), within the 99 % band of a Gaussian record:
    relative standard deviation sqrt(2 int S^2 df / T) / int S df per hour (the long-period gusts make one
    hour's variance scatter by about 10 %), over sqrt(20). A record whose variance is not its spectrum's (lines
    lost, amplitudes mis-scaled) fails."""
    u0, hours, fs, seeds = 15.0, 1.0, 1.0, 20
    duration = 3600.0 * hours
    times = np.arange(int(duration * fs)) / fs
    ratios = []
    for seed in range(seeds):
        gusts = Gusts(u0, seed, duration)
        power = gusts.amplitudes**2 / 2.0
        expected = np.sum(power * (1.0 - np.sinc(gusts.frequencies * duration) ** 2))
        ratios.append(np.var(gusts.fluctuation(times)) / expected)
    s1 = _band_integral(u0, GUST_F_LOW, GUST_F_HIGH)
    s2, _ = integrate.quad(lambda f: float(npd_spectrum(f, u0)) ** 2, GUST_F_LOW, GUST_F_HIGH,
                           points=[1e-3, 1e-2, 1e-1], limit=500)
    spread = math.sqrt(2.0 * s2 / duration) / s1 / math.sqrt(seeds)
    assert abs(np.mean(ratios) - 1.0) < stats.norm.ppf(0.995) * spread, (np.mean(ratios), spread)
    assert stats.norm.ppf(0.995) * spread < 0.08  # "a few per cent": the check is not vacuous


def test_hourly_mean_is_u0():
    """An hour's mean speed is u0 within 3.3 standard deviations (99.9 %) of an hour's mean of the synthesised
    lines, sqrt(sum p_i sinc^2(f_i T)) (about 0.06 m/s at 15 m/s). A fluctuation with a mean, or a mean at
    the wrong height, fails."""
    u0, duration = 15.0, 3600.0
    for seed in (0, 1, 2):
        gusts = Gusts(u0, seed, duration)
        record = gusts.speeds(np.arange(0.0, duration, 0.5))
        sigma = math.sqrt(np.sum(gusts.amplitudes**2 / 2.0 * np.sinc(gusts.frequencies * duration) ** 2))
        assert sigma < 0.1
        assert abs(record.mean() - u0) < 3.3 * sigma


def test_same_seed_same_series_other_seed_other_series():
    """A run is reproducible: the same seed gives the same series bit for bit (CONVENTIONS: same scenario + seed
    -> identical CSV); another seed another series (correlation ~ 0)."""
    times = np.arange(0.0, 600.0, 0.1)
    first, again = Gusts(12.0, 42, 600.0).speeds(times), Gusts(12.0, 42, 600.0).speeds(times)
    assert np.array_equal(first, again)
    other = Gusts(12.0, 43, 600.0).speeds(times)
    assert not np.array_equal(first, other)
    assert abs(np.corrcoef(first, other)[0, 1]) < 0.5
    gusts = Gusts(12.0, 42, 600.0)
    assert gusts.speed(123.4) == pytest.approx(gusts.speeds(np.array([123.4]))[0], abs=1e-12)


def test_gusts_draw_from_a_stream_of_their_own():
    """The scenario's seed also seeds the ocean (``default_rng([seed, tile])``): the gusts' phases must not be the
    first tile's random numbers, or the wind's gusts and the waves' phases would be one draw."""
    gusts = Gusts(12.0, 42, 600.0)
    tile0 = np.random.default_rng([42, 0])
    tile0.random(gusts.frequencies.size)
    assert not np.allclose(gusts.phases, tile0.uniform(0.0, 2.0 * math.pi, gusts.frequencies.size))


def test_gusts_scale_with_the_mean_wind():
    """A weather event ramps the mean: the whole wind scales by u_mean / u0 (gust factor kept); a calm mean is calm.
    Otherwise gusts of a 20 m/s wind would blow in a 2 m/s breeze."""
    gusts = Gusts(20.0, 5, 1200.0)
    times = np.linspace(0.0, 1200.0, 1201)
    assert np.allclose(gusts.speeds(times, u_mean=10.0), 0.5 * gusts.speeds(times))
    ramp = np.linspace(0.0, 20.0, times.size)
    assert np.allclose(gusts.speeds(times, u_mean=ramp), ramp / 20.0 * gusts.speeds(times))
    assert gusts.speed(600.0, u_mean=0.0) == 0.0


def test_gusts_refuse_times_outside_their_duration_and_bad_parameters():
    """Times past the duration they were built for, a negative mean, a zero u0 are mistakes the caller hears of."""
    gusts = Gusts(10.0, 1, 100.0)
    with pytest.raises(ParameterError, match="0..100 s"):
        gusts.speed(101.0)
    with pytest.raises(ParameterError, match="u_mean"):
        gusts.speed(1.0, u_mean=-1.0)
    with pytest.raises(ParameterError, match="u0"):
        Gusts(0.0, 1, 100.0)
    with pytest.raises(ParameterError, match="seed"):
        Gusts(10.0, -1, 100.0)


# --- Blendermann's coefficients ------------------------------------------------------------------------------


@pytest.mark.parametrize("vessel", ["offshore supply vessel", "drilling vessel", "tanker loaded", "container ship"])
def test_blendermann_coefficients_at_the_sources_reference_angles(vessel):
    """Fossen (2021) sec. 10.1.2: in a beam wind C_Y = CD_t and C_N = s_L/L CD_t (sin 2 gamma = 0); head on C_X =
    -CD_l_AF(0), astern +CD_l_AF(pi); the other side is the mirror image. A transposed table column, a sign, or
    a C_N not mirrored shows here."""
    row = BLENDERMANN[vessel]
    coefficients = BlendermannCoefficients(vessel, **OSV, s_l=2.0)
    assert coefficients.c_y(math.pi / 2) == row.cd_t
    assert coefficients.c_n(math.pi / 2) == pytest.approx(2.0 / 48.0 * row.cd_t, abs=1e-15)
    assert coefficients.c_x(0.0) == -row.cd_l_af_bow
    assert coefficients.c_x(math.pi) == row.cd_l_af_stern
    gamma = np.radians(np.arange(5.0, 180.0, 5.0))
    here, mirror = coefficients(gamma), coefficients(-gamma)
    assert np.allclose(mirror[0], here[0]) and np.allclose(mirror[1:], -here[1:])


def test_blendermann_oblique_value_by_hand():
    """The offshore supply vessel at 45 deg, by hand from the source's numbers (CD_t 0.90, CD_l_AF 0.55, delta
    0.55): CD_l = 0.55 A_F/A_L, den = 1 - 0.275 (1 - CD_l/0.90), C_Y = 0.90 sin 45 / den, C_X = -0.55 cos 45 /
    den, C_N = (0 + 0.18 pi/4) C_Y."""
    cd_l = 0.55 * 160.7 / 434.8
    den = 1.0 - 0.275 * (1.0 - cd_l / 0.90)
    cx, cy, cn = BlendermannCoefficients("Offshore supply vessel", **OSV)(math.pi / 4)
    assert cy == pytest.approx(0.90 * math.sqrt(0.5) / den, rel=1e-12)
    assert cx == pytest.approx(-0.55 * math.sqrt(0.5) / den, rel=1e-12)
    assert cn == pytest.approx(0.18 * math.pi / 4 * cy, rel=1e-12)


def test_unknown_vessel_type_names_the_known_ones():
    """A vessel type the table lacks is a mistake naming the types it has."""
    with pytest.raises(ParameterError, match="offshore supply vessel"):
        WindLoads.blendermann("hovercraft", 100.0, 300.0, 50.0)


# --- loads ------------------------------------------------------------------------------------------------------


def test_wind_force_signs():
    """Wind from dead ahead pushes her astern with no side force or moment; from the starboard beam it pushes her to
    port (Y < 0), from the port beam to starboard; from astern ahead. Forward of the beam the bow falls off to
    leeward (s_L = 0): from the starboard bow N < 0 (bow to port), from the starboard quarter the stern goes to
    leeward (N > 0). A 'from' taken for 'towards', or y taken to port, flips these."""
    loads = WindLoads.blendermann("offshore supply vessel", **OSV)
    psi = math.radians(40.0)
    head = loads.force(0.0, 0.0, psi, 20.0, psi)
    assert head[0] < 0.0 and abs(head[1]) < 1e-9 * abs(head[0]) and abs(head[2]) < 1e-9 * abs(head[0])
    starboard = loads.force(0.0, 0.0, psi, 20.0, psi + math.pi / 2)
    assert starboard[1] < 0.0 and abs(starboard[0]) < 1e-9 * abs(starboard[1])
    assert starboard[1] == pytest.approx(-0.5 * RHO_AIR * 20.0**2 * 0.90 * OSV["lateral_area"])
    assert loads.force(0.0, 0.0, psi, 20.0, psi - math.pi / 2)[1] > 0.0
    assert loads.force(0.0, 0.0, psi, 20.0, psi + math.pi)[0] > 0.0
    assert loads.force(0.0, 0.0, psi, 20.0, psi + math.radians(30.0))[2] < 0.0
    assert loads.force(0.0, 0.0, psi, 20.0, psi + math.radians(150.0))[2] > 0.0


def test_wind_force_is_felt_relative_to_her_motion():
    """Steaming at 5 m/s in calm air is a 5 m/s head wind; running before a wind at its own speed she feels none;
    and the load turns with her: the same relative wind at another heading is the same load."""
    loads = WindLoads.blendermann("container ship", 600.0, 4000.0, 200.0, s_l=-5.0)
    assert np.allclose(loads.force(5.0, 0.0, 1.0, 0.0, 0.0), loads.force(0.0, 0.0, 1.0, 5.0, 1.0))
    assert np.allclose(loads.force(8.0, 0.0, 0.3, 8.0, 0.3 + math.pi), 0.0, atol=1e-6)
    assert np.allclose(loads.force(1.0, -0.5, 0.2, 15.0, 1.1), loads.force(1.0, -0.5, 2.2, 15.0, 3.1))
    speed, gamma = relative_wind(0.0, 0.0, 0.0, 10.0, -math.pi / 2)  # from the west, heading north: port beam
    assert speed == pytest.approx(10.0) and gamma == pytest.approx(math.pi / 2)


# --- the coefficient file -------------------------------------------------------------------------------------


def test_shipped_semisub_table_reads_and_is_a_column_stabilised_unit():
    """configs/wind/semisub.csv reads: head on C_X < 0, C_X and C_Y of a size (a square deck: within 20 % at 0 and
    90 deg), C_N small (under 5 % of C_Y), mirrored to starboard; in a starboard beam wind the unit is pushed to
    port."""
    table = read_wind_coefficients(SEMISUB)
    cx0, cy90 = float(table.c_x(0.0)), float(table.c_y(math.pi / 2))
    assert cx0 < 0.0 < cy90 and abs(abs(cx0) / cy90 - 1.0) < 0.2
    gamma = np.radians(np.arange(0.0, 360.0, 5.0))
    assert np.max(np.abs(table.c_n(gamma))) < 0.05 * np.max(np.abs(table.c_y(gamma)))
    assert np.allclose(table.c_y(-gamma), -table.c_y(gamma))
    loads = WindLoads.from_file(SEMISUB, 2600.0, 2600.0, 84.6)
    assert loads.force(0.0, 0.0, 0.0, 20.0, math.pi / 2)[1] < 0.0


def test_full_table_wraps_round_and_interpolates_linearly(tmp_path):
    """A 0..350 table wraps round to 0 (355 deg is halfway between 350 and 0) and reads between rows linearly."""
    rows = "\n".join(f"{a},{-math.cos(math.radians(a)):.6f},{math.sin(math.radians(a)):.6f},0.01" for a in
                     range(0, 360, 10))
    path = tmp_path / "full.csv"
    path.write_text("# a full table\nangle_deg,cx,cy,cn\n" + rows + "\n")
    table = read_wind_coefficients(path)
    cx350, cx0 = -math.cos(math.radians(350.0)), -1.0
    assert float(table.c_x(math.radians(355.0))) == pytest.approx(0.5 * (cx350 + cx0), abs=1e-6)
    assert float(table.c_x(math.radians(-5.0))) == pytest.approx(0.5 * (cx350 + cx0), abs=1e-6)
    assert float(table.c_y(math.radians(15.0))) == pytest.approx(
        0.5 * (math.sin(math.radians(10.0)) + math.sin(math.radians(20.0))), abs=1e-6)


GOOD = ["angle_deg,cx,cy,cn"] + [f"{a},-0.5,0.0,0.0" if a in (0, 180) else f"{a},0.1,0.8,0.02"
                                 for a in range(0, 181, 30)]
"""A minimal good half table: angles 0, 30, ..., 180 on lines 2..8."""


@pytest.mark.parametrize("edit, line, expected", [
    ({3: "30,0.1,,0.02"}, 3, "expected cy (a number), got an empty cell"),
    ({4: "60,0.1,abc,0.02"}, 4, "expected cy (a number), got 'abc'"),
    ({5: "90,0.1,0.8,nan"}, 5, "finite number"),
    ({5: "100,0.1,0.8,0.02"}, 5, "no more than 30 deg apart"),
    ({4: "20,0.1,0.8,0.02"}, 4, "increasing"),
    ({2: "10,-0.5,0.0,0.0"}, 2, "first angle to be 0"),
    ({8: None}, 7, "cover 0..180"),
    ({6: "120,0.1,0.8"}, 6, "expected 4 cells"),
    ({1: "angle,cx,cy,cn"}, 1, "header"),
    ({2: "0,-0.5,0.3,0.0"}, 2, "cy = cn = 0"),
])
def test_a_table_with_holes_names_the_line(tmp_path, edit, line, expected):
    """A blank cell, a word, NaN, a gap over 30 deg, angles going back, not starting at 0 or not reaching 180, a
    short row, a wrong header, a side force in a head wind of a mirrored table: FileFormatError naming the file
    and the line, and saying what was expected there."""
    lines = list(GOOD)
    for number, text in edit.items():
        lines[number - 1] = text
    path = tmp_path / "holes.csv"
    path.write_text("\n".join(text for text in lines if text is not None) + "\n")
    with pytest.raises(FileFormatError, match=re.escape(expected)) as caught:
        read_wind_coefficients(path)
    assert caught.value.line == line and "holes.csv" in str(caught.value)


def test_missing_or_empty_file(tmp_path):
    """A missing file and a file with no rows are format errors naming the file, not tracebacks."""
    with pytest.raises(FileFormatError, match="no such"):
        read_wind_coefficients(tmp_path / "absent.csv")
    empty = tmp_path / "empty.csv"
    empty.write_text("# nothing here\n")
    with pytest.raises(FileFormatError, match="no header"):
        read_wind_coefficients(empty)


def test_tabulated_coefficients_refuse_an_unmirrorable_half_table():
    """Made in code, a half table with a side force head on is refused (its mirror image would jump at 0 deg)."""
    with pytest.raises(ParameterError, match="mirrors"):
        angles = np.arange(0.0, 181.0, 30.0)
        TabulatedCoefficients(angles, -np.cos(np.radians(angles)), np.sin(np.radians(angles)) + 0.1, 0.0 * angles)


def test_wind_force_function_matches_the_vessels_method():
    """``wind_force`` with the vessel's numbers is ``WindLoads.force``."""
    loads = WindLoads.blendermann("tanker loaded", 1200.0, 6000.0, 320.0, s_l=10.0)
    direct = wind_force(loads.coefficients, 1200.0, 6000.0, 320.0, 0.5, 0.1, 2.0, 18.0, 2.5)
    assert np.array_equal(direct, loads.force(0.5, 0.1, 2.0, 18.0, 2.5))


def test_blendermann_one_angle_at_a_time_equals_the_array_formula():
    """The simulation asks for one angle a step (plain floats, for speed); the array formula is the published one.
    What would be wrong if not: the simulation's wind loads differing from the ones the tests above check."""
    coefficients = BlendermannCoefficients("offshore supply vessel", 250.0, 780.0, 84.8, 8.0)
    gammas = np.linspace(-math.pi, math.pi, 721)
    table = coefficients(gammas)
    one = np.array([coefficients(float(g)) for g in gammas]).T
    np.testing.assert_allclose(one, table, rtol=1e-13, atol=1e-15)
