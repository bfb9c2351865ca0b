"""gmsh meshes (marinesim/hull/gmsh_mesh.py) from gmsh itself (tests/data/gmsh, made by make_meshes.py there):
the hydrostatics of a box barge exactly, a faceted spar between its inscribed polygon and its circle, the binary
form, and a file without a surface refused in one line."""

from __future__ import annotations

import math

import meshio
import numpy as np
import pytest

from conftest import ROOT, cli
from marinesim.errors import FileFormatError
from marinesim.hull import hydrostatics, load_hull

GMSH = ROOT / "tests" / "data" / "gmsh"


def test_the_box_barge_from_gmsh_has_the_boxs_hydrostatics():
    """40 x 10 m, draft 3 m, MSH 4.1 with a physical group: flat faces, so the wetted volume, the waterplane and
    the centre of buoyancy are exact; a failure means elements lost (a face missing leaves the hull open), or
    faces read with the wrong nodes."""
    statics = hydrostatics(load_hull(GMSH / "barge.msh"))
    assert statics.volume_m3 == pytest.approx(40 * 10 * 3, rel=1e-9)
    assert statics.waterplane_area_m2 == pytest.approx(400.0, rel=1e-9)
    np.testing.assert_allclose(statics.centre_of_buoyancy_m, [0.0, 0.0, -1.5], atol=1e-9)


def test_the_spar_from_gmsh_lies_between_its_inscribed_polygon_and_its_circle():
    """Radius 5 m, draft 30 m, MSH 2.2 in quadrangles of at most 2 m: the facets' nodes are on the circle, so
    the waterplane is at most the circle's and at least the regular polygon of 2 m sides inscribed in it
    (16 sides: 2.5 % less); the volume likewise. Quadrangles read as one triangle each would lose half the hull."""
    statics = hydrostatics(load_hull(GMSH / "spar_v22.msh"))
    circle = math.pi * 5.0**2
    sides = math.ceil(2 * math.pi * 5.0 / 2.0)
    polygon = sides / 2 * 5.0**2 * math.sin(2 * math.pi / sides)
    assert polygon <= statics.waterplane_area_m2 <= circle
    assert polygon * 30.0 <= statics.volume_m3 <= circle * 30.0
    assert statics.centre_of_buoyancy_m[2] == pytest.approx(-15.0, rel=2e-3)


def test_a_binary_msh_reads_as_its_ascii_twin(tmp_path):
    mesh = meshio.read(GMSH / "barge.msh")
    binary = tmp_path / "barge.msh"
    meshio.write(binary, mesh, file_format="gmsh", binary=True)
    assert b"\x00" in binary.read_bytes()
    assert hydrostatics(load_hull(binary)).volume_m3 == pytest.approx(1200.0, rel=1e-9)


def test_a_volume_mesh_without_its_surface_is_refused_in_one_line(tmp_path):
    path = tmp_path / "solid.msh"
    points = np.array([[0, 0, -1], [1, 0, -1], [0, 1, -1], [0, 0, 0.5]], float)
    meshio.write(path, meshio.Mesh(points, [("tetra", np.array([[0, 1, 2, 3]]))]), file_format="gmsh")
    with pytest.raises(FileFormatError, match=r"no surface elements .*tetra \(1\)"):
        load_hull(path)
    garbled = tmp_path / "garbled.msh"
    garbled.write_bytes((GMSH / "barge.msh").read_bytes()[:3000])
    run = cli("hull", str(garbled), cwd=tmp_path)
    assert run.returncode == 2 and "Traceback" not in run.stderr and len(run.stderr.strip().splitlines()) == 1
    assert "garbled.msh" in run.stderr
