"""Absurd values, unbounded work and odd paths, staged for real through the command line: each must end as one
line on stderr naming the file, key or option and what was expected, exit status 2, no traceback, and quickly."""

from __future__ import annotations

import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

from conftest import HANG_S, ROOT, cli, cli_process
from marinesim.errors import FileFormatError, ParameterError
from marinesim.vessel.native import write_native
from marinesim.vessel.read import read_rao

TANKER_RAO = ROOT / "rao" / "tanker" / "tanker.4"
TANKER_HULL = ROOT / "hulls" / "tanker.gdf"
S175 = ROOT / "rao" / "s175" / "input.re1"


def marinesim(*args: str, process: bool = False) -> subprocess.CompletedProcess:
    """``marinesim ARGS`` through the command line's own entry in this process (conftest's ``cli``); with
    ``process``, in a process of its own (for what could block: a hang then fails the test after
    :data:`~conftest.HANG_S`). The subprocess path itself (imports, signals) is tested by test_cli_main.py and the
    input campaign."""
    return cli_process(*args, timeout=HANG_S) if process else cli(*args)


def refused(result: subprocess.CompletedProcess, *words: str) -> str:
    """The one stderr line of a clean refusal (exit 2, no traceback), checked to hold ``words``."""
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 2 and "Traceback" not in result.stderr and len(lines) == 1, result.stderr
    assert all(word in lines[0] for word in words), lines[0]
    return lines[0]


def scenario(folder: Path, *, sea: str = 'type = "jonswap"\nhs_m = 3.0\ntp_s = 9.0\nfrom_deg = 0.0',
             ocean: str = "resolution = 64", vessel: str = "", run: str = "duration_s = 10.0\ndt_s = 0.5",
             rao: str | Path = TANKER_RAO, hull: str | Path | None = None) -> Path:
    """A small scenario file with the given sections' bodies; the tanker's RAOs (and hull, if given)."""
    hull_line = f'hull = "{hull}"\n' if hull is not None else ""
    text = (f"[ocean]\n{ocean}\n[[sea]]\n{sea}\n[vessel]\nrao = \"{rao}\"\n{hull_line}{vessel}\n[run]\n{run}\n")
    path = folder / "scenario.toml"
    path.write_text(text)
    return path


def one_frequency_native(folder: Path) -> Path:
    """The tanker's table written by write_native, keeping the rows of one frequency only."""
    full = folder / "full.csv"
    write_native(read_rao(TANKER_RAO), full)
    lines = full.read_text().splitlines()
    head = [line for line in lines if not line[:1].isdigit()]
    rows = [line for line in lines if line[:1].isdigit()]
    omega = rows[0].split(",")[2]
    path = folder / "one.csv"
    path.write_text("\n".join(head + [row for row in rows if row.split(",")[2] == omega]) + "\n")
    return path


def one_period_wamit(folder: Path) -> Path:
    """The tanker's .4 with only the lines of its first period."""
    lines = TANKER_RAO.read_text().splitlines()
    period = lines[0].split()[0]
    path = folder / "one.4"
    path.write_text("\n".join(line for line in lines if line.split()[0] == period) + "\n")
    return path


# A: absurd values -----------------------------------------------------------------------------


@pytest.mark.parametrize("args, words", [
    (["--hs", "1e6"], ["hs", "0..30 m"]),
    (["--tp", "0.01"], ["tp", "1..40 s"]),
    (["--tp", "1e5"], ["tp", "1..40 s"]),
    (["--u10", "1e6"], ["u10", "0..60 m/s"]),
    (["--choppiness", "-5"], ["choppiness", "0..2"]),
    (["--spectrum", "pm", "--gamma", "5"], ["gamma", "pm"]),
    (["--spectrum", "regular", "--hs", "3"], ["hs", "regular"]),
    (["--u10", "20", "--hs", "3"], ["hs", "u10"]),
    (["--fetch-km", "50"], ["fetch_km", "u10"]),
    (["--depth", "1e9"], ["depth", "11000"]),
])
def test_sea_options_out_of_a_real_sea_are_refused(args, words):
    """Without this, ``marinesim sea`` builds seas no ocean has (or silently ignores an option) and exits 0."""
    refused(marinesim("sea", "--resolution", "16", "--tiles", "1", *args), *words)


