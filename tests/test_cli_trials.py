"""``marinesim trials`` as a user runs it (in-process): the IMO standard manoeuvres of a manoeuvring file or a
scenario's vessel, the JSON it prints, the plot it draws, and bad inputs refused in one line with exit 2,
nothing written."""

from __future__ import annotations

import json

import numpy as np
import pytest
from PIL import Image

from conftest import ROOT, write
from marinesim.cli import main

KVLCC2 = ROOT / "configs" / "vessels" / "kvlcc2.toml"


def test_json_has_exactly_the_imo_trials_of_the_kvlcc2(tmp_path, capsys):
    """``--json`` prints the turning circles, zig-zags, crash stop and the IMO verdict with exactly the keys the
    issue names; the KVLCC2's turning circle is the free-running tests' (3.1 L), every criterion met; the plot is
    a picture of the tracks and the zig-zags."""
    plot = tmp_path / "trials.png"
    assert main(["trials", str(KVLCC2), "--json", "--plot", str(plot)]) == 0
    result = json.loads(capsys.readouterr().out)
    assert set(result) == {"turning", "zigzag", "stopping", "imo"}
    assert set(result["turning"]) == {"port", "starboard"}
    for side in ("port", "starboard"):
        assert set(result["turning"][side]) == {"rudder_deg", "advance_m", "transfer_m", "tactical_diameter_m",
                                                "steady_diameter_m", "final_speed_kn"}
        assert result["turning"][side]["advance_m"] / 320.0 == pytest.approx(3.1, abs=0.1)
    assert result["turning"]["port"]["rudder_deg"] == -35.0 and result["turning"]["starboard"]["rudder_deg"] == 35.0
    assert set(result["zigzag"]) == {"10/10", "20/20"}
    assert all(set(z) == {"first_overshoot_deg", "second_overshoot_deg"} for z in result["zigzag"].values())
    assert set(result["stopping"]) == {"track_reach_m", "head_reach_m", "time_s"}
    assert result["imo"]["pass"] is True and len(result["imo"]["criteria"]) == 9
    assert {c["name"] for c in result["imo"]["criteria"]} >= {"advance, port", "20/20 zig-zag, first overshoot",
                                                              "crash stop, track reach"}
    with Image.open(plot) as image:
        assert image.size == (1200, 1000)
        colours = len(np.unique(np.asarray(image.convert("RGB")).reshape(-1, 3), axis=0))
    assert colours > 50  # tracks, traces and a table drawn, not a blank page


def test_a_scenario_is_trialled_from_its_speed_and_a_vessel_on_station_is_refused(tmp_path, capsys):
    """The heavy-weather transit's S175 at her 10 kn (the table names the approach); the semisubmersible held on
    station has no manoeuvring model: one line, exit 2."""
    assert main(["trials", str(ROOT / "configs" / "training" / "heavy_weather_transit.toml"), "--quiet"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("S175: L 175.0 m, approach 10.00 kn, calm water") and "IMO MSC.137(76): " in out
    assert main(["trials", str(ROOT / "configs" / "training" / "helideck_landing.toml"), "--quiet"]) == 2
    error = capsys.readouterr().err.strip()
    assert error.endswith("no manoeuvring model to trial") and "\n" not in error


BAD = {
    "a missing coefficient": (("n_r = -0.049\n", ""), "mmg.n_r: required"),
    "a NaN": (("y_v = -0.315", "y_v = nan"), "mmg.y_v: expected a finite number"),
    "a damping of the wrong sign": (("n_r = -0.049", "n_r = 0.049"), "mmg.n_r: must be a damping derivative < 0"),
    "a wake fraction of one": (("w_p0 = 0.40", "w_p0 = 1.0"), "mmg.w_p0: must be in 0..1 (1 excluded)"),
    "unstable at hard-over": (("n_rrr = -0.013", "n_rrr = 0.8"), "mmg: KVLCC2: the model is unstable at +35 deg"),
    "an unknown key": (("k_zz = 0.25", "k_zz = 0.25\nk_yy = 0.25"), "mmg.k_yy: unknown key"),
    "the wrong model's table": (('model = "mmg"', 'model = "clarke"'), "mmg: a [mmg] table with model = 'clarke'"),
    "a telegraph out of order": (("full_ahead_rpm = 105.02", "full_ahead_rpm = 105.02\nhalf_ahead_rpm = 120.0"),
                                 "engine.full_ahead_rpm: the telegraph's rpm must grow"),
    "an approach faster than full ahead": (("approach_speed_kn = 15.5", "approach_speed_kn = 18.0"),
                                           "KVLCC2: 18 kn is faster than her engine drives her at full ahead"),
    "an autopilot past the gear": (("rudder_limit_deg = 20.0", "rudder_limit_deg = 40.0"),
                                   "autopilot: rudder_limit_deg 40 is more than the steering gear's"),
}


@pytest.mark.parametrize("change, expected", BAD.values(), ids=BAD.keys())
def test_a_bad_manoeuvring_file_is_one_line_naming_the_key(tmp_path, capsys, change, expected):
    """Missing, NaN or non-physical coefficients and a model that runs away at hard-over: one line naming the file
    and the key, exit 2, no plot written."""
    text = KVLCC2.read_text()
    assert change[0] in text
    path = write(tmp_path, text.replace(*change), "ship.toml")
    plot = tmp_path / "trials.png"
    assert main(["trials", str(path), "--json", "--plot", str(plot)]) == 2
    captured = capsys.readouterr()
    error = captured.err.strip()
    assert expected in error and str(path) in error and "\n" not in error, error
    assert "Traceback" not in captured.err and captured.out == "" and not plot.exists()


def test_the_plot_is_never_written_over_an_input(tmp_path, capsys):
    """``--plot`` onto the manoeuvring file it reads (here through a hard link) would lose the file: refused in one
    line, the file unchanged."""
    ship = write(tmp_path, KVLCC2.read_text(), "ship.toml")
    link = tmp_path / "link.png"
    link.hardlink_to(ship)
    before = ship.read_bytes()
    assert main(["trials", str(ship), "--plot", str(link), "--quiet"]) == 2
    error = capsys.readouterr().err.strip()
    assert "is one of this command's inputs" in error and "\n" not in error
    assert ship.read_bytes() == before


def test_a_plot_into_a_missing_folder_and_a_manoeuvring_file_that_is_no_toml_are_one_line(tmp_path, capsys):
    """The plot's folder must exist (checked before the trials run); a scenario naming a manoeuvring file that is
    not TOML is refused naming that file."""
    assert main(["trials", str(KVLCC2), "--plot", str(tmp_path / "no" / "t.png"), "--quiet"]) == 2
    assert "folder" in capsys.readouterr().err
    (tmp_path / "ship.toml").write_text("model = [unclosed\n")
    scenario = write(tmp_path, (ROOT / "configs" / "training" / "heavy_weather_transit.toml").read_text()
                     .replace('manoeuvring = "s175"', f'manoeuvring = "{(tmp_path / "ship.toml").as_posix()}"')
                     .replace('"../../', f'"{ROOT.as_posix()}/'))
    assert main(["trials", str(scenario), "--quiet"]) == 2
    error = capsys.readouterr().err.strip()
    assert "ship.toml: not valid TOML" in error and "\n" not in error, error
