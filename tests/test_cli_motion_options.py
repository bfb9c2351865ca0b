"""Motions from the command line without a scenario file: `export` and `run` with --rao and the sea options of
`marinesim sea`. The scenario the options make is the one saved (--save-scenario) and the one run; conflicting or
ignored options, and a scenario saved over an input, are refused in one line before anything is written."""

import json
import math
import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from conftest import ROOT, VESSEL_SCENARIO, write
from marinesim.cli import build_parser, main
from marinesim.sea import Jonswap
from marinesim.vessel import read_rao

TANKER = ROOT / "rao" / "tanker" / "tanker.4"
SMALL = ["--resolution", "64", "--tiles", "3", "--quiet"]
"""A small ocean: the motions' components come from its tiles."""


def heave(path) -> pd.Series:
    return pd.read_csv(path)["heave_m"]


def named(sidecar: Path) -> Path:
    """The scenario file a sidecar names (relative to its folder, or absolute)."""
    return (sidecar.parent / json.loads(sidecar.read_text())["scenario"]).resolve()


def refused(capsys, argv: list[str], *words: str) -> str:
    """Run ``argv``: exit status 2 and one line on stderr holding ``words``; that line."""
    assert main(argv) == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1 and all(word in lines[0] for word in words), lines
    return lines[0]


def test_export_from_an_rao_file_and_sea_options(tmp_path, monkeypatch, capsys):
    """Head seas (waves from north, bow north) Hs 3 m, Tp 9 s: 601 rows at dt 0.1 s over 60 s, the heave's standard
    deviation of the order of the spectral one, sqrt(int |H|^2 S dw), and twice that for Hs 6 m (linear response,
    the same seed: the same phases); over 30 min it comes within 10 % of the spectral one. The scenario the options
    make is kept beside the table, and the sidecar names it and its hash."""
    monkeypatch.chdir(tmp_path)
    sea = ["--tp", "9", "--gamma", "3.3", "--from-deg", "0", "--heading-deg", "0"]
    assert main(["export", "--rao", str(TANKER), "--hs", "3", *sea, "--duration", "60", "--out", "m.csv",
                 "--quiet"]) == 0
    out = capsys.readouterr().out
    assert "wrote 601 rows" in out and f"scenario: {tmp_path / 'm.csv.toml'}" in out
    frame = pd.read_csv("m.csv")
    assert len(frame) == 601 and frame["time_s"].iloc[-1] == pytest.approx(60.0)
    assert np.isfinite(frame["heave_m"]).all()
    omega = np.linspace(0.05, 4.0, 4000)
    response = read_rao(TANKER)(omega, np.full(omega.size, math.pi))[:, 2]
    spectral = math.sqrt(np.trapezoid(np.abs(response) ** 2 * Jonswap(3.0, 9.0, 3.3).density(omega), omega))
    assert 0.3 * spectral < frame["heave_m"].std() < 1.5 * spectral  # one minute: some seven waves
    assert named(tmp_path / "m.csv.json") == (tmp_path / "m.csv.toml").resolve()
    assert json.loads((tmp_path / "m.csv.json").read_text())["seed"] == 0
    assert main(["export", "--rao", str(TANKER), "--hs", "6", *sea, "--duration", "60", "--out", "m6.csv",
                 "--quiet"]) == 0
    assert heave("m6.csv").std() / frame["heave_m"].std() == pytest.approx(2.0, rel=0.01)
    assert main(["export", "--rao", str(TANKER), "--hs", "3", *sea, "--duration", "1800", "--dt", "0.5",
                 "--out", "long.csv", "--quiet"]) == 0
    assert heave("long.csv").std() == pytest.approx(spectral, rel=0.1)


