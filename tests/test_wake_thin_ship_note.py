"""Thin-ship validity (marinesim/wake/compute.py, thin_ship_note; ``marinesim wake``): Michell's wave resistance is
reported with a caveat exactly when the hull is not a thin, fine ship (B/L > 0.15 or Cb > 0.7), the hulls for which
it gives implausible numbers, and without one for the slender hulls it is validated on."""

import json

import pytest

from conftest import ROOT
from marinesim.cli import main
from marinesim.hull import box_hull, hydrostatics, wigley_hull
from marinesim.wake.compute import thin_ship_note


@pytest.mark.parametrize("hull, expected", [
    (wigley_hull(100.0, 10.0, 6.25), None),  # Wigley: B/L 0.10, Cb 0.44, the thin ship itself
    (wigley_hull(100.0, 14.0, 6.25), None),  # B/L 0.14: still slender
    (wigley_hull(100.0, 16.0, 6.25), ["B/L 0.16 > 0.15"]),  # fine (Cb 0.44) but beamy
    (box_hull(100.0, 10.0, 5.0), ["block coefficient 1 > 0.7"]),  # slender (B/L 0.1) but full
    (box_hull(100.0, 50.0, 5.0), ["B/L 0.5 > 0.15", "block coefficient 1 > 0.7"]),  # the B/L 0.5 barge
])
def test_note_names_each_limit_the_hull_breaks(hull, expected):
    """Each criterion on its own: a slender full barge gets the Cb caveat only, a beamy fine hull the B/L one; a
    note on the Wigley hull would caveat the case thin-ship theory is right for, a missing one would pass a barge's
    Cw as a resistance."""
    note = thin_ship_note(hydrostatics(hull))
    if expected is None:
        assert note is None
    else:
        assert note.startswith("this hull is outside thin-ship validity") and all(part in note for part in expected)
        assert ("B/L" in note) == any("B/L" in part for part in expected)
        assert ("block coefficient" in note) == any("block" in part for part in expected)


def test_wake_command_caveats_the_barge_whose_cw_is_implausible(capsys):
    """At the same Fn 0.197 the box barge's Michell Cw is over a hundred times the Wigley hull's (order 1e-3, as
    real hulls): that barge, and not the Wigley hull, carries the note in the JSON and in the text report."""
    reports = {}
    for name in ("box_barge", "wigley"):
        args = ["wake", str(ROOT / "hulls" / f"{name}.stl"), "--speed-kn", "12", "--nx", "64", "--ny", "32",
                "--no-cache", "--quiet"]
        assert main([*args, "--json"]) == 0
        reports[name] = json.loads(capsys.readouterr().out)
        assert main(args) == 0
        reports[name]["text"] = capsys.readouterr().out
    barge, wigley = reports["box_barge"], reports["wigley"]
    assert barge["froude"] == pytest.approx(wigley["froude"])
    assert wigley["wave_resistance_coefficient"] < 2e-3 < 0.05 < barge["wave_resistance_coefficient"]
    assert "B/L 0.2 > 0.15 and block coefficient 1 > 0.7" in barge["thin_ship_note"]
    assert "note: this hull is outside thin-ship validity (B/L 0.2" in barge["text"]
    assert "thin_ship_note" not in wigley and "thin-ship validity" not in wigley["text"]
