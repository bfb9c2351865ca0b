"""Second-order wave drift: the WAMIT ``.9`` reader on the MSS tanker's real file, the mean drift in a JONSWAP sea,
and Newman's slowly varying drift series (marinesim/vessel/wamit_drift.py, marinesim/station/drift.py)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT
from marinesim.errors import FileFormatError
from marinesim.sea.ocean import Components
from marinesim.sea.spectra import Jonswap
from marinesim.station.drift import FORCE_STEP, KEPT_SHARE, SlowDrift, mean_drift
from marinesim.vessel.wamit_drift import read_drift

TANKER_DRIFT = ROOT / "rao" / "tanker" / "tanker.9"
RHO_G = 1025.0 * 9.80665  # the tanker run's .frc and .gdf; ULEN = 1 m
HS, TP, GAMMA = 4.0, 10.0, 3.3


@pytest.fixture(scope="module")
def table():
    return read_drift(TANKER_DRIFT)


def _line(period: str, beta: str, mode: int) -> list[float]:
    """The numbers of the shipped file's line for (PER, BETA, mode), as the file writes PER and BETA."""
    for text in TANKER_DRIFT.read_text().splitlines():
        parts = text.split()
        if parts[0] == period and parts[1] == beta and parts[2] == beta and int(parts[3]) == mode:
            return [float(p) for p in parts]
    raise AssertionError(f"no line for {period} {beta} {mode}")


def test_one_value_by_hand_gives_units_and_axes(table):
    """The nondimensional RE times rho g ULEN (forces) or rho g ULEN^2 (yaw), WAMIT's y-port/z-up turned to the
    manoeuvring y-starboard/z-down: a wrong scale would miss by rho g, a missed axis turn by the sign."""
    w = 2.0 * math.pi / 9.49
    surge = _line("0.949000E+01", "0.180000E+03", 1)[6]
    sway = _line("0.949000E+01", "0.900000E+02", 2)[6]
    yaw = _line("0.949000E+01", "0.900000E+02", 6)[6]
    assert (surge, sway, yaw) == (-16.95027, 132.6088, -111.501)
    assert table(w, math.pi)[0] == pytest.approx(surge * RHO_G, rel=1e-12)
    x, y, n = table(w, math.pi / 2)
    assert y == pytest.approx(-sway * RHO_G, rel=1e-12) and n == pytest.approx(-yaw * RHO_G, rel=1e-12)
    assert x == pytest.approx(_line("0.949000E+01", "0.900000E+02", 1)[6] * RHO_G, rel=1e-12)
    assert table.coefficients.shape == (44, 36, 3) and np.all(np.diff(table.omega) > 0)


def test_head_seas_push_her_astern_and_beam_seas_from_starboard_to_port(table):
    """A ship reflects the waves she meets: head seas (beta = pi) give a negative (astern) surge drift, waves
    from starboard (travelling towards port, beta = +pi/2) push her to port (Y < 0) and those from port to
    starboard. A reversed heading or sway convention flips these signs."""
    period = 2.0 * math.pi / table.omega
    head = table(table.omega, np.full(table.omega.size, math.pi))
    assert np.all(head[(period > 3.0) & (period < 41.0), 0] < 0.0)
    band = (period > 3.2) & (period < 14.0)
    from_starboard = table(table.omega[band], np.full(band.sum(), math.pi / 2))
    from_port = table(table.omega[band], np.full(band.sum(), -math.pi / 2))
    assert np.all(from_starboard[:, 1] < 0.0) and np.all(from_port[:, 1] > 0.0)
    # beam seas in short waves: about 3/4 of a wall's 1/2 rho g A^2 L over her 246 m
    assert 0.5 < -from_starboard[-1, 1] / (0.5 * RHO_G * 246.0) < 1.0