@pytest.mark.parametrize("section, change, words", [
    ("sea", 'type = "jonswap"\nhs_m = 1e6\ntp_s = 9.0\nfrom_deg = 0.0', ["sea[0].hs_m", "0..30 m"]),
    ("sea", 'type = "jonswap"\nhs_m = 3.0\ntp_s = 0.01\nfrom_deg = 0.0', ["sea[0].tp_s", "1..40 s"]),
    ("sea", 'type = "jonswap"\nu10_m_s = 1e6\nfetch_km = 100.0\nfrom_deg = 0.0', ["sea[0].u10_m_s", "0..60"]),
    ("sea", 'type = "pm"\nhs_m = 3.0\ntp_s = 9.0\ngamma = 3.3\nfrom_deg = 0.0', ["sea[0].gamma", "pm"]),
    ("sea", 'type = "regular"\nheight_m = 2.0\nperiod_s = 9.0\nhs_m = 3.0\nfrom_deg = 0.0', ["sea[0].hs_m", "regular"]),
    ("sea", 'type = "jonswap"\nu10_m_s = 20.0\nfetch_km = 100.0\ngamma = 2.0\nfrom_deg = 0.0', ["sea[0].gamma", "u10_m_s"]),
    ("ocean", "choppiness = -5.0", ["ocean.choppiness", "0..2"]),
    ("ocean", "resolution = 65536", ["ocean.resolution", "16..4096"]),
    ("vessel", "ulen_m = 1e-300", ["vessel.ulen_m", "0.01..1000 m"]),
    ("run", "duration_s = 10.0\ndt_s = 1e-300", ["run.dt_s", "in 0.001..duration_s"]),
    ("run", "duration_s = 604800.0\ndt_s = 0.001", ["run.dt_s", "1e+08"]),
])
def test_scenario_values_out_of_range_are_refused_naming_the_key(tmp_path, section, change, words):
    """Without this, a scenario with an absurd value runs (NaN rows, a disk filled, a sea with no meaning)."""
    path = scenario(tmp_path, **{section: change})
    refused(marinesim("export", str(path), "--out", str(tmp_path / "m.csv"), "--quiet"), str(path), *words)
    assert not (tmp_path / "m.csv").exists()


def test_water_shallower_than_the_draft_is_refused(tmp_path):
    """Without this, a 10 m draft tanker floats in 0.5 m of water and the export exits 0."""
    path = scenario(tmp_path, ocean="resolution = 64\ndepth_m = 0.5", hull=TANKER_HULL)
    refused(marinesim("export", str(path), "--out", str(tmp_path / "m.csv")), "ocean.depth_m", "draft")


def test_export_dt_too_small_is_refused_before_anything_is_written(tmp_path):
    """Without this, ``export --dt 1e-9`` writes rows until the disk is full."""
    path = scenario(tmp_path)
    refused(marinesim("export", str(path), "--out", str(tmp_path / "m.csv"), "--dt", "1e-9"), "run.dt_s", "0.001")
    assert list(tmp_path.iterdir()) == [path]


def test_a_huge_veres_heave_is_refused_and_json_stays_json(tmp_path):
    """Without the bound, one heave value of 1e307 gives 1e307 m of heave and ``rao --json`` prints NaN."""
    lines = S175.read_text().splitlines()
    assert lines[15].split()[0] == "3"
    lines[15] = lines[15].replace("0.99920726E+00", "0.10000000E+308")
    path = tmp_path / "big.re1"
    path.write_text("\n".join(lines) + "\n")
    refused(marinesim("rao", str(path), "--json"), str(path), "heave", "50 m/m")
    report = marinesim("rao", str(S175), "--json")
    assert report.returncode == 0
    json.loads(report.stdout, parse_constant=lambda name: pytest.fail(f"{name} in the JSON"))


def test_rotation_bound_allows_every_shipped_table():
    """The |RAO| bounds must not refuse a real vessel: every shipped table reads."""
    for path in sorted((ROOT / "rao").glob("*/*.[4r]*")):
        if path.suffix in (".4", ".re1"):
            assert read_rao(path).values.size


@pytest.mark.parametrize("ulen", ["1e-300", "1e9"])
def test_rao_ulen_out_of_range_is_refused(ulen):
    """Without this, ``rao --ulen 1e-300`` divides rotations into infinities."""
    refused(marinesim("rao", str(TANKER_RAO), "--ulen", ulen), "ULEN", "0.01..1000 m")


