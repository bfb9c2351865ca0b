"""NEMOH meshes (``.dat``, Capytaine's ``.mar``) read from NEMOH's own verification case (the cube of its
two-body test, tests/data/nemoh/README.md), checked against the box it describes."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from marinesim import formats
from marinesim.errors import FileFormatError
from marinesim.hull import load_hull
from marinesim.hull.hydrostatics import hydrostatics
from marinesim.hull.nemoh_mesh import read_nemoh_mesh, sniff

CUBE = Path(__file__).parent / "data" / "nemoh" / "cube" / "Cube.dat"


def test_nemohs_cube_is_the_box_it_describes(tmp_path):
    """The cube (half given, ISYM 1) is 10 x 10 m and 5 m deep at x = 100 m: 500 m^3, a 100 m^2 waterplane, the
    centre of buoyancy at (100, 0, -2.5) m, exactly (flat faces). A failure means a half not mirrored, a panel
    misread, or normals flipped the wrong way. The same file named .mar (Capytaine's name for it) reads alike."""
    statics = hydrostatics(load_hull(CUBE))
    assert statics.volume_m3 == pytest.approx(500.0, rel=1e-12)
    assert statics.waterplane_area_m2 == pytest.approx(100.0, rel=1e-12)
    assert statics.centre_of_buoyancy_m == pytest.approx((100.0, 0.0, -2.5), abs=1e-9)
    mar = tmp_path / "cube.mar"
    shutil.copyfile(CUBE, mar)
    assert formats.detect(mar, "mesh").name == "nemoh-mesh"
    assert hydrostatics(load_hull(mar)).volume_m3 == pytest.approx(500.0, rel=1e-12)


def test_sniff_and_malformed_files_name_the_line(tmp_path):
    head = CUBE.read_bytes()[:4096]
    assert sniff(head) and not sniff(b"solid cube\n facet normal 0 0 1\n")
    lines = CUBE.read_text().splitlines()
    end_of_nodes = next(i for i, line in enumerate(lines) if line.split()[0] == "0")
    cases = {
        "ISYM must be 0 or 1": ["2 3"] + lines[1:],
        "panel uses node 9999": lines[:end_of_nodes + 1] + ["1 2 3 9999"] + lines[end_of_nodes + 2:],
        "the file ends early": lines[:end_of_nodes + 20],
        "node 1 is defined twice": lines[:2] + lines[1:],
    }
    for expected, text in cases.items():
        path = tmp_path / "bad.dat"
        path.write_text("\n".join(text) + "\n")
        with pytest.raises(FileFormatError, match=expected):
            read_nemoh_mesh(path)
