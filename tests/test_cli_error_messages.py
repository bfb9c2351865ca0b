"""A mistake gives exactly one line: it names the user's file (never the temporary it was being
written as), says a folder is a folder, and no library prints around it. A TOML file saved with a
UTF-8 byte-order mark is read as TOML."""

from __future__ import annotations

import contextlib
import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import DEFAULT, HANG_S, ROOT
from staging import tmpfs
from marinesim.cli import main
from marinesim.scenario import load_scenario


@pytest.fixture(params=["full disk", "read-only file system"], scope="module")
def unwritable_folder(request):
    with tmpfs("ro" if request.param == "read-only file system" else "rw") as folder:
        if request.param == "full disk":
            with contextlib.suppress(OSError), open(folder / "filler", "wb") as filler:
                while True:
                    filler.write(b"\0" * 4096)
        yield folder


WAKE = ["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "20", "--nx", "128", "--ny", "64", "--quiet"]
COMMANDS = {
    "wake --out": ("w.npz", WAKE + ["--out"]),
    "wake --plot": ("w.png", WAKE + ["--plot"]),
    "export": ("m.csv", ["export", str(DEFAULT), "--duration", "60", "--quiet", "--out"]),
    "rao --plot": ("r.png", ["rao", str(ROOT / "rao" / "tanker" / "tanker.4"), "--plot"]),
    "render --screenshot": ("s.png", ["render", str(DEFAULT), "--size", "64x64", "--solver", "off", "--quiet",
                                      "--screenshot"]),
}
"""Each command that writes a file: the file's name and the command line it ends (the file's path added)."""


@pytest.mark.parametrize("command", COMMANDS)
def test_write_errors_name_the_users_file(unwritable_folder, command, capsys):
    """If this fails, a full or read-only output folder is reported with the temporary file's name
    (``.w.j3vo1tgz.part.png``) or with no file at all ("No space left on device: None")."""
    name, args = COMMANDS[command]
    target = unwritable_folder / name
    assert main(args + [str(target)]) == 2
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"marinesim {args[0]}: error: cannot write {target}: "), lines
    assert ".part" not in lines[0] and "None" not in lines[0]


def test_a_folder_given_as_a_file_is_called_a_folder(tmp_path, capsys):
    """If this fails, ``marinesim hull FOLDER`` (or rao, or a scenario) says "no such file" of a folder
    that exists, or prints a traceback."""
    for args in (["hull", str(tmp_path)], ["rao", str(tmp_path)], ["export", str(tmp_path), "--out",
                                                                     str(tmp_path / "m.csv")]):
        assert main(args) == 2
        lines = capsys.readouterr().err.splitlines()
        assert len(lines) == 1 and "is a folder" in lines[0] and "no such file" not in lines[0], lines


def test_a_scenario_with_a_byte_order_mark_is_read(tmp_path):
    """If this fails, a scenario saved by an editor that writes a UTF-8 byte-order mark (Notepad) is refused
    with "Invalid statement (at line 1, column 1)"."""
    text = DEFAULT.read_text(encoding="utf-8").replace('"../', f'"{ROOT}/')
    plain, marked = tmp_path / "plain.toml", tmp_path / "marked.toml"
    plain.write_text(text, encoding="utf-8")
    marked.write_bytes(b"\xef\xbb\xbf" + text.encode("utf-8"))
    a, b = load_scenario(plain), load_scenario(marked)
    assert (a.sea, a.run, a.ocean) == (b.sea, b.run, b.ocean)


def _stderr_of(args: list[str], cwd: Path) -> list[str]:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, *args], env=env, cwd=cwd, capture_output=True, text=True, timeout=HANG_S)
    return done.stderr.splitlines()


def test_a_mesh_trimesh_struggles_with_gives_one_line(tmp_path):
    """If this fails, trimesh's log records (a traceback of its binary-STL attempt and "failed to extract
    face_normals") are printed around marinesim's one-line error."""
    mesh = tmp_path / "odd.stl"
    mesh.write_text("solid x\n facet normal 0 0 1e\n  outer loop\n   vertex 0 0 -1\n   vertex 1 0 -1\n"
                    "   vertex 0 1 -1\n  endloop\n endfacet\nendsolid x\n")
    lines = _stderr_of(["-m", "marinesim", "hull", str(mesh)], tmp_path)
    assert len(lines) == 1 and lines[0].startswith("marinesim hull: error: "), lines


@pytest.mark.slow
def test_a_damaged_netcdf_gives_one_line(tmp_path):
    """If this fails, h5netcdf's half-opened file of a damaged NetCDF prints an "Exception ignored in:
    <function File.close>" traceback when it is collected, besides marinesim's error."""
    xarray = pytest.importorskip("xarray")
    pytest.importorskip("h5netcdf")
    import numpy as np

    good = tmp_path / "good.nc"
    xarray.Dataset({"a": ("x", np.arange(10.0))}).to_netcdf(good, engine="h5netcdf")
    data = good.read_bytes()
    script = ("import sys\nfrom pathlib import Path\nfrom marinesim.errors import MarinesimError\n"
              "from marinesim.vessel import read_rao\n"
              "data = Path(sys.argv[1]).read_bytes()\n"
              "for where in range(0, min(len(data), 1024), 8):\n"
              "    damaged = Path(sys.argv[2])\n"
              "    damaged.write_bytes(data[:where] + bytes([data[where] ^ 0xFF]) + data[where + 1:])\n"
              "    try:\n"
              "        read_rao(damaged)\n"
              "    except MarinesimError:\n"
              "        pass\n")
    assert _stderr_of(["-c", script, str(good), str(tmp_path / "damaged.nc")], tmp_path) == []
    (tmp_path / "one.nc").write_bytes(data[:64] + bytes([data[64] ^ 0xFF]) + data[65:])
    lines = _stderr_of(["-m", "marinesim", "rao", str(tmp_path / "one.nc")], tmp_path)
    assert len(lines) == 1 and lines[0].startswith("marinesim rao: error: "), lines
