"""What a naval architect would say of an RAO table: surge and sway that no floating body has are noted where
the table is read (``marinesim rao``, the export's console and sidecar), naming where and against what."""

from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from marinesim.constants import KNOT
from marinesim.vessel import read_rao
from marinesim.vessel.rao import make_table

DATA = ROOT / "tests" / "data"


def implausible(table) -> list[str]:
    return [note for note in table.notes if note.startswith("implausible")]


def test_the_s175s_surge_at_20_knots_is_noted_as_the_files():
    """The VERES file itself gives the S175 a surge RAO of 2.65 m/m at 20 kn in head seas (the reader converts
    only the heading to radians; at 0 kn its surge stays under 1.0): the note says so, with the figures."""
    table = read_rao(ROOT / "rao" / "s175" / "input.re1")
    notes = implausible(table)
    assert len(notes) == 1 and "at speed: 2.65 m/m at 20 kn" in notes[0] and "0.996 m/m" in notes[0], notes
    at_rest = np.abs(table.values[0, ..., 0]).max()
    fastest = np.abs(table.values[-1, ..., 0]).max()
    assert table.speed[-1] / KNOT == pytest.approx(20.0, abs=0.01) and fastest / at_rest > 2.5


@pytest.mark.parametrize("path", [ROOT / "rao" / "tanker" / "tanker.4", ROOT / "rao" / "semisub" / "semisub.4",
                                  ROOT / "rao" / "supply" / "input.re1", DATA / "aqwa" / "cylinder_excerpt.LIS",
                                  DATA / "hams" / "cylinder" / "Output" / "Hydrostar_format" / "Motion_3.rao"])
def test_real_tables_of_sound_sources_carry_no_such_note(path):
    """WAMIT, VERES at low speed, AQWA and HAMS tables (the HAMS cylinder's surge reaches 2.1 times the orbit
    near its resonances) are not flagged: a failure means the rule cries wolf."""
    assert implausible(read_rao(path)) == []


def test_a_surge_table_in_feet_or_centimetres_is_noted():
    """A surge RAO of 30 m/m (a table in cm read as m) is 30 times the orbit of a deep-water wave."""
    omega = np.array([0.3, 0.6])
    values = np.zeros((1, 3, 2, 6), complex)
    values[..., 0] = 30.0
    notes = implausible(make_table(omega, np.radians([0.0, 90.0, 180.0]), [0.0], values))
    assert len(notes) == 1 and "implausible surge RAO: 30 m/m" in notes[0] and "30 times the wave orbit" in notes[0]
