"""`marinesim sea` as a user runs it: a real process, real files read back."""

import json
import math

import numpy as np
import pandas as pd
import pytest

from conftest import cli


def test_sea_json_reports_spectrum_and_surface(tmp_path):
    csv = tmp_path / "spectrum.csv"
    png = tmp_path / "sea.png"
    result = cli("sea", "--hs", "4", "--tp", "10", "--gamma", "3.3", "--from-deg", "30", "--spreading-s", "15",
                 "--depth", "50", "--seed", "1", "--json", "--spectrum-csv", str(csv), "--plot", str(png))
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    assert report["hs_spectrum_m"] == pytest.approx(4.0, rel=1e-6)
    assert report["tp_spectrum_s"] == pytest.approx(10.0, rel=1e-4)
    assert report["mean_from_deg_spectrum"] == pytest.approx(30.0)
    assert report["hs_surface_m"] == pytest.approx(4.0, rel=0.1)  # one realisation: ~4% scatter
    assert abs(report["mean_from_deg_surface"] - 30.0) < 3.0
    assert report["m0_fraction"] >= 0.99
    assert len(report["tiles"]) == 4 and report["depth_m"] == 50.0
    # the spectrum CSV reads back with pandas defaults and integrates to Hs
    frame = pd.read_csv(csv)
    assert list(frame.columns) == ["omega_rad_s", "S_m2s_rad"]
    m0 = np.trapezoid(frame["S_m2s_rad"], frame["omega_rad_s"])
    assert 4 * math.sqrt(m0) == pytest.approx(4.0, rel=0.01)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 20_000
    assert not list(tmp_path.glob(".*.part*"))  # atomic writes leave no temporary files


def test_sea_text_summary_swell_and_regular():
    result = cli("sea", "--hs", "2", "--tp", "7", "--swell-hs", "1.5", "--swell-tp", "15",
                 "--swell-from-deg", "250", "--swell-spreading-s", "60", "--tiles", "3")
    assert result.returncode == 0, result.stderr
    assert "3 tiles carry" in result.stdout and "surface at t=0 s" in result.stdout
    regular = cli("sea", "--spectrum", "regular", "--height", "2", "--period", "8", "--json")
    report = json.loads(regular.stdout)
    assert report["tp_spectrum_s"] == pytest.approx(8.0)
    assert report["hs_surface_m"] == pytest.approx(2.0 * math.sqrt(2.0), rel=1e-3)  # Hs = 4 sqrt(H^2/8)
