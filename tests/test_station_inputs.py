"""Bad station-keeping input at the command line: one line naming the file and the key or line, exit 2, no
traceback (the scenario loader's errors through ``marinesim export``)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from conftest import ROOT
from marinesim.cli import main

SUPPLY = (ROOT / "configs" / "station" / "supply.toml").read_text()
MOORED = (ROOT / "configs" / "semisub_moored.toml").read_text()
MOORINGS = (ROOT / "configs" / "moorings" / "semisub_8_chain.toml").read_text()
WIND = (ROOT / "configs" / "wind" / "semisub.csv").read_text()


def _dp_scenario(tmp_path, station: str) -> str:
    (tmp_path / "vessel.toml").write_text(station)
    text = (ROOT / "configs" / "supply_dp.toml").read_text().replace('"../', f'"{ROOT.as_posix()}/')
    path = tmp_path / "dp.toml"
    path.write_text(text.replace('vessel = "supply"', 'vessel = "vessel.toml"'))
    return str(path)


def _moored_scenario(tmp_path, moorings: str = MOORINGS, wind: str | None = None) -> str:
    (tmp_path / "lines.toml").write_text(moorings)
    text = MOORED.replace('"../', f'"{ROOT.as_posix()}/').replace('moorings = "semisub_8_chain"',
                                                                  'moorings = "lines.toml"')
    if wind is not None:
        (tmp_path / "wind.csv").write_text(wind)
        station = (ROOT / "configs" / "station" / "semisub.toml").read_text().replace(
            'file = "../wind/semisub.csv"', 'file = "wind.csv"')
        (tmp_path / "semisub.toml").write_text(station)
        text = text.replace('vessel = "semisub"', 'vessel = "semisub.toml"')
    path = tmp_path / "moored.toml"
    path.write_text(text)
    return str(path)


def _tunnels_gone(text: str) -> str:
    blocks = text.split("[[thrusters]]")
    return blocks[0] + "".join("[[thrusters]]" + b for b in blocks[1:] if 'kind = "tunnel"' not in b)


CASES = {
    "thrusters that cannot hold any heading": (
        lambda tmp: _dp_scenario(tmp, _tunnels_gone(SUPPLY)), r"vessel\.toml: thrusters: they cannot push her"),
    "an anchor above the seabed": (
        lambda tmp: _moored_scenario(tmp, MOORINGS.replace("depth_m = 150.0", "depth_m = 120.0")),
        r"lines\.toml.*line 1.*seabed"),
    "a wind coefficient file with a hole": (
        lambda tmp: _moored_scenario(tmp, wind="\n".join(
            line if not line.startswith("90,") else "90,,1.1,0.02" for line in WIND.splitlines()) + "\n"),
        r"wind\.csv, line \d+"),
    "a fault the vessel cannot have": (
        lambda tmp: _dp_scenario(tmp, SUPPLY) and _fault(tmp, 'fault = "thruster:bow 9"'),
        r"events\[0\]\.fault: .*no thruster 'bow 9'"),
    "moorings laid for another heading": (
        lambda tmp: _heading(_moored_scenario(tmp), 200.0),
        r"vessel\.heading_deg: 200 deg, but the moorings \(lines\.toml\) are laid for a vessel heading 250"),
    "a line to turn about without DP": (
        lambda tmp: _tandem(tmp, 'mode = "dp"', 'mode = "moored"'),
        r"tandem\.toml: station\.turn_about: a line to turn about needs mode = \"dp\" and her moorings"),
    "a line to turn about that she does not have": (
        lambda tmp: _tandem(tmp, 'turn_about = "hawser"', 'turn_about = "bow"'),
        r"station\.turn_about: 'bow' is not a line of tanker_hawser\.toml \(its lines: hawser\)"),
}


def _tandem(tmp_path, old: str, new: str) -> str:
    """The offshore-loading exercise (on DP, turning about her hawser's far end) with ``old`` made ``new``."""
    text = (ROOT / "configs" / "training" / "offshore_loading.toml").read_text()
    assert old in text
    path = tmp_path / "tandem.toml"
    path.write_text(text.replace('"../../', f'"{ROOT.as_posix()}/').replace(old, new))
    return str(path)


def _heading(path: str, heading: float) -> str:
    file = Path(path)
    file.write_text(file.read_text().replace("heading_deg = 250.0", f"heading_deg = {heading}"))
    return path


def _fault(tmp_path, line: str) -> str:
    path = tmp_path / "dp.toml"
    path.write_text(path.read_text().replace('fault = "thruster:bow tunnel 1"', line))
    return str(path)


@pytest.mark.parametrize("case", CASES, ids=list(CASES))
def test_bad_station_input_is_one_line_and_exit_2(tmp_path, capsys, case):
    """What would be wrong if not: a traceback, a silent default, or an error that does not say where."""
    make, pattern = CASES[case]
    scenario = make(tmp_path)
    code = main(["export", scenario, "--duration", "1", "--out", str(tmp_path / "m.csv")])
    err = capsys.readouterr().err.strip()
    assert code == 2, err
    assert len(err.splitlines()) == 1 and "Traceback" not in err, err
    assert re.search(pattern, err), err
    assert not (tmp_path / "m.csv").exists()