def test_half_range_table_is_completed_by_the_mirror(table):
    """The file covers 0..180 deg; the other side is X(-beta) = X(beta), Y and N odd. Without the mirror the
    port side would be read as a 180 deg gap (or wrapped from the starboard side with the wrong sign)."""
    assert any("mirror" in note for note in table.notes)
    assert np.allclose(np.degrees(table.beta), np.arange(-180.0, 180.0, 10.0))
    betas = np.radians(np.arange(10.0, 180.0, 10.0))
    for w in table.omega[::7]:
        starboard = table(np.full(betas.size, w), betas)
        port = table(np.full(betas.size, w), -betas)
        assert np.allclose(port, starboard * [1.0, -1.0, -1.0], rtol=1e-12, atol=0.0)


def test_interpolation_between_and_beyond_the_table(table):
    """Bilinear inside, periodic in heading, constant above the highest frequency, (omega/omega_0)^4 below the
    lowest: a table lookup that extrapolated linearly would give drift at zero frequency."""
    w0, w1 = table.omega[10], table.omega[11]
    b0, b1 = table.beta[20], table.beta[21]
    middle = table(0.5 * (w0 + w1), 0.5 * (b0 + b1))
    assert np.allclose(middle, table.coefficients[10:12, 20:22].mean(axis=(0, 1)), rtol=1e-12)
    assert np.allclose(table(w0, b0 + 2.0 * math.pi), table(w0, b0), rtol=1e-12)
    assert np.array_equal(table(10.0, 1.0), table(table.omega[-1], 1.0))
    low = table.omega[0]
    assert np.allclose(table(0.5 * low, 2.0), table(low, 2.0) / 16.0, rtol=1e-12)
    assert np.array_equal(table(0.0, 2.0), np.zeros(3))
    assert table(np.ones((2, 5)), 0.3).shape == (2, 5, 3)


def _components(omega_low: float, omega_high: float, d_omega: float, seed: int = 1):
    """JONSWAP components on a regular frequency grid: deterministic amplitudes sqrt(2 S d omega), random phases."""
    spectrum = Jonswap(hs=HS, tp=TP, gamma=GAMMA)
    omega = omega_low + d_omega * (np.arange(round((omega_high - omega_low) / d_omega)) + 0.5)
    phase = np.random.default_rng(seed).uniform(0.0, 2.0 * math.pi, omega.size)
    return spectrum, omega, np.sqrt(2.0 * spectrum.density(omega) * d_omega) * np.exp(1j * phase)


@pytest.mark.parametrize("beta_deg", [180.0, 135.0, 90.0])
def test_mean_drift_equals_the_time_average_of_newmans_series(table, beta_deg):
    """Two independent routes to the mean load in a long-crested JONSWAP (Hs 4 m, Tp 10 s): the quadrature
    2 int S D d omega, and the time average of SlowDrift.force_series over its whole repeat period 2 pi / d omega
    (where the cross terms average to zero exactly). They agree within 2 % on every load that matters; a factor 2
    lost between one- and two-sided spectra, or a sign group mixed up, would not."""
    spectrum, omega, amplitude = _components(0.2, 4.0, 0.004)
    heading = math.radians(30.0)
    beta = math.radians(beta_deg)
    slow = SlowDrift(omega, np.full(omega.size, heading + beta), amplitude, table)
    times = np.linspace(0.0, 2.0 * math.pi / 0.004, 8192, endpoint=False)
    average = slow.force_series(times, heading).mean(axis=0)
    quadrature = mean_drift(table, np.linspace(0.2, 4.0, 2000), spectrum.density, beta)
    sampled = mean_drift(table, omega, spectrum.density(omega), beta)
    assert np.allclose(average, slow.mean(heading), rtol=1e-9, atol=1e-9 * np.abs(average).max())
    floor = np.array([1e3, 1e3, 1e5])  # N, N, N m: 2 % of the loads that matter here (head seas: sway, yaw ~ 0)
    assert np.all(np.abs(average - quadrature) <= 0.02 * np.abs(quadrature) + floor), (average, quadrature)
    assert np.all(np.abs(sampled - quadrature) <= 0.02 * np.abs(quadrature) + floor)
    if beta_deg == 180.0:  # head seas: about 330 kN astern for a 246 m tanker in Hs 4 m
        assert -4e5 < quadrature[0] < -2.5e5