def test_the_saved_scenario_is_the_one_run_and_moves_with_its_files(tmp_path, monkeypatch, capsys):
    """Exporting with options and --save-scenario, then exporting the saved file, gives the same CSV bytes and the
    same sidecar but for the table's name: both name the saved file and its hash. Its paths are relative to its
    folder: moved with the vessel's files, it gives the same motions again."""
    vessel = tmp_path / "project" / "vessel"
    vessel.mkdir(parents=True)
    for name in ("tanker.4", "tanker.gdf"):
        shutil.copy(TANKER.with_name(name), vessel / name)
    (tmp_path / "project" / "scenarios").mkdir()
    monkeypatch.chdir(tmp_path / "project")
    options = ["--rao", "vessel/tanker.4", "--hull", "vessel/tanker.gdf", "--speed-kn", "6", "--heading-deg", "30",
               "--hs", "4", "--tp", "10", "--from-deg", "200", "--spreading-s", "10", "--swell-hs", "1.5",
               "--swell-from-deg", "250", "--depth", "200", "--duration", "30", "--dt", "0.5", "--seed", "5", *SMALL]
    assert main(["export", *options, "--save-scenario", "scenarios/s.toml", "--out", "a.csv"]) == 0
    saved = tmp_path / "project" / "scenarios" / "s.toml"
    text = saved.read_text()
    assert 'rao = "../vessel/tanker.4"' in text and 'hull = "../vessel/tanker.gdf"' in text
    assert "speed_kn = 6.0" in text and "heading_deg = 30.0" in text and "depth_m = 200.0" in text
    assert not (tmp_path / "project" / "a.csv.toml").exists()  # saved where asked, nowhere else
    assert main(["export", "scenarios/s.toml", "--out", "b.csv", "--quiet"]) == 0
    assert (tmp_path / "project" / "a.csv").read_bytes() == (tmp_path / "project" / "b.csv").read_bytes()
    a, b = (json.loads((tmp_path / "project" / f"{name}.csv.json").read_text()) for name in "ab")
    assert a.pop("file") == "a.csv" and b.pop("file") == "b.csv" and a == b
    assert named(tmp_path / "project" / "a.csv.json") == saved.resolve() and a["seed"] == 5 and a["dt_s"] == 0.5
    shutil.move(tmp_path / "project", tmp_path / "moved")
    monkeypatch.chdir(tmp_path / "moved")
    assert main(["export", "scenarios/s.toml", "--out", "c.csv", "--quiet"]) == 0
    assert (tmp_path / "moved" / "c.csv").read_bytes() == (tmp_path / "moved" / "a.csv").read_bytes()
    capsys.readouterr()


@pytest.mark.parametrize("argv, words", [
    (["export", "SCENARIO", "--rao", str(TANKER), "--out", "m.csv"], ["scenario file", "--rao", "not both"]),
    (["export", "--out", "m.csv"], ["scenario file (SCENARIO)", "--rao FILE"]),
    (["export", "SCENARIO", "--hs", "5", "--out", "m.csv"], ["--hs applies only with --rao", "scenario file"]),
    (["export", "SCENARIO", "--save-scenario", "s.toml", "--speed-kn", "3", "--out", "m.csv"],
     ["--speed-kn, --save-scenario apply only with --rao"]),
    (["run", "SCENARIO", "--rao", str(TANKER), "--headless"], ["not both"]),
    (["run", "--tp", "12", "--depth", "50", "--headless"], ["--tp, --depth apply only with --rao"]),
    (["export", "--rao", str(TANKER), "--hs", "-1", "--out", "m.csv"], ["sea[0].hs_m", "-1"]),
    (["export", "--rao", str(TANKER), "--height", "2", "--out", "m.csv"], ["sea[0].height_m", "jonswap"]),
    (["export", "--rao", str(TANKER), "--heading-deg", "400", "--out", "m.csv"], ["vessel.heading_deg", "400"]),
    (["export", "--rao", str(TANKER), "--swell-hs", "2", "--swell-tp", "60", "--out", "m.csv"], ["sea[1].tp_s"]),
    (["export", "--rao", "nope.4", "--out", "m.csv"], ["nope.4: no such RAO file"]),
    (["export", "--rao", str(TANKER), "--out", "m.csv", "--save-scenario", "m.csv.json"], ["output", "too"]),
    (["run", "--rao", str(TANKER), "--hs", "-1", "--headless"], ["sea[0].hs_m"]),
])
def test_conflicting_ignored_and_bad_options_are_refused_before_anything_is_written(tmp_path, monkeypatch, capsys,
                                                                                    argv, words):
    """--rao with a scenario file, neither, motion options a scenario file would silently ignore, and option values
    the scenario model refuses (named by the key, as in a file): one line, exit 2, no file and no folder made."""
    monkeypatch.chdir(tmp_path)
    scenario = write(tmp_path, VESSEL_SCENARIO)
    refused(capsys, [str(scenario) if arg == "SCENARIO" else arg for arg in argv], *words)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scenario.toml"]


