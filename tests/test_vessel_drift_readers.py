"""Mean wave drift from AQWA listings and NEMOH v3 QTF output (marinesim/vessel/aqwa_drift.py, nemoh_drift.py), on
real files (tests/data/drift/README.md): units and axes by values converted by hand, sign physics, the short-wave
limit of a vertical cylinder as a second method, and malformed files refused at their line."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from marinesim.errors import FileFormatError, ParameterError
from marinesim.vessel.aqwa_drift import aqwa_drift_loads, read_aqwa_drift
from marinesim.vessel.drift import turned_round
from marinesim.vessel.nemoh_drift import nemoh_drift_loads, read_nemoh_drift

DATA = Path(__file__).parent / "data" / "drift"
CYLINDER = DATA / "aqwa_cylinder_drift.LIS"
OC3 = DATA / "nemoh_oc3"
OC3_QTF = OC3 / "results" / "QTF" / "OUT_QTFM_N_0.dat"
OC3_RHO_G = 1025.0 * 9.81  # the run's Nemoh.cal
X, Y, N = range(3)


@pytest.fixture(scope="module")
def cylinder():
    return aqwa_drift_loads(CYLINDER)


@pytest.fixture(scope="module")
def cylinder_table():
    return read_aqwa_drift(CYLINDER, axisymmetric=True)


@pytest.fixture(scope="module")
def spar():
    return nemoh_drift_loads(OC3_QTF)


def _aqwa_row(load: str, freq: str) -> list[float]:
    """The numbers of the shipped listing's row ``freq`` under the label ``load`` (the file's own text)."""
    current = None
    for text in CYLINDER.read_text().splitlines():
        words = text.split()
        if len(words) == 1 and "(" in words[0]:
            current = words[0]
        elif current == load and words and words[0] == freq:
            return [float(w) for w in words]
    raise AssertionError(f"no row {freq} under {load}")


def _waterline_diameter() -> float:
    """The cylinder's diameter (m) from the CUT WATER PLANE AREA the listing prints (0.3837 m^2: D = 0.699 m)."""
    for text in CYLINDER.read_text().splitlines():
        if "CUT WATER PLANE AREA" in text and "=" in text:
            return 2.0 * math.sqrt(float(text.split("=")[1]) / math.pi)
    raise AssertionError("no waterplane area in the listing")


# --- AQWA: WEC-Sim's floating cylinder (0.7 m diameter, 3 m deep tank), directions -180, 0, 180 deg ---


def test_aqwa_values_by_hand_give_units_and_axes(cylinder):
    """The listing's numbers are N/m^2 and N m/m^2 already: surge kept, sway and yaw sign-changed from AQWA's Z-up
    axes (y port) to the manoeuvring y-starboard/z-down. A scale would miss the magnitude, a missed axis turn the
    sign of Y or N, a column mix-up the value (the -180 column is kept for the heading printed twice)."""
    assert cylinder.omega.size == 50 and np.allclose(cylinder.headings_deg, [-180.0, 0.0])
    i = int(np.flatnonzero(np.isclose(cylinder.omega, 2.815))[0])
    minus180, zero, plus180 = _aqwa_row("SURGE(X)", "2.815")[1:]
    assert (minus180, zero, plus180) == (-4.65, 4.46, -4.65)
    assert cylinder.values[i, :, X].tolist() == [minus180, zero]
    j = int(np.flatnonzero(np.isclose(cylinder.omega, 0.467))[0])
    sway = _aqwa_row("SWAY(Y)", "0.467")[2]
    assert sway == 1.95e-02 and cylinder.values[j, 1, Y] == -sway
    k = int(np.flatnonzero(np.isclose(cylinder.omega, 4.950))[0])
    yaw = _aqwa_row("YAW(RZ)", "4.950")[2]
    assert yaw == -4.87e-02 and cylinder.values[k, 1, N] == -yaw
    notes = " ".join(cylinder.notes)
    assert "HEAVE(Z), PITCH(RY), ROLL(RX) drift left out" in notes and "printed twice" in notes
    assert "centre of gravity (0, 0, 0) m" in notes


