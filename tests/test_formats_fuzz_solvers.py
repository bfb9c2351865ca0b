"""The readers of AQWA, NEMOH, HAMS/HydroStar, OrcaFlex, WAMIT report files and HAMS and gmsh meshes fuzzed from their real files (the
hardening rule: whatever the bytes, a table or the project's one error, never another exception), and one damaged
file of each through the command line: exit 2, one line naming the file, no traceback."""

from __future__ import annotations

import lzma
import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import cli
from marinesim.errors import MarinesimError
from marinesim.hull import load_hull
from marinesim.vessel import read_rao

DATA = Path(__file__).parent / "data"
SOURCES = {
    "aqwa": (DATA / "aqwa", "cylinder_excerpt.LIS", "cylinder_excerpt.LIS"),
    "nemoh": (DATA / "nemoh" / "oc3_hywind", "results/ExcitationForce.tec", "Nemoh.cal"),
    "nemoh-cal": (DATA / "nemoh" / "oc3_hywind", "Nemoh.cal", "Nemoh.cal"),
    "hydrostar": (DATA / "hams" / "cylinder" / "Output" / "Hydrostar_format", "Motion_3.rao", "Motion_3.rao"),
    "orcaflex": (DATA / "orcaflex", "cylinder_vessel_type.yml", "cylinder_vessel_type.yml"),
    "pnl": (DATA / "hams" / "cylinder" / "Input", "HullMesh.pnl", "HullMesh.pnl"),
    "nemoh-mesh": (DATA / "nemoh" / "cube", "Cube.dat", "Cube.dat"),
    "wamit-out": (DATA / "mss", "tanker.out", "tanker.out"),
    "gmsh": (DATA / "gmsh", "barge.msh", "barge.msh"),
}
"""Per reader: the folder it reads from, the file mutated in a copy of it, the file given to the reader (a file
stored compressed, ``NAME.xz``, is unpacked first)."""
MESHES = ("pnl", "nemoh-mesh", "gmsh")


def project(folder: Path, copy: Path) -> Path:
    """A copy of ``folder`` at ``copy`` with its ``.xz`` files unpacked."""
    shutil.copytree(folder, copy)
    for packed in copy.glob("*.xz"):
        packed.with_suffix("").write_bytes(lzma.decompress(packed.read_bytes()))
    return copy


def mutate(text: str, edits: list[tuple[int, str, str]]) -> str:
    lines = text.splitlines()
    for index, kind, junk in edits:
        if not lines:
            break
        index %= len(lines)
        if kind == "drop":
            del lines[index]
        elif kind == "cut":
            lines[index] = lines[index][: len(lines[index]) // 2]
        elif kind == "junk":
            lines[index] += junk
        elif kind == "dup":
            lines.insert(index, lines[index])
        elif kind == "nan":
            lines[index] = lines[index].replace("0", "nan", 1)
        else:
            lines[index] = lines[index].replace(" ", "", 2)
    return "\n".join(lines) + "\n"


EDITS = st.lists(st.tuples(st.integers(0, 10_000), st.sampled_from(["drop", "cut", "junk", "dup", "nan", "squash"]),
                           st.text(max_size=8)), min_size=1, max_size=4)


@pytest.mark.parametrize("name", sorted(SOURCES))
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(edits=EDITS)
def test_mutated_files_give_a_table_or_the_projects_error(tmp_path_factory, name, edits):
    """If this fails, a damaged file of that program escapes the reader as a Python exception (a traceback
    for the user) instead of a FileFormatError naming the file and line."""
    folder, mutated, given_file = SOURCES[name]
    copy = project(folder, tmp_path_factory.mktemp(name) / "project")
    target = copy / mutated
    target.write_bytes(mutate(target.read_text(errors="replace"), edits).encode("utf-8", "surrogatepass"))
    try:
        (load_hull if name in MESHES else read_rao)(copy / given_file)
    except MarinesimError:
        pass


@pytest.mark.parametrize("name", ["aqwa", "nemoh", "hydrostar", "orcaflex", "pnl", "nemoh-mesh", "wamit-out"])
def test_a_cut_file_is_one_line_at_the_command_line(tmp_path, name):
    """Cut to a third (the WAMIT report inside its second period's motions: a report cut between two periods
    reads as a shorter one, with a note)."""
    folder, mutated, given_file = SOURCES[name]
    copy = project(folder, tmp_path / "project")
    target = copy / mutated
    data = target.read_bytes()
    cut = len(data) // 3 if name != "wamit-out" else data.index(b"Wave Heading", data.index(b"RESPONSE AMPLITUDE", 30_000))
    target.write_bytes(data[:cut])
    result = cli("hull" if name in MESHES else "rao", str(copy / given_file), "--json", cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "project" in lines[0], result.stderr