def test_a_scenario_is_not_saved_over_an_input(tmp_path, monkeypatch, capsys):
    """--save-scenario onto the RAO file itself, by its name or through a link, is refused and the RAO is intact."""
    for name in ("tanker.4", "tanker.gdf"):
        shutil.copy(TANKER.with_name(name), tmp_path / name)
    (tmp_path / "link.4").symlink_to(tmp_path / "tanker.4")
    monkeypatch.chdir(tmp_path)
    before = (tmp_path / "tanker.4").read_bytes()
    for target in ("tanker.4", "link.4", "tanker.gdf"):
        refused(capsys, ["export", "--rao", "tanker.4", "--out", "m.csv", "--save-scenario", target],
                f"--save-scenario {target}", "one of this command's inputs")
    assert (tmp_path / "tanker.4").read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.4", "tanker.4", "tanker.gdf"]


def test_run_keeps_the_scenario_of_its_options_in_its_output_folder(tmp_path, monkeypatch, capsys):
    """A headless run from options writes the scenario to out/<RAO name>/<RAO name>.toml, where its files go."""
    monkeypatch.chdir(tmp_path)
    assert main(["run", "--rao", str(TANKER), "--hs", "2", "--duration", "2", "--headless", *SMALL]) == 0
    out = capsys.readouterr().out
    kept = tmp_path / "out" / "tanker" / "tanker.toml"
    assert f"scenario {kept}:" in out and "heading 0 deg" in out
    assert named(kept.parent / "motions.csv.json") == kept.resolve()


def test_sea_export_and_run_share_one_definition_of_the_sea_options():
    """The same options, choices and help in all three commands (defaults: `sea` fills them in; `export` and `run`
    leave an option not given out, to tell it from one given, and fill in the same defaults)."""
    commands = build_parser()._subparsers._group_actions[0].choices

    def sea_options(command: str) -> dict:
        return {a.option_strings[0]: (a.help, a.choices, a.type) for a in commands[command]._actions
                if a.option_strings and a.dest in commands["sea"].parse_args([]).__dict__
                and a.dest not in ("seed", "time", "deterministic_amplitudes", "json", "plot", "spectrum_csv")}

    assert sea_options("sea") == sea_options("export") == sea_options("run")
    assert len(sea_options("sea")) == 20


def test_the_scenario_text_holds_any_file_name_and_number(tmp_path):
    """A file name with quotes, backslashes, control characters or letters beyond ASCII reads back as itself, relative
    to the file's folder; numbers read back as given (inf and nan too, for the model to refuse as a file's)."""
    import tomllib

    from marinesim.scenario.from_options import scenario_text

    name = 'a "b" \\c\td\x01\x7fé €.4'
    text = scenario_text({"vessel": {"rao": tmp_path / "x" / name, "hull": None, "speed_kn": 1e-300},
                          "run": {"seed": 7, "duration_s": math.inf, "dt_s": None}}, tmp_path / "y")
    data = tomllib.loads(text)
    assert data["vessel"] == {"rao": f"../x/{name}", "speed_kn": 1e-300}
    assert data["run"] == {"seed": 7, "duration_s": math.inf}