def test_a_regular_wave_gives_d_times_a_squared_at_every_instant(table):
    """One component has no difference frequency: the load is the constant |A|^2 D(omega, beta), at any time
    and by both force() and force_series(). A lost square root or sign group would show here first."""
    omega, beta, heading = 0.65, math.radians(150.0), math.radians(-20.0)
    amplitude = 1.7 * np.exp(0.4j)
    slow = SlowDrift([omega], [heading + beta], [amplitude], table)
    expected = abs(amplitude) ** 2 * table(omega, beta)
    for t in (0.0, 0.137, 12.3, 977.05):
        assert np.allclose(slow.force(t, heading), expected, rtol=1e-12, atol=1e-9)
    assert np.allclose(slow.force_series(np.linspace(0, 100, 7), heading), expected, rtol=1e-12, atol=1e-9)
    assert np.allclose(slow.mean(heading), expected, rtol=1e-12)


def test_newmans_series_holds_difference_frequencies_only(table):
    """With components between 0.55 and 2 peak frequencies, the difference frequencies stay below 1.45 wp: the
    series' power spectrum is empty from 1.5 to 2.5 wp, where a model with sum frequencies (here the square of
    the elevation itself) puts a third of its variance; most of the load's variance is slow (below wp / 2)."""
    wp = 2.0 * math.pi / TP
    d_omega = 0.004
    _, omega, amplitude = _components(0.55 * wp, 2.0 * wp, d_omega)
    heading = 0.0
    slow = SlowDrift(omega, np.full(omega.size, heading + math.pi), amplitude, table)
    n = 8192
    times = np.linspace(0.0, 2.0 * math.pi / d_omega, n, endpoint=False)
    surge = slow.force_series(times, heading)[:, 0]
    eta = (np.exp(1j * np.outer(times, omega)) @ amplitude).real
    frequency = 2.0 * math.pi * np.fft.rfftfreq(n, times[1])
    near_2wp = (frequency > 1.5 * wp) & (frequency < 2.5 * wp)

    def share(series: np.ndarray, band: np.ndarray) -> float:
        power = np.abs(np.fft.rfft(series - series.mean())) ** 2
        return float(power[band].sum() / power.sum())

    assert share(surge, near_2wp) < 1e-12
    assert share(eta**2, near_2wp) > 0.2
    assert share(surge, frequency < 0.5 * wp) > 0.7


def test_slow_drift_looks_the_table_up_relative_to_the_heading(table):
    """beta_rel = direction - heading (CONVENTIONS): waves travelling north hit a ship heading east from
    starboard (she is pushed to port, Y < 0), a ship heading west from port (Y > 0), and come from astern
    of a ship heading north (X > 0 in 8 s waves). Using the absolute direction would give one answer for all."""
    slow = SlowDrift([2.0 * math.pi / 8.0], [math.pi / 2], [1.0], table)
    assert slow.mean(0.0)[1] < 0.0
    assert slow.mean(math.pi)[1] > 0.0
    assert slow.mean(math.pi / 2)[0] > 0.0
    assert np.allclose(slow.mean(0.0), table(2.0 * math.pi / 8.0, math.pi / 2))


def test_force_interpolates_the_exact_sums(table):
    """force() interpolates a 0.1 s grid of exact sums (fast enough for 4 calls per 0.1 s step): exact on the
    grid, and within 1e-3 of the load's standard deviation between (a stale window or a wrong Lagrange weight
    would be off by the load itself)."""
    _, omega, amplitude = _components(0.25, 2.0, 0.004)
    heading = math.radians(45.0)
    slow = SlowDrift(omega, np.full(omega.size, 2.5), amplitude, table)
    times = np.sort(np.random.default_rng(3).uniform(0.0, 300.0, 400))
    exact = slow.force_series(times, heading)
    approx = np.array([slow.force(t, heading) for t in times])
    assert np.all(np.abs(approx - exact).max(axis=0) < 1e-3 * exact.std(axis=0))
    grid = np.arange(0, 50) * FORCE_STEP
    on_grid = np.array([slow.force(t, heading) for t in grid])
    assert np.allclose(on_grid, slow.force_series(grid, heading), rtol=1e-9, atol=1e-9 * np.abs(on_grid).max())
    assert np.allclose(slow.force(12.34, heading + math.radians(0.04)), slow.force(12.34, heading))  # 0.1 deg