def test_aqwa_head_seas_push_the_cylinder_astern_and_short_waves_give_the_wall_limit(cylinder):
    """Waves travelling along +X (0 deg) push the cylinder along +X, head seas (180 deg, kept as -180) astern,
    once the drift rises above the solver's noise (about 1e-2 N/m^2, under 1e-5 of the short-wave drift, below
    1.75 rad/s where kR < 0.3). Second method: in short waves a wall-sided cylinder reflects all it meets and
    the drift tends to (2/3) rho g R = rho g D / 3 (integrating 1/2 rho g cos^2 over the lit half; e.g.
    Faltinsen, Sea Loads, ch. 5); at kR = 1.8..3.8 (7..10.5 rad/s) AQWA gives 0.77..0.98 of it. A reversed
    direction convention fails the signs, a wrong unit (kN, or times rho g) the ratio."""
    limit = 1025.0 * 9.807 * _waterline_diameter() / 3.0
    assert limit == pytest.approx(2344.0, rel=1e-3)
    noise = cylinder.omega <= 1.75
    assert np.all(np.abs(cylinder.values[noise, :, X]) < 1e-5 * limit)
    waves = cylinder.omega >= 1.9
    following, head = cylinder.values[waves, 1, X], cylinder.values[waves, 0, X]
    assert np.all(following > 0.0) and np.all(head < 0.0)
    assert np.allclose(head, -following, rtol=0.06, atol=1e-3 * limit)  # a symmetric body: the push reversed
    short = cylinder.omega >= 7.0
    ratio = cylinder.values[short, 1, X] / limit
    assert np.all((ratio > 0.75) & (ratio < 1.0)) and 0.85 < ratio.mean() < 0.97


def test_aqwa_axisymmetric_table_turns_the_push_with_the_waves(cylinder, cylinder_table):
    """The listing covers two headings, so a table needs the body's symmetry: turned round the circle, waves from
    starboard (travelling towards port, beta = +pi/2) push it to port (Y < 0) as hard as following seas push it
    ahead, waves from port to starboard, and head seas give back the file's own 180 deg column. Turning the wrong
    way would push it to starboard; without the option the gap is refused, naming the headings."""
    table = cylinder_table
    assert table.beta.size == 72 and any("axisymmetric" in note for note in table.notes)
    w = cylinder.omega[cylinder.omega >= 1.9]
    ahead = table(w, 0.0)
    assert np.all(ahead[:, X] > 0.0)
    from_starboard, from_port = table(w, math.pi / 2), table(w, -math.pi / 2)
    assert np.all(from_starboard[:, Y] < 0.0) and np.all(from_port[:, Y] > 0.0)
    assert np.allclose(from_starboard[:, Y], -ahead[:, X], rtol=1e-12)
    assert np.allclose(from_starboard[:, X], ahead[:, Y], rtol=1e-12, atol=1e-12)
    head = table(w, math.pi)[:, X]
    file_head = cylinder.values[cylinder.omega >= 1.9, 0, X]
    assert np.all(np.abs(head - file_head) <= 0.03 * np.abs(file_head) + 0.012 * np.abs(cylinder.values).max())
    assert np.allclose(table(w, 0.3)[:, N], ahead[:, N], rtol=1e-12)  # yaw: the same for every heading
    with pytest.raises(FileFormatError) as error:
        read_aqwa_drift(CYLINDER)
    assert "gap of 180 deg" in str(error.value) and "-180, 0 deg" in str(error.value)
    assert "axisymmetric=True" in str(error.value)


