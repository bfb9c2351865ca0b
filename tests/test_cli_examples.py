"""``marinesim examples`` and the shipped scenarios by name: the listing names every shipped scenario, a copy is
self-contained (its scenarios read the copied RAO and hull files) and never overwrites a user's file, and every
command that takes a scenario takes a shipped one by name while a missing path is still one line naming it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from conftest import SEA_SCENARIO, write
from marinesim.cli import main
from marinesim.errors import ScenarioError
from marinesim.resources import resource_dir
from marinesim.scenario import load_scenario

CONFIGS = resource_dir("configs")
SHIPPED = sorted(CONFIGS.glob("*.toml")) + sorted(CONFIGS.glob("training/*.toml"))
"""The shipped scenario files, read from the folder (not a list kept by hand)."""


def command(capsys, *args: str) -> tuple[int, list[str], list[str]]:
    """``marinesim *args`` in this process: (exit status, stdout lines, stderr lines)."""
    status = main(list(args))
    out = capsys.readouterr()
    return status, out.out.splitlines(), out.err.splitlines()


@pytest.fixture(scope="module")
def copied(tmp_path_factory) -> Path:
    """A folder with every shipped scenario copied into it (``marinesim examples copy all``)."""
    dest = tmp_path_factory.mktemp("examples")
    assert main(["examples", "copy", "all", str(dest)]) == 0
    return dest


def test_the_list_names_every_shipped_scenario_once(capsys):
    """If this fails, a scenario added to configs/ or configs/training/ is missing from ``marinesim examples`` (or
    listed twice), or a training exercise is listed as a plain scenario."""
    status, out, err = command(capsys, "examples")
    assert status == 0 and not err
    rows = [line.split(maxsplit=2) for line in out if line.startswith("  ")]
    assert sorted(name for name, _, _ in rows) == sorted(path.stem for path in SHIPPED)
    kinds = {name: kind for name, kind, _ in rows}
    assert all(kinds[path.stem] == "exercise" for path in SHIPPED if path.parent.name == "training")
    assert set(kinds.values()) == {"scenario", "exercise"}
    assert all(0 < len(description) <= 90 for _, _, description in rows)
    assert "marinesim examples copy" in out[-1]


@pytest.mark.parametrize("name", ["crane_lift", "crane_lift.toml", "training/crane_lift", "training/crane_lift.toml",
                                  "configs/training/crane_lift.toml"])
def test_a_shipped_scenario_is_found_by_name(name, tmp_path, monkeypatch):
    """If this fails, a user of the wheel cannot name a shipped scenario (``marinesim assess crane_lift``): every
    command loads its scenario through ``load_scenario``."""
    monkeypatch.chdir(tmp_path)
    assert load_scenario(name).path == (CONFIGS / "training" / "crane_lift.toml").resolve()


def test_an_existing_file_is_used_before_a_shipped_name(tmp_path, monkeypatch):
    """A file of the user's called like a shipped scenario is the one read."""
    monkeypatch.chdir(tmp_path)
    write(tmp_path, SEA_SCENARIO, "default.toml")
    assert load_scenario("default.toml").path == (tmp_path / "default.toml").resolve()


def test_a_missing_path_is_one_line_naming_it_and_the_shipped_scenarios(capsys):
    with pytest.raises(ScenarioError) as error:
        load_scenario("nosuch/dir/x.toml")
    message = str(error.value)
    assert message.startswith("nosuch/dir/x.toml: no such scenario file") and "\n" not in message
    assert all(path.stem in message for path in SHIPPED) and "marinesim examples" in message
    status, out, err = command(capsys, "assess", "nosuch/dir/x.toml")
    assert status == 2 and len(err) == 1 and "nosuch/dir/x.toml: no such scenario file" in err[0]