def test_every_json_output_is_strict_json():
    """``strict_json`` turns NaN and infinities into null: a NaN in a report (or in the served exercise's state) would
    make it unreadable as JSON."""
    from marinesim.atomic import strict_json

    text = strict_json({"a": math.nan, "b": [math.inf, 1.5], "c": np.float64(-math.inf)})
    assert json.loads(text) == {"a": None, "b": [None, 1.5], "c": None}


@pytest.mark.parametrize("command", [["sea", "--resolution", "16", "--tiles", "1"], ["hull", str(TANKER_HULL)]])
def test_sea_and_hull_json_parse_strictly(command):
    """``sea --json`` and ``hull --json`` print JSON that a strict parser reads (no NaN, no Infinity)."""
    result = marinesim(*command, "--json")
    assert result.returncode == 0, result.stderr
    json.loads(result.stdout, parse_constant=lambda name: pytest.fail(f"{name} in the JSON"))


# B: unbounded work ----------------------------------------------------------------------------


def test_a_gdf_claiming_a_huge_panel_count_is_refused_before_allocating(tmp_path):
    """Without this, NPAN = 99999999999 asks numpy for 8.7 TiB (MemoryError or the OOM killer)."""
    lines = TANKER_HULL.read_text().splitlines()
    lines[3] = "99999999999"
    path = tmp_path / "huge.gdf"
    path.write_text("\n".join(lines) + "\n")
    refused(marinesim("hull", str(path)), str(path), "line 4", "NPAN 99999999999")


@pytest.mark.parametrize("args, words", [
    (["--spacing", "1e-9"], ["quadrature", "GiB"]),
    (["--nx", "100000", "--ny", "100000"], ["100000 x 100000", "GiB"]),
])
def test_a_wake_that_does_not_fit_in_memory_is_refused_with_the_number(args, words):
    """Without the estimate, these grids ask for hundreds of GiB and the machine swaps or kills the run."""
    refused(marinesim("wake", str(TANKER_HULL), "--speed-kn", "10", "--no-cache", "--quiet", *args), *words)


def test_an_ocean_that_does_not_fit_in_memory_is_refused_before_allocating(monkeypatch):
    """Without the estimate, 8 tiles of 4096^2 take some 20 GiB before a single frame."""
    from marinesim import errors
    from marinesim.sea import Ocean, SeaState, WaveSystem
    from marinesim.sea.spectra import Jonswap

    monkeypatch.setattr(errors, "physical_memory", lambda: 2**30)
    sea = SeaState((WaveSystem(Jonswap(3.0, 9.0), 0.0),))
    with pytest.raises(ParameterError, match=r"8 tiles of 4096\^2 would need .* GiB"):
        Ocean(sea, tile_count=8, resolution=4096)


# C: paths that are not regular files ------------------------------------------------------------


@pytest.mark.parametrize("kind", ["fifo", "loop", "folder"])
def test_an_rao_or_hull_path_that_is_not_a_regular_file_is_refused(tmp_path, kind):
    """Without this, a FIFO blocks the reader for ever, a symbolic-link loop raises RuntimeError."""
    odd = tmp_path / "odd.4"
    if kind == "fifo":
        os.mkfifo(odd)
    elif kind == "loop":
        os.symlink(tmp_path / "other.4", odd)
        os.symlink(odd, tmp_path / "other.4")
    else:
        odd.mkdir()
    apart = kind == "fifo"  # a FIFO would block a reader that missed it: in a process of its own
    refused(marinesim("rao", str(odd), process=apart), str(odd))
    odd_hull = tmp_path / "odd.gdf"
    odd_hull.symlink_to(odd)
    refused(marinesim("hull", str(odd_hull), process=apart), str(odd_hull))
    for key, files in (("vessel.rao", {"rao": odd}), ("vessel.hull", {"hull": odd_hull})):
        path = scenario(tmp_path, **files)
        refused(marinesim("export", str(path), "--out", str(tmp_path / "m.csv"), process=apart), key)


def test_a_nul_byte_in_a_scenario_path_is_refused(tmp_path):
    """Without this, ``resolve()`` raises ValueError (embedded null byte) and the user gets a traceback."""
    refused(marinesim("export", str(scenario(tmp_path, rao="a\\u0000b.4")), "--out", str(tmp_path / "m.csv")),
            "vessel.rao", "NUL")