def test_turned_round_keeps_a_turned_body_turned():
    """Loads given at 30 deg of a symmetric body, turned back and round, give back the 30 deg loads and those at
    any other heading are the 30 deg force vector turned by the difference: (X, Y) = (1, 0) at 0 deg becomes
    (0, -1) at +90 deg (pushed to port)."""
    values = np.array([[[math.cos(math.radians(30.0)), -math.sin(math.radians(30.0)), 0.2]]])  # (1, 0) turned 30
    beta, turned, note = turned_round(np.array([30.0]), values)
    at = {round(math.degrees(b)): v for b, v in zip(beta, turned[0])}
    assert np.allclose(at[0], [1.0, 0.0, 0.2]) and np.allclose(at[90], [0.0, -1.0, 0.2])
    assert np.allclose(at[30], values[0, 0]) and np.allclose(at[-180], [-1.0, 0.0, 0.2])
    assert "30 deg turned to 0 deg" in note


def test_aqwa_malformed_tables_are_refused_at_their_line(tmp_path):
    """A row short of a direction's value, a value that is not a number, a frequency row missing from a load, a
    structure without drift pages and a listing in other units: each refused, naming the line where it can."""
    lines = CYLINDER.read_text().splitlines()
    path = tmp_path / "cut.LIS"

    def refused(changed: list[str]) -> FileFormatError:
        path.write_text("\n".join(changed) + "\n")
        with pytest.raises(FileFormatError) as error:
            aqwa_drift_loads(path)
        return error.value

    number = next(n for n, text in enumerate(lines, 1) if text.split()[:1] == ["0.467"] and "1.94E-03" in text)
    short = list(lines)
    short[number - 1] = short[number - 1].replace("  1.90E-03", "")
    error = refused(short)
    assert error.line == number and "expected FREQ and 3 value(s)" in str(error)

    broken = list(lines)
    broken[number - 1] = broken[number - 1].replace("1.90E-03", "1.9OE-03")
    error = refused(broken)
    assert error.line == number and "'1.9OE-03'" in str(error)

    sway = next(n for n, text in enumerate(lines, 1) if text.split()[:1] == ["0.467"] and "1.95E-02" in text)
    error = refused(lines[: sway - 1] + lines[sway:])
    assert "no SWAY(Y) drift for direction -180 deg at 0.467 rad/s" in str(error)
    assert error.line == number  # the first row of that frequency

    with pytest.raises(FileFormatError, match="of structure 2; structures with one: 1"):
        aqwa_drift_loads(CYLINDER, structure=2)
    with pytest.raises(ParameterError):
        aqwa_drift_loads(CYLINDER, structure=0)
    units = [text.replace("Metric: kg, m [N]", "Imperial: slug, ft [lbf]") for text in lines]
    error = refused(units)
    assert error.line == 13 and "only SI listings" in str(error)


# --- NEMOH v3: WEC-Sim's OC3-Hywind spar, one heading (0 deg), 0.25..1.5 rad/s ---


def _nemoh_row(w: str, dof: int) -> list[float]:
    """The numbers of the shipped file's diagonal row at frequency ``w`` (as printed) for ``dof``."""
    for text in OC3_QTF.read_text().splitlines()[1:]:
        words = text.split()
        if words[0] == w and words[1] == w and int(words[4]) == dof:
            return [float(v) for v in words]
    raise AssertionError(f"no row {w} {dof}")


