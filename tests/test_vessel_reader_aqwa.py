"""The AQWA ``.LIS`` reader on a real listing (WEC-Sim's cylinder, tests/data/aqwa/README.md): AQWA's phase
lag, direction and deg/m conventions converted once, checked against physics rather than stored numbers."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from marinesim.errors import FileFormatError, ParameterError
from marinesim.sea.dispersion import k_from_omega
from marinesim.vessel.aqwa import aqwa_to_internal, read_aqwa, read_aqwa_raos, sniff
from marinesim.vessel.rao import long_wave_limit

DATA = Path(__file__).parent / "data" / "aqwa"
CYLINDER = DATA / "cylinder_excerpt.LIS"
SURGE, SWAY, HEAVE, ROLL, PITCH, YAW = range(6)


@pytest.fixture(scope="module")
def cylinder():
    return read_aqwa_raos(CYLINDER)


def test_listing_parameters_are_read(cylinder):
    """rho, g and the 3 m tank depth come from the listing: the long-wave surge limit depends on the depth."""
    assert cylinder.rho == pytest.approx(1025.0)
    assert cylinder.g == pytest.approx(9.807)
    assert cylinder.depth == pytest.approx(3.0)
    assert cylinder.reference_point == pytest.approx((0.0, 0.0, 0.0))
    assert list(cylinder.headings_deg) == [0.0, 180.0]  # -180 and 180 are one heading
    assert np.all(np.diff(cylinder.omega) > 0) and cylinder.omega.size == 50


@pytest.mark.parametrize("heading", [0, 1])
def test_long_wave_limits(cylinder, heading):
    """At the lowest frequency (0.04 rad/s, 850 m waves in 3 m of water) the free-floating cylinder follows the
    wave: heave 1, surge -i cos(beta) / tanh(kh), pitch i k cos(beta) (marinesim's lead convention, rad/m).
    Unconverted phase lag would give surge +i; deg/m left as read, pitch 57 times too large; the direction read as
    "coming from", surge and pitch of the wrong sign."""
    beta = math.radians(cylinder.headings_deg[heading])
    w = cylinder.omega[:1]
    expected = long_wave_limit(w, np.array([beta]), cylinder.g, cylinder.depth)[0]
    got = cylinder.values[heading, 0]
    assert got[HEAVE] == pytest.approx(expected[HEAVE], abs=0.01)
    assert abs(got[SURGE] - expected[SURGE]) < 0.01 * abs(expected[SURGE])
    k = k_from_omega(w, cylinder.depth, cylinder.g)[0]
    assert abs(got[PITCH] - expected[PITCH]) < 0.03 * k


def test_opposite_headings_mirror(cylinder):
    """The cylinder is symmetric fore and aft: waves along -X give the same heave and the same |surge|, |pitch|
    as waves along +X, with surge and pitch of opposite sign (reflection x -> -x), at every frequency."""
    ahead, astern = cylinder.values
    scale = np.abs(ahead) + np.abs(astern)
    tolerance = 0.01 * scale + 2e-4
    assert np.all(np.abs(ahead[:, HEAVE] - astern[:, HEAVE]) <= tolerance[:, HEAVE])
    for dof in (SURGE, PITCH):
        assert np.all(np.abs(np.abs(ahead[:, dof]) - np.abs(astern[:, dof])) <= tolerance[:, dof])
        big = np.abs(ahead[:, dof]) > 0.1 * np.abs(ahead[:, dof]).max()
        assert np.all(np.sign(ahead[big, dof].imag) == -np.sign(astern[big, dof].imag))


def test_heave_resonance_is_where_hydrostatics_put_it(cylinder):
    """The heave peak sits at a frequency where |heave| > 1 and the phase passes through -90 deg (lead
    convention: the response lags the wave by a quarter period at resonance)."""
    heave = cylinder.values[0, :, HEAVE]
    peak = int(np.argmax(np.abs(heave)))
    assert abs(heave[peak]) > 2.0
    phase = np.degrees(np.angle(heave))
    assert phase[peak - 2] > -45.0 and phase[peak + 2] < -135.0


def test_conversion_function():
    """One conversion: lag 90 deg -> -i; 57.3 deg/m -> 1 rad/m."""
    h = aqwa_to_internal(np.array([1.0, 1, 1, 180 / math.pi, 1, 1]), np.array([90.0, 0, 0, 0, 0, 0]))
    assert h[0] == pytest.approx(-1j) and h[3] == pytest.approx(1.0)


def test_the_partial_heading_set_makes_a_table_of_what_it_covers(cylinder):
    """Only 0 and 180 deg: a partial table covering each +-15 deg, answering head seas with the listing's own
    180 deg RAOs (a sea it does not cover is refused when a run meets it: test_vessel_rao_partial_headings.py)."""
    table = read_aqwa(CYLINDER)
    assert table.covered_text() == "165..195 deg (tabulated 180), 345..15 deg (tabulated 0)"
    head = list(cylinder.headings_deg).index(180.0)
    np.testing.assert_allclose(table(cylinder.omega, np.full(cylinder.omega.size, math.pi)), cylinder.values[head])


def test_sniff():
    assert sniff(CYLINDER.read_bytes()[:4096])
    assert not sniff(b"0.1 0 1 1.0 0 1.0 0\n")


def test_other_structure_is_refused():
    with pytest.raises(FileFormatError, match="structure 2.*structures with RAO tables: 1"):
        read_aqwa_raos(CYLINDER, structure=2)
    with pytest.raises(ParameterError):
        read_aqwa_raos(CYLINDER, structure=0)


def test_malformed_listings_name_the_line(tmp_path):
    """A damaged number is reported with its line; a file without RAO tables says so; binary junk is refused."""
    lines = CYLINDER.read_text().splitlines()
    row = next(i for i, text in enumerate(lines) if text.strip().startswith("157.08"))
    broken = lines.copy()
    broken[row] = broken[row].replace("45.2109", "45.2x09")
    path = tmp_path / "broken.LIS"
    path.write_text("\n".join(broken))
    with pytest.raises(FileFormatError, match=f"line {row + 1}"):
        read_aqwa_raos(path)
    empty = tmp_path / "empty.LIS"
    empty.write_text("\n".join(lines[:60]))
    with pytest.raises(FileFormatError, match="no position RAO table"):
        read_aqwa_raos(empty)
    junk = tmp_path / "junk.LIS"
    junk.write_bytes(bytes(range(256)) * 8)
    with pytest.raises(FileFormatError):
        read_aqwa_raos(junk)
    missing_direction = lines.copy()
    del missing_direction[row + 1]  # heading 0 deg missing at the first frequency
    path.write_text("\n".join(missing_direction))
    with pytest.raises(FileFormatError, match="no RAOs for direction 0"):
        read_aqwa_raos(path)