def test_a_fifo_as_scenario_is_refused(tmp_path):
    """Without this, ``marinesim export FIFO`` waits for ever for a writer."""
    fifo = tmp_path / "s.toml"
    os.mkfifo(fifo)
    refused(marinesim("export", str(fifo), "--out", str(tmp_path / "m.csv"), process=True), str(fifo),
            "not a regular file")


# D: tracebacks --------------------------------------------------------------------------------


@pytest.mark.parametrize("make", [one_frequency_native, one_period_wamit])
def test_a_one_frequency_table_is_a_valid_regular_wave_table(tmp_path, make):
    """Without this, ``rao`` on a one-frequency table raises IndexError in the interpolation."""
    path = make(tmp_path)
    result = marinesim("rao", str(path), "--json")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["frequencies"] == 1
    table = read_rao(path)
    w0 = float(table.omega[0])
    held = table(np.array([w0, 1.2 * w0]), np.array([math.pi, math.pi]))
    assert np.allclose(held[0], table.values[0, np.argmin(abs(table.beta - math.pi)), 0])
    assert np.all(np.abs(held[1]) <= np.abs(held[0]) + 1e-12)  # tapering above, never growing


def test_a_one_frequency_capytaine_dataset_reads(tmp_path):
    """Without this, a Capytaine dataset solved at one frequency fails to give RAOs."""
    capytaine = pytest.importorskip("capytaine")
    xarray = pytest.importorskip("xarray")
    mesh = capytaine.mesh_parallelepiped(size=(40.0, 10.0, 4.0), resolution=(6, 2, 2), center=(0.0, 0.0, -1.0))
    body = capytaine.FloatingBody(mesh=mesh, dofs=capytaine.rigid_body_dofs(rotation_center=(0, 0, 0)),
                                  center_of_mass=(0.0, 0.0, -0.5)).immersed_part()
    body.inertia_matrix = body.compute_rigid_body_inertia(rho=1025.0)
    body.hydrostatic_stiffness = body.compute_hydrostatic_stiffness(rho=1025.0)
    problems = xarray.Dataset(coords={"omega": [0.5], "wave_direction": [0.0, math.pi / 2, math.pi],
                                      "radiating_dof": list(body.dofs), "water_depth": [np.inf], "rho": [1025.0]})
    path = tmp_path / "one.nc"
    capytaine.export_dataset(path, capytaine.BEMSolver().fill_dataset(problems, body))
    result = marinesim("rao", str(path), "--json")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["frequencies"] == 1


def test_an_obj_vertex_of_two_coordinates_is_refused(tmp_path):
    """Without this, ``hull`` dies in a matmul with a ValueError traceback."""
    path = tmp_path / "flat.obj"
    path.write_text("v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    refused(marinesim("hull", str(path)), str(path), "3 coordinates")


def test_toml_nested_too_deeply_is_refused(tmp_path):
    """Without this, tomllib's recursion gives a RecursionError traceback."""
    path = tmp_path / "deep.toml"
    path.write_text("a = " + "[" * 1200 + "]" * 1200 + "\n")
    refused(marinesim("export", str(path), "--out", str(tmp_path / "m.csv")), str(path), "nested too deeply")


@pytest.mark.parametrize("time", ["1e15", "1e300"])
def test_sea_time_far_away_is_refused(time):
    """Without this, ``sea --time 1e15`` divides by zero and ``1e300`` reduces an empty array."""
    refused(marinesim("sea", "--resolution", "16", "--tiles", "1", "--time", time), "time", "1e+06 s")


def test_an_empty_out_is_refused(tmp_path):
    """Without this, ``export --out ''`` raises ValueError (empty name) from the sidecar's path."""
    refused(marinesim("export", str(scenario(tmp_path)), "--out", ""), "file name")


def test_format_check_refuses_what_is_not_a_regular_file(tmp_path):
    """The one check every reader's path goes through: a folder and a FIFO are no RAO table."""
    from marinesim.formats import check_file

    with pytest.raises(FileFormatError, match="is a folder, not a file"):
        check_file(tmp_path)
    os.mkfifo(tmp_path / "pipe.4")
    with pytest.raises(FileFormatError, match="not a regular file"):
        check_file(tmp_path / "pipe.4")
    with pytest.raises(FileFormatError, match="NUL"):
        check_file(Path("a\x00b"))