def test_nemoh_values_by_hand_give_units_and_axes(spar):
    """NEMOH divides by rho g (its header says so): Re times 1025 * 9.81 from Nemoh.cal gives N/m^2 and N m/m^2;
    sway and yaw change sign to the manoeuvring axes. Missing rho g misses by 1e4, a missed axis turn flips Y and
    N. The file's own anomalies pass through unchanged: at 1.0 rad/s it says -26.5 rho g (pushed against the
    waves, which no single body without current does: Maruo's far-field drift is >= 0), and the reader keeps it."""
    assert spar.omega.size == 26 and np.allclose(spar.omega, np.arange(0.25, 1.5001, 0.05))
    assert spar.headings_deg.tolist() == [0.0]
    i = int(np.flatnonzero(np.isclose(spar.omega, 0.5))[0])
    surge, sway, yaw = (_nemoh_row("0.500", dof)[7] for dof in (1, 2, 6))
    assert (surge, sway, yaw) == (0.5030305, -0.1981014e-06, -0.4562654e-05)
    assert spar.values[i, 0].tolist() == pytest.approx([surge * OC3_RHO_G, -sway * OC3_RHO_G, -yaw * OC3_RHO_G],
                                                       rel=1e-12)
    assert spar.values[i, 0, X] == pytest.approx(5058.1, rel=1e-4)
    j = int(np.flatnonzero(np.isclose(spar.omega, 1.0))[0])
    assert spar.values[j, 0, X] == pytest.approx(_nemoh_row("1.000", 1)[7] * OC3_RHO_G, rel=1e-12)
    assert spar.values[j, 0, X] < 0.0
    notes = " ".join(spar.notes)
    assert "rho g = 1025 * 9.81" in notes and "(0, 0) m" in notes and "975 row(s) with w1 != w2" in notes
    scaled = nemoh_drift_loads(OC3_QTF, rho=1000.0, g=9.80665)
    assert np.allclose(scaled.values, spar.values * 1000.0 * 9.80665 / OC3_RHO_G, rtol=1e-12)
    assert any("rho 1000 kg/m^3 given (Nemoh.cal says 1025)" in note for note in scaled.notes)


def test_nemoh_spar_drifts_with_the_waves_and_turns_with_them(spar):
    """Waves along +x push the spar along +x in long waves (0.25..0.7 rad/s; the file turns negative at 0.75..1.0
    and 1.4..1.5 rad/s, see test above and the README), the run being symmetric about the x-z plane its sway
    drift is under 2e-4 of the surge drift there and its yaw drift that of the surge drift acting under a
    millimetre off the centreline (the spar is 6.5 to 9.4 m wide). Turned round the circle (the spar is
    axisymmetric): head seas push it astern, waves from starboard to port. A reversed sway convention or turn
    pushes it to starboard."""
    long = spar.omega <= 0.7
    surge = spar.values[long, 0, X]
    assert np.all(surge > 0.0)
    assert np.all(np.abs(spar.values[long, 0, Y]) < 2e-4 * surge)
    assert np.all(np.abs(spar.values[long, 0, N]) < 1e-3 * surge)
    table = read_nemoh_drift(OC3_QTF, axisymmetric=True)
    w = spar.omega[long]
    assert np.allclose(table(w, 0.0)[:, X], surge, rtol=1e-12)
    assert np.all(table(w, math.pi)[:, X] < 0.0)
    assert np.all(table(w, math.pi / 2)[:, Y] < 0.0) and np.all(table(w, -math.pi / 2)[:, Y] > 0.0)
    with pytest.raises(FileFormatError, match="gap of 360 deg.*heading.s. 0 deg.*axisymmetric=True"):
        read_nemoh_drift(OC3_QTF)


def _synthetic(path: Path, header: str, rows: list[tuple[float, float, float, float, int, float]]) -> Path:
    """An OUT_QTFM_N-layout file of ``rows`` (w1, w2, beta1, beta2, DOF, Re/rho/g), written as NEMOH writes it."""
    text = [header] + [f"{w1:12.3f} {w2:12.3f} {b1:12.3f} {b2:12.3f} {dof:2d} {abs(re):14.7E} "
                       f"{0.0 if re >= 0 else 180.0:14.7E} {re:14.7E} {0.0:14.7E}" for w1, w2, b1, b2, dof, re in rows]
    path.write_text("\n".join(text) + "\n")
    return path


HEADER = ("      f1[Hz]       f2[Hz] beta1 [deg] beta2[deg] DOF MOD(QTF)/rho/g PHASE(QTF)[deg] Re(QTF)/rho/g "
          "Im(QTF)/rho/g")


