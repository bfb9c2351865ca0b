"""HAMS panel meshes (``.pnl``) read from HAMS's own certification inputs (tests/data/hams/README.md), checked
against the numbers HAMS was given with them and against the mirror of a half mesh."""

from __future__ import annotations

import lzma
from pathlib import Path

import numpy as np
import pytest

from marinesim.errors import FileFormatError
from marinesim.hull import load_hull
from marinesim.hull.hydrostatics import hydrostatics
from marinesim.hull.pnl import read_pnl, sniff

HAMS = Path(__file__).parent / "data" / "hams"
CYLINDER = HAMS / "cylinder" / "Input" / "HullMesh.pnl"
RHO = 1025.0


def hams_matrix(path: Path, title: str) -> np.ndarray:
    """The 6 x 6 matrix under ``title`` in a HAMS ``Hydrostatic.in``."""
    lines = path.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if line.strip().startswith(title)) + 1
    return np.array([[float(v) for v in line.split()] for line in lines[start:start + 6]])


def test_the_cylinder_displaces_the_mass_hams_was_given_and_floats_at_its_stiffness():
    """HAMS's cylinder (r 1 m, draught 0.5 m, 24 sides): the panels displace the body's mass over rho (1604 kg,
    1.56488 m^3) and their waterplane gives the heave stiffness in HAMS's input (31462 N/m = rho g Awp) to the
    printed digits: a failure means nodes, panels or the orientation are read wrong."""
    statics = hydrostatics(load_hull(CYLINDER))
    hydrostatic = HAMS / "cylinder" / "Input" / "Hydrostatic.in"
    mass = hams_matrix(hydrostatic, "Body Mass Matrix")[0, 0]
    assert statics.volume_m3 == pytest.approx(mass / RHO, rel=1e-4)
    c33 = hams_matrix(hydrostatic, "Hydrostatic Restoring Matrix")[2, 2]
    assert RHO * 9.80665 * statics.waterplane_area_m2 == pytest.approx(c33, rel=1e-4)


def test_a_half_mesh_with_its_symmetry_flag_is_the_whole_mesh(tmp_path):
    """The cylinder cut to its y >= 0 panels with Y-symmetry 1 has the whole cylinder's volume, waterplane and
    centre of buoyancy: the mirrored half keeps its normals outward (a wrong vertex order would cancel it)."""
    lines = CYLINDER.read_text().splitlines()
    vertices, _ = read_pnl(CYLINDER)
    start = next(i for i, line in enumerate(lines) if "Node Relations" in line and "Start" in line)
    end = next(i for i, line in enumerate(lines) if "Node Relations" in line and "End" in line)
    kept = [line for line in lines[start + 1:end]
            if min(vertices[int(n) - 1, 1] for n in line.split()[2:]) >= -1e-9]
    counts = lines[3].split()
    lines[3] = f"  {len(kept)}  {counts[1]}  0  1"
    half = tmp_path / "half.pnl"
    half.write_text("\n".join(lines[:start + 1] + kept + lines[end:]) + "\n")
    whole, mirrored = hydrostatics(load_hull(CYLINDER)), hydrostatics(load_hull(half))
    assert 0 < len(kept) < end - start - 1
    assert mirrored.volume_m3 == pytest.approx(whole.volume_m3, rel=1e-9)
    assert mirrored.waterplane_area_m2 == pytest.approx(whole.waterplane_area_m2, rel=1e-9)


def test_hams_deepcwind_semisubmersible_reads_as_a_closed_hull(tmp_path):
    """The OC4 DeepCwind semisubmersible (Y-symmetry 1, 1479 panels): its warped quadrilaterals give volumes by
    x, y and z 0.074 % apart, as WAMIT's own VOLX/VOLZ differ; it is a closed hull (it was refused before), and
    its mirrored halves make it symmetric about y = 0."""
    path = tmp_path / "HullMesh.pnl"
    path.write_bytes(lzma.decompress((HAMS / "deepcwind_HullMesh.pnl.xz").read_bytes()))
    hull = load_hull(path)
    statics = hydrostatics(hull)
    assert statics.volume_m3 == pytest.approx(13_680, rel=0.001)
    assert abs(statics.centre_of_buoyancy_m[1]) < 1e-6 * statics.volume_m3 ** (1 / 3)


def test_sniff_and_malformed_files_name_the_line(tmp_path):
    assert sniff(CYLINDER.read_bytes()[:2048]) and not sniff(b"0.1 0 1 1.0\n")
    lines = CYLINDER.read_text().splitlines()
    cases = {
        "276 panels where the header declares 277": lines[:3] + ["  277  261  0  0"] + lines[4:],
        "panel uses node 999": [line.replace("   1    4 ", "   1    4       999 ", 1) if i > 268 else line
                                for i, line in enumerate(lines)],
        "ends inside the panel section": lines[:300],
        "node ID": [line.replace("    1 ", "    x ", 1) if i == 6 else line for i, line in enumerate(lines)],
    }
    for expected, text in cases.items():
        path = tmp_path / "bad.pnl"
        path.write_text("\n".join(text) + "\n")
        with pytest.raises(FileFormatError, match=expected):
            read_pnl(path)
