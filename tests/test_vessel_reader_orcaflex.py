"""OrcaFlex vessel-type displacement RAOs (.yml) on the documented example (tests/data/orcaflex; no OrcaFlex export
with displacement RAOs and a known licence is public).

The example carries the HAMS cylinder's RAOs in OrcaFlex's default conventions (periods, phase lags in degrees,
rotations in deg/m, directions 0-180 with xz symmetry). It is checked against physics (long-wave limits), against
the HAMS run read by the HydroStar reader (an independent path through other conventions), and each convention
setting is checked by rewriting the file in the other setting: the table must not change.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

from conftest import ROOT
from marinesim.errors import FileFormatError
from marinesim.sea.dispersion import k_from_omega
from marinesim.vessel.hydrostar import read_hydrostar
from marinesim.vessel.orcaflex import COLUMNS, TABLE_KEY, read_orcaflex, sniff
from marinesim.vessel.rao import MIRROR_SIGN

EXAMPLE = ROOT / "tests" / "data" / "orcaflex" / "cylinder_vessel_type.yml"
HAMS = ROOT / "tests" / "data" / "hams" / "cylinder" / "Output" / "Hydrostar_format" / "Motion_3.rao"
DEPTH = 10.0  # the HAMS run's water depth (an OrcaFlex vessel type does not carry it)


@pytest.fixture(scope="module")
def table():
    return read_orcaflex(EXAMPLE)


@pytest.fixture(scope="module")
def hams():
    return read_hydrostar(HAMS)


def _headings(t) -> np.ndarray:
    return np.round(np.degrees(t.beta)).astype(int)


def test_long_wave_limits(table):
    """Lowest frequency: heave 1 at phase 0, pitch +i k cos b, roll -i k sin b (k in the run's 10 m depth). Reading
    OrcaFlex's phase lags as leads would give pitch -i k cos b; deg/m read as rad/m, pitch / k = 57; direction
    180 read as 'coming from' would flip the sign of pitch in head and following seas."""
    h = table.values[0, :, 0]
    b = table.beta
    k = float(k_from_omega(table.omega[0], DEPTH))
    np.testing.assert_allclose(h[:, 2], 1.0, atol=0.01)
    for j, expected, weight in ((4, 1j * k * np.cos(b), np.abs(np.cos(b))), (3, -1j * k * np.sin(b), np.abs(np.sin(b)))):
        strong = weight > 0.5
        ratio = h[strong, j] / expected[strong]
        np.testing.assert_allclose(np.abs(ratio), 1.0, atol=0.1)
        np.testing.assert_allclose(np.angle(ratio, deg=True), 0.0, atol=5.0)


def test_equals_the_hams_run_it_was_written_from(table, hams):
    """At the file's directions the table equals the HydroStar reader's (printed precision: 6 digits, 1e-3 deg),
    and at the mirrored directions 210-330 it matches HAMS's own computation there within the mesh's asymmetry."""
    assert table.mirrored and set(_headings(table)) == set(range(0, 360, 30))
    np.testing.assert_allclose(table.omega, hams.omega, rtol=1e-5)
    theirs = {h: i for i, h in enumerate(_headings(hams))}
    for i, h in enumerate(_headings(table)):
        mine, ref = table.values[0, i], hams.values[0, theirs[h]]
        peak = np.abs(hams.values[0]).max(axis=(0, 1))
        tolerance = 1e-4 if h <= 180 else 0.15  # given vs mirrored (the cylinder mesh is not exactly symmetric)
        assert np.all(np.abs(mine - ref).max(axis=0)[:5] <= tolerance * peak[:5]), f"direction {h}"


def test_port_and_starboard_mirror(table):
    """Directions b and 360 - b: surge, heave, pitch equal; sway, roll, yaw opposite (Symmetry: xz plane completes
    the 0-180 table). 0 and 180 are their own mirrors and keep the file's values."""
    headings = list(_headings(table))
    for i, h in enumerate(headings):
        if h in (0, 180):
            continue
        j = headings.index((360 - h) % 360)
        np.testing.assert_allclose(table.values[0, j], table.values[0, i] * MIRROR_SIGN, atol=1e-12)


def _rewrite(tmp_path: Path, change) -> Path:
    """A copy of the example with ``change(vessel_type, rows_of_each_direction)`` applied."""
    data = yaml.safe_load(EXAMPLE.read_text())
    vt = data["VesselTypes"][0]
    tables = [entry[TABLE_KEY] for entry in vt["Draughts"][0]["DisplacementRAOs"]["RAOs"]]
    change(vt, tables)
    out = tmp_path / "changed.yml"
    out.write_text(yaml.safe_dump(data, sort_keys=False))
    return out


def _each(tables, column, function):
    c = COLUMNS.index(column)
    for rows in tables:
        for row in rows:
            row[c] = function(row[c])


@pytest.mark.parametrize("name, change", [
    ("leads", lambda vt, t: (vt.update(RAOPhaseConvention="leads"),
                             [_each(t, f"RAO{d}Phase", lambda p: -p) for d in ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")])),
    ("phase radians", lambda vt, t: (vt.update(RAOPhaseUnitsConvention="radians"),
                                     [_each(t, f"RAO{d}Phase", math.radians) for d in ("Surge", "Heave", "Roll", "Pitch", "Sway", "Yaw")])),
    ("rotations rad/m", lambda vt, t: (vt.update(RAOResponseUnits="radians"),
                                       [_each(t, f"RAO{d}Amp", math.radians) for d in ("Roll", "Pitch", "Yaw")])),
    ("frequency", lambda vt, t: (vt.update(WavesReferredToBy="frequency (rad/s)"),
                                 _each(t, "RAOPeriodOrFrequency", lambda p: 2 * math.pi / p))),
    ("trough", lambda vt, t: (vt.update(RAOPhaseRelativeToConvention="trough"),
                              [_each(t, f"RAO{d}Phase", lambda p: p - 180.0) for d in ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")])),
    ("sway to starboard", lambda vt, t: (vt.update(SwayPositive="starboard"), _each(t, "RAOSwayPhase", lambda p: p + 180.0))),
    ("height", lambda vt, t: (vt.update(RAOWaveUnit="height"),
                              [_each(t, f"RAO{d}Amp", lambda a: a / 2) for d in ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")])),
])
def test_each_convention_setting_is_converted(tmp_path, table, name, change):
    """The same motions written in another OrcaFlex convention read as the same table."""
    other = read_orcaflex(_rewrite(tmp_path, change))
    np.testing.assert_allclose(other.omega, table.omega, rtol=1e-12)
    np.testing.assert_allclose(other.values, table.values, rtol=0, atol=1e-9 * np.abs(table.values).max())


def test_phase_origin_ahead_of_the_rao_origin(tmp_path, table):
    """Phases measured from the crest at a point 10 m ahead: in head seas the crest reaches it k 10 earlier, so
    the same motion has a phase lag larger by k 10 there (deep water); re-referred, the table is unchanged."""
    def change(vt, tables):
        vt["Draughts"][0]["DisplacementRAOs"]["PhaseOrigin"] = [10.0, 0.0, None]
        for entry, rows in zip(vt["Draughts"][0]["DisplacementRAOs"]["RAOs"], tables):
            cos_b = math.cos(math.radians(entry["RAODirection"]))
            for row in rows:
                k = (2 * math.pi / row[0]) ** 2 / 9.80665
                for c in range(2, 13, 2):
                    row[c] -= math.degrees(k * 10.0 * cos_b)  # the crest passes x = 10 at w t = k 10 cos b
    other = read_orcaflex(_rewrite(tmp_path, change))
    np.testing.assert_allclose(other.values, table.values, rtol=0, atol=1e-9 * np.abs(table.values).max())


@pytest.mark.parametrize("old, new, message", [
    ("  UnitsSystem: SI", "  UnitsSystem: US", r"line \d+: UnitsSystem 'US'"),
    ("RAOPhaseConvention: lags", "RAOPhaseConvention: sideways", r"line 15: RAOPhaseConvention 'sideways'"),
    ("- [1.1584, 0.193528, 17.498, ", "- [1.1584, 17.498, ", r"line 35: expected a row of 13 numbers"),
    ("- [1.1584, 0.193528,", "- [1.1584, x0.193528,", r"line 35: expected RAOSurgeAmp"),
    ("          RAOs:", "          RAOs: [", r"line \d+: not valid YAML"),
    ("DisplacementRAOs:", "LoadRAOs:", r"no DisplacementRAOs"),
])
def test_malformed_copies_name_the_line(tmp_path, old, new, message):
    text = EXAMPLE.read_text()
    assert old in text
    bad = tmp_path / "bad.yml"
    bad.write_text(text.replace(old, new, 1))
    with pytest.raises(FileFormatError, match=message):
        read_orcaflex(bad)


def test_sniffer():
    assert sniff(EXAMPLE.read_bytes()[:4096])
    assert not sniff(HAMS.read_bytes()[:4096])