def test_nemoh_headings_through_radians_frequencies_in_hz_and_left_out_rows(tmp_path):
    """NEMOH prints beta through radians with three decimals (90 deg reads 90.011, 180 deg 180.023): rounded to
    0.1 deg, 0..180 is a half range the mirror completes; without the rounding 180.023 would wrap to -179.977 and
    leave the port side a gap. Hz becomes 2 pi f; off-diagonal, bidirectional and heave rows are left out with
    notes. Without Nemoh.cal, rho and g must be given."""
    rows = []
    for f in (0.1, 0.2):
        for b in (0.0, 90.011, 180.023):
            for dof, re in ((1, 1.0 - b / 90.0), (2, -b / 1000.0 - 0.5), (3, 7.0), (6, 0.25)):
                rows.append((f, f, b, b, dof, re * f))
            rows.append((f, f, b, 45.0, 1, 9.0))  # bidirectional
        rows.append((0.2, 0.1, 0.0, 0.0, 1, 3.0))  # slowly varying
    path = _synthetic(tmp_path / "OUT_QTFM_N.dat", HEADER, rows)
    with pytest.raises(FileFormatError, match="no Nemoh.cal .* give rho and g"):
        nemoh_drift_loads(path)
    loads = nemoh_drift_loads(path, rho=1000.0, g=10.0)
    assert loads.headings_deg.tolist() == [0.0, 90.0, 180.0]
    assert np.allclose(loads.omega, [2.0 * math.pi * 0.1, 2.0 * math.pi * 0.2])
    notes = " ".join(loads.notes)
    assert "w1 != w2" in notes and "beta1 != beta2" in notes and "DOF 3 left out" in notes
    table = read_nemoh_drift(path, rho=1000.0, g=10.0)
    assert np.allclose(np.degrees(table.beta), [-180.0, -90.0, 0.0, 90.0])
    at = table(2.0 * math.pi * 0.2, np.radians([90.0, -90.0]))
    sway_90 = -(-90.011 / 1000.0 - 0.5) * 0.2 * 1e4
    assert at[0, Y] == pytest.approx(sway_90, rel=1e-6) and at[1, Y] == pytest.approx(-sway_90, rel=1e-6)
    assert at[0, X] == pytest.approx((1.0 - 90.011 / 90.0) * 0.2 * 1e4, rel=1e-6)


def test_nemoh_malformed_files_are_refused_at_their_line(tmp_path):
    """A short row, a non-number, a diagonal row missing (its cell lacks sway), a one-contribution file in radians,
    a sum-frequency file and a file of other columns: each refused, at its line where it has one."""
    root = tmp_path / "run"
    (root / "results" / "QTF").mkdir(parents=True)
    (root / "Nemoh.cal").write_text((OC3 / "Nemoh.cal").read_text())
    lines = OC3_QTF.read_text().splitlines()
    path = root / "results" / "QTF" / "OUT_QTFM_N.dat"

    def refused(changed: list[str], target: Path = path) -> FileFormatError:
        target.write_text("\n".join(changed) + "\n")
        with pytest.raises(FileFormatError) as error:
            nemoh_drift_loads(target)
        return error.value

    short = list(lines)
    short[21] = " ".join(short[21].split()[:8])
    error = refused(short)
    assert error.line == 22 and "expected 9 columns" in str(error)

    broken = list(lines)
    broken[21] = broken[21].replace("0.5030305E+00", "0.503O305E+00", 1)
    error = refused(broken)
    assert error.line == 22 and "'0.503O305E+00'" in str(error)

    error = refused(lines[:372] + lines[373:])  # line 373: 0.5 rad/s, DOF 2
    assert error.line == 22 and "DOF 2 missing for 0.5 rad/s, beta 0 deg" in str(error)

    duok = ["w1[rad/s] w2[rad/s] beta1 [rad] beta2[rad] DOF Re(QTF) Im(QTF)"] + lines[1:]
    error = refused(duok)
    assert error.line == 1 and "QTFM_DUOK.dat" in str(error)

    error = refused(lines, root / "results" / "QTF" / "OUT_QTFP_N.dat")
    assert "sum-frequency" in str(error)

    error = refused(["PER BETA1 BETA2 I MOD PHA RE IM"] + lines[1:])
    assert error.line == 1 and "expected NEMOH's QTF header" in str(error)