def test_copy_all_is_self_contained(copied):
    """If this fails, a copied scenario reads the shipped RAO or hull (an edit of the copy would not count) or
    misses a file beside its RAO table (its table would differ from the shipped one's), or the data's licence
    notice is left behind."""
    copies = sorted((copied / "configs").glob("*.toml")) + sorted((copied / "configs").glob("training/*.toml"))
    assert [path.relative_to(copied / "configs") for path in copies] == [path.relative_to(CONFIGS) for path in SHIPPED]
    for path in copies:
        scenario, shipped = load_scenario(path), load_scenario(path.stem)
        assert copied in scenario.path.parents
        vessel = scenario.vessel
        assert copied in vessel.rao_path.parents, f"{path.name} reads {vessel.rao_path}"
        assert vessel.hull_path is None or copied in vessel.hull_path.parents, f"{path.name} reads {vessel.hull_path}"
        assert np.array_equal(vessel.rao.values, shipped.vessel.rao.values)
        assert vessel.rao.notes == shipped.vessel.rao.notes
        for role, file in (scenario.station.files if scenario.station is not None else {}).items():
            assert copied in file.parents, f"{path.name} reads the shipped {role} file {file}"
    for kind, notice in (("rao", "LICENSE-MSS"), ("rao", "README.md"), ("hulls", "LICENSE-MSS")):
        assert (copied / kind / notice).read_bytes() == (resource_dir(kind) / notice).read_bytes()


def files(folder: Path) -> dict[Path, tuple[bytes, int]]:
    """Every file below ``folder``: its bytes and modification time (ns)."""
    return {path: (path.read_bytes(), path.stat().st_mtime_ns) for path in folder.rglob("*") if path.is_file()}


def test_copying_again_changes_nothing(copied, capsys):
    before = files(copied)
    status, out, err = command(capsys, "examples", "copy", "all", str(copied))
    assert status == 0 and not err
    assert not any(line.startswith("wrote") for line in out) and f"{len(before)} file(s) already" in out[0]
    assert files(copied) == before


def test_a_different_file_in_the_way_is_refused_and_kept(tmp_path, capsys):
    """If this fails, ``examples copy`` overwrites a user's edited RAO table (or writes half the copy before it
    refuses)."""
    assert command(capsys, "examples", "copy", "crane_lift", str(tmp_path))[0] == 0
    edited, scenario = tmp_path / "rao" / "supply" / "input.re1", tmp_path / "configs" / "training" / "crane_lift.toml"
    edited.write_text("my own table\n")
    scenario.unlink()
    status, out, err = command(capsys, "examples", "copy", "crane_lift", str(tmp_path))
    assert status == 2 and len(err) == 1 and str(edited) in err[0]
    assert edited.read_text() == "my own table\n" and not scenario.exists()


def test_an_unknown_name_is_one_line_with_the_shipped_names(tmp_path, capsys):
    status, out, err = command(capsys, "examples", "copy", "nosuch", str(tmp_path))
    assert status == 2 and len(err) == 1 and "'nosuch'" in err[0]
    assert all(path.stem in err[0] for path in SHIPPED)
    assert not any(tmp_path.iterdir())


def test_copy_says_what_it_wrote_and_how_to_run_it(tmp_path, capsys):
    status, out, err = command(capsys, "examples", "copy", "crane_lift", str(tmp_path))
    written = [Path(line.removeprefix("wrote ")) for line in out if line.startswith("wrote ")]
    assert status == 0 and sorted(written) == sorted(path for path in tmp_path.rglob("*") if path.is_file())
    assert out[-1] == f"to run crane_lift: marinesim assess {tmp_path / 'configs' / 'training' / 'crane_lift.toml'}"


def test_render_without_a_scenario_draws_the_shipped_default(tmp_path, capsys):
    """``marinesim render`` takes the same default as ``marinesim run``."""
    shot = tmp_path / "shot.png"
    status, out, err = command(capsys, "render", "--screenshot", str(shot), "--size", "64x64", "--solver", "off",
                               "--quiet")
    assert status == 0 and shot.stat().st_size > 0, err