def test_the_series_sums_the_largest_components_holding_the_kept_share(table):
    """Per load, the components summed in time are the fewest largest ``|a_j|^2 |D_j|`` holding KEPT_SHARE of their
    sum (with any as large as the smallest of them), the loads' sets joined; the rest only add their mean. The
    weights here are worked out from the table on their own. What would be wrong: a component the share needs left
    out (the series short of its variance), or all of them summed (the shortcut lost)."""
    rng = np.random.default_rng(11)
    _, omega, amplitude = _components(0.25, 2.0, 0.004)              # distinct frequencies: one sum per component
    direction = math.radians(200.0) + rng.normal(0.0, 0.5, omega.size)
    heading = math.radians(10.0)
    slow = SlowDrift(omega, direction, amplitude, table)
    kept = np.isin(omega, slow._prepared(heading).omega)
    weight = np.abs(amplitude)[:, None] ** 2 * np.abs(table(omega, direction - heading))
    needed = np.zeros(omega.size, dtype=bool)
    for load in range(3):
        w = weight[:, load]
        descending = np.sort(w)[::-1]
        cumulative = np.cumsum(descending)
        count = int(np.argmax(cumulative >= KEPT_SHARE * cumulative[-1])) + 1
        needed |= w >= descending[count - 1]
        assert w[kept].sum() >= KEPT_SHARE * w.sum() * (1.0 - 1e-12)
    assert np.array_equal(kept, needed), (int(kept.sum()), int(needed.sum()))
    assert 0 < kept.sum() < omega.size


def test_from_components_refers_the_phases_to_the_point(table):
    """An ocean's components become amplitudes at the set point (a exp(-i k.x)) and directions atan2(ky, kx):
    the slow load at a point away from the origin differs in time but not in mean."""
    omega = np.array([0.55, 0.6, 0.7])
    k = omega**2 / 9.80665
    direction = np.array([0.3, 0.5, 0.4])
    c = Components(omega, k * np.cos(direction), k * np.sin(direction), np.array([1.0, 0.8j, 0.5]), np.zeros(3, int))
    here = SlowDrift.from_components(c, table, x=120.0, y=-40.0)
    by_hand = SlowDrift(omega, direction, c.amplitude * np.exp(-1j * (c.kx * 120.0 - c.ky * 40.0)), table)
    times = np.linspace(0.0, 200.0, 11)
    assert np.allclose(here.force_series(times, 1.0), by_hand.force_series(times, 1.0))
    origin = SlowDrift.from_components(c, table)
    assert np.allclose(here.mean(1.0), origin.mean(1.0))
    assert not np.allclose(here.force_series(times, 1.0), origin.force_series(times, 1.0))


def _cut(tmp_path: Path, periods: int = 2, suffix: str = ".8") -> tuple[Path, list[str]]:
    """The first ``periods`` periods of the shipped file, alone in ``tmp_path`` (no .gdf, .frc beside)."""
    lines = TANKER_DRIFT.read_text().splitlines()[: periods * 19 * 3]
    path = tmp_path / f"cut{suffix}"
    path.write_text("\n".join(lines) + "\n")
    return path, lines


def test_a_cut_file_reads_with_the_assumed_run_values(tmp_path):
    """Alone, a file is read with ULEN 1 m and rho 1025 kg/m^3, each said in a note."""
    path, _ = _cut(tmp_path)
    table = read_drift(path)
    assert table.omega.size == 2 and any("rho not found" in note for note in table.notes)
    assert read_drift(path, rho=1000.0, g=9.81)(table.omega[0], math.pi)[0] == pytest.approx(
        table(table.omega[0], math.pi)[0] * 1000.0 * 9.81 / RHO_G, rel=1e-12)


