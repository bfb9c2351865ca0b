"""`marinesim hull`: a hull file's hydrostatics as a report."""

import json

import pytest

from conftest import ROOT
from marinesim.cli import main


def test_hull_command(capsys):
    assert main(["hull", str(ROOT / "hulls" / "box_barge.stl"), "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["volume_m3"] == pytest.approx(100 * 20 * 5, rel=1e-6)
    assert report["waterplane_area_m2"] == pytest.approx(100 * 20, rel=1e-6)
