"""Fuzzing the readers with mutated real files: every reader returns a valid object or raises a
:class:`MarinesimError` of one line, never another exception, and ends (a read that has not ended after
:data:`~conftest.HANG_S` fails as a hang; no deadline of a few seconds, which a loaded machine misses).

Each case deletes, duplicates or replaces lines of a shipped file, or replaces one of its tokens by
a hostile one (huge, tiny, negative, non-finite, text, empty). ``MARINESIM_FUZZ_EXAMPLES`` sets the
cases per reader (default :data:`DEFAULT_EXAMPLES`, so that the file runs in under a minute here).
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
import trimesh
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import cli, hang_guard, outcome
from marinesim.hull import Hull, load_hull
from marinesim.scenario import load_scenario
from marinesim.vessel.native import write_native
from marinesim.vessel.rao import RaoTable
from marinesim.vessel.read import read_rao

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_EXAMPLES = 50
FUZZ = settings(max_examples=int(os.environ.get("MARINESIM_FUZZ_EXAMPLES", DEFAULT_EXAMPLES)),
                deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])

HOSTILE_TOKENS = st.one_of(
    st.sampled_from(["0", "-1", "1e308", "-1e308", "1e-300", "nan", "inf", "-inf", "99999999999", "1.5",
                     "x", "", "=", "[", "\"", "#", "1D400", "0.0E+00", "-0"]),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.integers(min_value=-10**12, max_value=10**12).map(str),
    st.text(alphabet="0123456789.-+eE,x ", max_size=8),
)
EDIT = st.tuples(st.sampled_from(["delete", "duplicate", "replace_line", "replace_token"]),
                 st.integers(min_value=0), HOSTILE_TOKENS, st.integers(min_value=0))


def mutate(lines: list[str], edits: list[tuple[str, int, str, int]]) -> list[str]:
    """``lines`` after each edit (what, line index, token, token index; indices wrap around)."""
    lines = list(lines)
    for what, at, token, position in edits:
        if not lines:
            break
        at %= len(lines)
        if what == "delete":
            del lines[at]
        elif what == "duplicate":
            lines.insert(at, lines[at])
        elif what == "replace_line":
            lines[at] = token
        else:
            parts = lines[at].split(" ")
            parts[position % len(parts)] = token
            lines[at] = " ".join(parts)
    return lines


def check_reader(read: Callable[[Path], object], valid: type, lines: list[str], name: str,
                 edits: list[tuple[str, int, str, int]]) -> None:
    """Write the mutated ``lines`` as ``name`` in a fresh folder and read it: a ``valid`` object or a one-line
    :class:`MarinesimError`; any other exception fails the test (hypothesis reports the edits), and so does a read
    that does not end (:class:`~conftest.Hang`, naming the edits)."""
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / name
        path.write_text("\n".join(mutate(lines, edits)) + "\n")
        with hang_guard(f"reading {name} after the edits {edits}"):
            outcome(read, valid, path)


def native_lines() -> list[str]:
    """A native table written by write_native from the S175 RAOs (first speed's rows only, to stay small)."""
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "s175.csv"
        write_native(read_rao(ROOT / "rao" / "s175" / "input.re1"), path)
        lines = path.read_text().splitlines()
    return [line for line in lines if not line[:1].isdigit()] + [
        line for line in lines if line[:1].isdigit() and line.startswith("0,")][:400]


def obj_lines() -> list[str]:
    """The box barge as an OBJ (trimesh's writer)."""
    return trimesh.load(ROOT / "hulls" / "box_barge.stl").export(file_type="obj").splitlines()


def scenario_lines() -> list[str]:
    """configs/default.toml with its files as absolute paths, without the hull and its visual mesh (the RAO reader
    is fuzzed apart)."""
    text = (ROOT / "configs" / "default.toml").read_text()
    text = text.replace('"../rao/', f'"{ROOT}/rao/').replace('hull = "../hulls/tanker.gdf"', "")
    return [line for line in text.splitlines() if not line.startswith("visual_mesh")]


SOURCES = {
    "wamit": (lambda: (ROOT / "rao" / "tanker" / "tanker.4").read_text().splitlines(), "t.4", read_rao, RaoTable),
    "veres": (lambda: (ROOT / "rao" / "s175" / "input.re1").read_text().splitlines(), "s.re1", read_rao, RaoTable),
    "native": (native_lines, "n.csv", read_rao, RaoTable),
    "gdf": (lambda: (ROOT / "hulls" / "tanker.gdf").read_text().splitlines(), "h.gdf", load_hull, Hull),
    "obj": (obj_lines, "h.obj", load_hull, Hull),
    "scenario": (scenario_lines, "s.toml", load_scenario, object),
}
"""Reader name -> (the real file's lines, the fuzzed file's name, the reader, what it returns)."""
_LINES: dict[str, list[str]] = {}


def lines_of(name: str) -> list[str]:
    if name not in _LINES:
        _LINES[name] = SOURCES[name][0]()
    return _LINES[name]


@pytest.mark.parametrize("name", sorted(SOURCES))
@FUZZ
@given(edits=st.lists(EDIT, min_size=1, max_size=4))
def test_mutated_files_give_a_result_or_one_clean_error(name, edits):
    """Another exception (IndexError, ValueError, RecursionError, ...) would reach the user as a traceback,
    and a read that never ends as a hang."""
    _, file_name, read, valid = SOURCES[name]
    check_reader(read, valid, lines_of(name), file_name, edits)


BROKEN = {
    "wamit": (0, "1.05 0.0 1 2.0 90.0 nan 1.0"),
    "veres": (9, "     5    19    36     7"),
    "native": (-1, "0,180,0.5,1,90,1"),
    "gdf": (3, "99999999999"),
    "obj": (0, "v 1 2"),
    "scenario": (0, "[ocean"),
}
"""Reader name -> (line index, its replacement) that breaks the real file."""


@pytest.mark.parametrize("name", sorted(BROKEN))
def test_a_broken_file_gives_exit_2_and_one_line(tmp_path, name):
    """The command line's side of the fuzz: a broken file of each reader is one line on stderr and exit 2 (the
    entry point, in this process; test_cli_main runs the command in a process of its own)."""
    _, file_name, _, _ = SOURCES[name]
    lines = list(lines_of(name))
    at, text = BROKEN[name]
    lines[at] = text
    path = tmp_path / file_name
    path.write_text("\n".join(lines) + "\n")
    command = {"scenario": ["export", str(path), "--out", str(tmp_path / "m.csv")],
               "gdf": ["hull", str(path)], "obj": ["hull", str(path)]}.get(name, ["rao", str(path)])
    with hang_guard(f"marinesim {command[0]} of a broken {name} file"):
        result = cli(*command, cwd=tmp_path)
    stderr = result.stderr.strip().splitlines()
    assert result.returncode == 2 and "Traceback" not in result.stderr and len(stderr) == 1, result.stderr
    assert str(path) in stderr[0]


def test_the_mutation_changes_the_file():
    """The fuzz is worthless if an edit leaves the file as it was."""
    lines = ["a b", "c d"]
    assert mutate(lines, [("replace_token", 1, "x", 0)]) == ["a b", "x d"]
    assert mutate(lines, [("delete", 2, "", 0)]) == ["c d"]
    assert np.array_equal(mutate(lines, [("duplicate", 0, "", 0)]), ["a b", "a b", "c d"])