def test_a_missing_cell_is_refused_with_its_line(tmp_path):
    """A (period, heading) cell missing would leave a hole the interpolation reads as zero: refused, naming the
    period, the heading and the line where that period starts."""
    path, lines = _cut(tmp_path)
    second = lines[57].split()[0]  # lines 58-114: the second period, 1.1 s
    kept = [text for text in lines if text.split()[:2] != [second, "0.500000E+02"]]
    assert len(kept) == len(lines) - 3
    path.write_text("\n".join(kept) + "\n")
    with pytest.raises(FileFormatError) as error:
        read_drift(path)
    assert error.value.line == 58 and "PER 1.1 has no mean drift lines for BETA 50" in str(error.value)
    assert str(error.value).startswith(f"{path}, line 58: ")


def test_a_missing_mode_a_non_number_and_a_short_line_are_refused_with_their_lines(tmp_path):
    """A cell without its sway line, a number that is not one, a line of seven columns: each refused at its line."""
    path, lines = _cut(tmp_path)
    path.write_text("\n".join(lines[:4] + lines[5:]) + "\n")  # line 5: PER 1.05, BETA 10, mode 2
    with pytest.raises(FileFormatError) as error:
        read_drift(path)
    assert error.value.line == 4 and "mode(s) 2 missing" in str(error.value) and "BETA 10" in str(error.value)

    broken = list(lines)
    broken[20] = broken[20].replace(broken[20].split()[6], "-1.2x3E+00", 1)
    path.write_text("\n".join(broken) + "\n")
    with pytest.raises(FileFormatError) as error:
        read_drift(path)
    assert error.value.line == 21 and "'-1.2x3E+00'" in str(error.value)

    broken = list(lines)
    broken[30] = " ".join(broken[30].split()[:7])
    path.write_text("\n".join(broken) + "\n")
    with pytest.raises(FileFormatError) as error:
        read_drift(path)
    assert error.value.line == 31 and "expected 8 columns" in str(error.value)


def test_cross_terms_limits_and_other_modes_are_left_out_and_a_quarter_circle_refused(tmp_path):
    """BETA1 != BETA2 rows (bidirectional), PER <= 0 rows and modes other than 1, 2, 6 are not mean drift:
    left out with notes. Headings 0..90 only cannot be mirrored into a circle: refused, naming them."""
    rows = []
    for per in (-1.0, 0.0, 8.0, 10.0):
        for b1 in range(0, 181, 45):
            for b2 in (b1, (b1 + 45) % 180):
                for mode in (1, 2, 3, 6, -6):
                    value = 0.0 if per <= 0 else (1.0 + mode + b1 / 90.0)
                    rows.append(f"{per:13.6E} {b1:13.6E} {b2:13.6E} {mode:5d} {abs(value):13.6E} "
                                f"{0.0 if value >= 0 else 180.0:13.6E} {value:13.6E} {0.0:13.6E}")
    path = tmp_path / "run.8"
    path.write_text("\n".join(rows) + "\n")
    table = read_drift(path)
    notes = " ".join(table.notes)
    assert "PER <= 0" in notes and "BETA1 != BETA2" in notes and "modes -6, 3" in notes
    assert np.allclose(2.0 * math.pi / table.omega, [10.0, 8.0])
    assert table(2.0 * math.pi / 8.0, math.pi / 4)[0] == pytest.approx(2.5 * RHO_G, rel=1e-12)

    quarter = [r for r in rows if float(r.split()[1]) <= 90.0]
    path.write_text("\n".join(quarter) + "\n")
    with pytest.raises(FileFormatError) as error:
        read_drift(path)
    assert "gap" in str(error.value) and "0, 45, 90 deg" in str(error.value)
