"""RAO readers: each source convention converted once, checked on the real files in rao/.

References independent of the readers: the raw WAMIT columns read with numpy, the free-floating
long-wave limits (heave 1, pitch k cos beta, roll k sin beta, surge -i cos beta), and the
speed dependence of the VERES tables.
"""

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from conftest import ROOT, raw_wamit, synthetic_table
from marinesim.constants import KNOT
from marinesim.errors import FileFormatError, MarinesimError, ParameterError
from marinesim.vessel import read_rao
from marinesim.vessel.native import read_native, write_native
from marinesim.vessel.rao import DOFS, make_table
from marinesim.vessel.read import detect_format

TANKER = ROOT / "rao" / "tanker" / "tanker.4"
SEMISUB = ROOT / "rao" / "semisub" / "semisub.4"
S175 = ROOT / "rao" / "s175" / "input.re1"
SUPPLY = ROOT / "rao" / "supply" / "input.re1"


@pytest.mark.parametrize("path", [TANKER, SEMISUB])
def test_wamit_values_are_the_files_columns_at_tabulated_points(path):
    # a wrong period/frequency reading, a heading offset or a lost sign shows here directly
    table = read_rao(path)
    raw = raw_wamit(path)
    for (per, beta), expected in list(raw.items())[::37]:
        got = table(np.array([2 * math.pi / per]), np.array([math.radians(beta)]))[0]
        np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-15)
        if 0 < beta < 180:  # the mirrored heading: sway, roll, yaw change sign
            mirrored = table(np.array([2 * math.pi / per]), np.array([math.radians(360 - beta)]))[0]
            np.testing.assert_allclose(mirrored, expected * [1, -1, 1, -1, 1, -1], rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("path", [TANKER, SEMISUB])
def test_wamit_long_wave_limits(path):
    # REFERENCES/CONVENTIONS: heave -> 1, pitch -> k cos(beta), roll -> k sin(beta), surge -> -i cos(beta).
    # Rotations per A/ULEN misread (e.g. degrees, or ULEN 246) would put pitch/k at 57 or 246.
    table = read_rao(path)
    w = table.omega[:1]
    k = w[0] ** 2 / table.g
    for beta_deg in (0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0, 240.0, 300.0):
        beta = math.radians(beta_deg)
        h = table(w, np.array([beta]))[0]
        assert abs(h[2]) == pytest.approx(1.0, abs=0.01)
        assert abs(h[4]) == pytest.approx(k * abs(math.cos(beta)), abs=0.05 * k)
        assert abs(h[3]) == pytest.approx(k * abs(math.sin(beta)), abs=0.05 * k)
        assert abs(h[0]) == pytest.approx(abs(math.cos(beta)), abs=0.12)  # the tanker's surge drifts ~0.1
        if abs(math.cos(beta)) > 0.4:  # phase of surge: -90 deg times the sign of cos(beta)
            assert math.degrees(np.angle(h[0] * np.sign(math.cos(beta)))) == pytest.approx(-90.0, abs=10.0)
        if abs(math.cos(beta)) > 0.4:  # pitch = i k cos(beta): leads by 90 deg in following seas
            assert math.degrees(np.angle(h[4] * np.sign(math.cos(beta)))) == pytest.approx(90.0, abs=2.0)


def test_wamit_ulen_scales_rotations_only():
    base, scaled = read_rao(TANKER), read_rao(TANKER, ulen=10.0)
    np.testing.assert_allclose(scaled.values[..., :3], base.values[..., :3])
    np.testing.assert_allclose(scaled.values[..., 3:], base.values[..., 3:] / 10.0)


def test_wamit_frequency_columns_per_iperio(tmp_path):
    # the same numbers read as frequencies (IPERIO = 2) give omega = PER, not 2 pi / PER
    copy = tmp_path / "tanker.4"
    copy.write_bytes(TANKER.read_bytes())
    (tmp_path / "tanker.cfg").write_text("IPERIO=2\n")
    as_frequency = read_rao(copy)
    periods = np.unique(np.loadtxt(TANKER, usecols=0))
    np.testing.assert_allclose(as_frequency.omega, periods)
    assert any("ULEN not found" in note for note in as_frequency.notes)


def veres_pitch_ratio(table, speed_index, beta_deg, frequency_kind):
    """|pitch| / k at the lowest frequency, k from the frequency read as wave or encounter frequency."""
    w_table = table.omega[0]
    u = table.speed[speed_index]
    cos_b = math.cos(math.radians(beta_deg))
    if frequency_kind == "wave":
        w = w_table
    else:  # solve w - w^2 U cos(b) / g = w_table for the wave frequency
        a = -u * cos_b / table.g
        w = w_table if a == 0 else (-1 + math.sqrt(1 + 4 * a * w_table)) / (2 * a)
    pitch = abs(table.values[speed_index, list(np.round(np.degrees(table.beta))).index(beta_deg), 0, 4])
    return pitch / (w ** 2 / table.g)


def test_veres_tables_are_given_at_wave_frequency_with_rotations_in_rad_per_m():
    # Long-wave pitch is k(w) |cos beta| whatever the speed. Read as wave frequency, the ratio stays
    # near 1 at every speed; read as encounter frequency it drifts with speed (1.3 in head, 0.8 in following seas at 20 kn).
    table = read_rao(S175)
    assert table.speed / KNOT == pytest.approx([0, 5, 10, 15, 20], abs=0.01)
    for s in range(table.speed.size):
        for beta in (0.0, 180.0):
            assert veres_pitch_ratio(table, s, beta, "wave") == pytest.approx(1.0, abs=0.1)
    fast = table.speed.size - 1
    assert veres_pitch_ratio(table, fast, 180.0, "encounter") > 1.2
    assert veres_pitch_ratio(table, fast, 0.0, "encounter") < 0.9


def test_veres_heading_180_is_head_seas():
    # With speed, head seas are met at a higher encounter frequency: the pitch peak moves to lower
    # wave frequency; in following seas the encounter frequency falls and heave at 0.6 rad/s tends
    # to the quasi-static 1. Were 0 the head sea, both would go the other way.
    table = read_rao(S175)
    w = np.linspace(table.omega[0], table.omega[-1], 2000)

    def peak(speed, beta_deg, dof):
        h = table(w, np.full(w.size, math.radians(beta_deg)), speed)[:, dof]
        return w[np.argmax(np.abs(h))]
    slow, fast = table.speed[0], table.speed[-1]
    assert peak(fast, 180.0, 4) < peak(slow, 180.0, 4) - 0.04
    heave = lambda speed, beta: abs(table(np.array([0.6]), np.array([math.radians(beta)]), speed)[0, 2])
    assert heave(fast, 0.0) > heave(slow, 0.0) + 0.3
    assert heave(fast, 180.0) < heave(slow, 180.0)


@pytest.mark.parametrize("path", [S175, SUPPLY])
def test_veres_long_wave_limits_and_phases(path):
    table = read_rao(path)
    w = table.omega[:1]
    k = w[0] ** 2 / table.g
    follow, beam = table(w, np.array([0.0]))[0], table(w, np.array([math.pi / 2]))[0]
    assert follow[2] == pytest.approx(1.0, abs=0.01)
    assert follow[0] == pytest.approx(-1j, abs=0.02)           # surge -i cos(beta)
    assert follow[4] == pytest.approx(1j * k, abs=0.05 * k)     # pitch +i k cos(beta): rad/m, not deg/m
    assert beam[1] == pytest.approx(-1j, abs=0.02)             # sway -i sin(beta): 90 = towards port
    assert np.angle(beam[3], deg=True) == pytest.approx(-90.0, abs=2.0)  # roll -i k sin(beta)


def test_native_round_trip_keeps_every_value(tmp_path):
    table = read_rao(S175)
    path = tmp_path / "s175.csv"
    write_native(table, path)
    again = read_native(path)
    assert again.speed == pytest.approx(table.speed)
    np.testing.assert_allclose(again.values, table.values, rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(again.beta, table.beta, atol=1e-9)


def test_native_hand_written_table_with_periods_knots_degrees_and_lag(tmp_path):
    # phase lag, rotations in deg/m and periods in s are converted to the internal convention
    rows = []
    for heading in (0, 90, 180):
        for period in (20.0, 10.0, 5.0):
            rows.append(f"3,{heading},{period},1,0,1,0,1,30,2,0,2,45,2,0")
    text = ("# hand-written\nvessel = test barge\nphase = lag\n"
            "speed_kn,heading_deg,period_s,surge_amp_m_m,surge_phase_deg,sway_amp_m_m,sway_phase_deg,"
            "heave_amp_m_m,heave_phase_deg,roll_amp_deg_m,roll_phase_deg,pitch_amp_deg_m,pitch_phase_deg,"
            "yaw_amp_deg_m,yaw_phase_deg\n" + "\n".join(rows) + "\n")
    path = tmp_path / "barge.txt"
    path.write_text(text)
    table = read_rao(path)
    assert table.speed == pytest.approx([3 * KNOT])
    assert table.omega == pytest.approx(2 * math.pi / np.array([20.0, 10.0, 5.0]))
    h = table(table.omega[:1], np.array([math.pi]), 3 * KNOT)[0]
    assert np.angle(h[2], deg=True) == pytest.approx(-30.0)       # lag 30 -> lead -30
    assert abs(h[4]) == pytest.approx(math.radians(2.0))          # 2 deg/m -> rad/m
    assert np.angle(h[4], deg=True) == pytest.approx(-45.0)


def test_format_detection_by_extension_and_content(tmp_path):
    assert detect_format(TANKER) == "wamit" and detect_format(S175) == "veres"
    sniffed = tmp_path / "motions.out"
    sniffed.write_bytes(S175.read_bytes())
    assert detect_format(sniffed) == "veres"
    unknown = tmp_path / "notes.dat"
    unknown.write_text("hello world\n")
    with pytest.raises(FileFormatError, match=r"unknown RAO format '\.dat' \(nor does its content match one\); "
                                              "supported: wamit.*veres.*capytaine.*native"):
        read_rao(unknown)


# --- bad files: the error names the file and the line, and says what was expected ---------------

def tanker_lines():
    return TANKER.read_text().splitlines()


def write_lines(tmp_path, lines, name="bad.4"):
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return path


def test_bad_wamit_files(tmp_path):
    lines = tanker_lines()
    cases = {
        "truncated line": (lines[:10] + [" ".join(lines[10].split()[:5])] + lines[11:], 11, "expected 7 columns"),
        "text in a number": (lines[:4] + [lines[4].replace("0.000000E+00", "zero", 1)] + lines[5:], 5,
                             "expected BETA"),
        "NaN": (lines[:7] + [lines[7].replace(lines[7].split()[5], "NaN")] + lines[8:], 8, "finite"),
        "missing DOF": (lines[:5] + lines[6:], 1, r"modes \[6\] missing"),
        "duplicate frequency": (lines[:114] + lines[:6] + lines[114:], 115, "mode 1 given twice for PER 0.105"),
        "unsorted frequencies": (lines[:228] + lines[:6] + lines[228:], 229, "PER 0.105000E\\+01 appears again"),
        "heading out of range": (lines[:6] + [line.replace("0.100000E+02", "0.400000E+03", 1) for line in lines[6:12]]
                                 + lines[12:], 7, "BETA must be a heading"),
    }
    for name, (content, line, message) in cases.items():
        path = write_lines(tmp_path, content)
        with pytest.raises(FileFormatError, match=message) as error:
            read_rao(path)
        assert error.value.path == path and error.value.line == line, name
        assert f"{path}, line {line}:" in str(error.value)


def test_bad_veres_and_native_files(tmp_path):
    lines = S175.read_text().splitlines()
    truncated = write_lines(tmp_path, lines[:500], "cut.re1")
    with pytest.raises(FileFormatError, match="file ends early: expected"):
        read_rao(truncated)
    text_in_number = lines[:]
    text_in_number[13] = text_in_number[13].replace("-0.43122587E-02", "x0.43")
    with pytest.raises(FileFormatError, match=r"line 14: expected Re of DOF 1, got 'x0.43'"):
        read_rao(write_lines(tmp_path, text_in_number, "text.re1"))
    unsorted = lines[:]
    unsorted[12], unsorted[19] = unsorted[19], unsorted[12]  # first two frequencies exchanged
    with pytest.raises(FileFormatError, match="line 20: frequency 0.10472.*must be > 0 and increase"):
        read_rao(write_lines(tmp_path, unsorted, "unsorted.re1"))
    native = tmp_path / "t.csv"
    native.write_text("heading_deg,omega_rad_s,surge_amp_m_m,surge_phase_deg\n0,1,1,0\n")
    with pytest.raises(FileFormatError, match="line 1: missing column 'sway_phase_deg'"):
        read_rao(native)


def test_table_checks():
    omega, beta = np.array([0.5, 1.0]), np.radians([0.0, 90.0, 180.0])
    values = np.ones((1, 3, 2, 6), complex)
    partial = make_table(omega, np.radians([0.0, 180.0, 200.0]), [0.0], values)  # a 160 deg gap: a partial table
    assert partial.covered_text() == "165..215 deg (tabulated 180..200), 345..15 deg (tabulated 0)"
    with pytest.raises(ParameterError, match="strictly increasing"):
        make_table(omega[::-1], beta, [0.0], values)
    with pytest.raises(ParameterError, match="finite"):
        make_table(omega, beta, [0.0], values * np.nan)
    assert DOFS == ("surge", "sway", "heave", "roll", "pitch", "yaw")


# --- fuzz: whatever the bytes, a reader raises the project's error or returns a table ----------


def _fuzz(tmp_path_factory, source: Path, suffix: str, data) -> None:
    text = source.read_text()[:6000] if suffix != ".re1" else source.read_text()
    lines = text.splitlines()
    edits = data.draw(st.lists(st.tuples(st.integers(0, len(lines) - 1),
                                         st.sampled_from(["drop", "cut", "junk", "dup", "nan", "swap"]),
                                         st.text(max_size=8)), max_size=4))
    for index, kind, junk in edits:
        if index >= len(lines):
            continue
        if kind == "drop":
            del lines[index]
        elif kind == "cut":
            lines[index] = lines[index][: len(lines[index]) // 2]
        elif kind == "junk":
            lines[index] = lines[index] + junk
        elif kind == "dup":
            lines.insert(index, lines[index])
        elif kind == "nan":
            lines[index] = lines[index].replace("E", "Enan", 1)
        else:
            lines[index], lines[-1] = lines[-1], lines[index]
    path = tmp_path_factory.mktemp("fuzz") / f"fuzz{suffix}"
    path.write_bytes(("\n".join(lines) + "\n").encode("utf-8", "surrogatepass"))  # may be invalid UTF-8
    try:
        read_rao(path)
    except MarinesimError:
        pass


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_fuzz_wamit(tmp_path_factory, data):
    _fuzz(tmp_path_factory, TANKER, ".4", data)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_fuzz_veres(tmp_path_factory, data):
    _fuzz(tmp_path_factory, SUPPLY, ".re1", data)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_fuzz_native(tmp_path_factory, data):
    table, _ = synthetic_table()
    source = tmp_path_factory.mktemp("native") / "table.csv"
    write_native(table, source)
    _fuzz(tmp_path_factory, source, ".csv", data)
