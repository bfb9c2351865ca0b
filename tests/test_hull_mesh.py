"""Hull meshes (marinesim.hull.mesh): placement on loading (units, axes, mirror, draft, trim), repairs,
the checks that refuse bad meshes, and the shipped samples. The .gdf reader is in test_hull_gdf.py,
hydrostatics in test_hull_hydrostatics.py.

Independent reference: a trimmed box worked out by hand.
"""

import math
from pathlib import Path

import numpy as np
import pytest
import trimesh

from conftest import ROOT
from marinesim.errors import FileFormatError, MarinesimError, ParameterError
from marinesim.hull import box_hull, hydrostatics, load_hull, wigley_hull

TANKER = ROOT / "hulls" / "tanker.gdf"


def export(hull, path: Path, transform=None) -> Path:
    vertices = hull.vertices if transform is None else transform(hull.vertices)
    trimesh.Trimesh(vertices, hull.faces, process=False).export(path)
    return path


def test_units_axes_and_mirror_are_undone_on_loading(tmp_path):
    """The box written in millimetres, y up (body z -> mesh y, body y -> mesh -z): read back with
    units='mm' and axes='x,-z,y' it is the same barge; read as metres it is refused, naming mm."""
    barge = box_hull(100.0, 20.0, 5.0, 10.0)
    path = export(barge, tmp_path / "barge_mm_yup.obj", lambda v: 1000.0 * v[:, [0, 2, 1]] * [1, 1, -1])
    s = hydrostatics(load_hull(path, units="mm", axes="x,-z,y"))
    assert s.volume_m3 == pytest.approx(100 * 20 * 5, rel=1e-9)
    assert s.centre_of_buoyancy_m[2] == pytest.approx(-2.5, rel=1e-9)
    with pytest.raises(ParameterError, match="units='mm' gives 100 m"):
        load_hull(path, axes="x,-z,y")
    mirrored = export(barge, tmp_path / "mirror.stl", lambda v: v * [1, -1, 1])  # left-handed copy
    assert hydrostatics(load_hull(mirrored, axes="x,-y,z")).volume_m3 == pytest.approx(10000.0, rel=1e-6)


def test_draft_and_trim_against_the_trimmed_box(tmp_path):
    """Keel at z = -draft, then trim t bow down about the origin: the waterline runs along
    z = x tan t in the hull, so V = L B T, x_B = L^2 tan t / (12 T) and z_B = tan^2 t L^2 / (24 T) - T / 2
    in the hull, rotated into the earth frame. A sign error in the trim moves the LCB aft."""
    L, B, T, trim = 100.0, 20.0, 3.0, 1.5
    path = export(box_hull(L, B, 5.0, 10.0), tmp_path / "barge.stl")
    level = hydrostatics(load_hull(path, draft=T))
    assert level.volume_m3 == pytest.approx(L * B * T, rel=1e-6) and level.draft_m == pytest.approx(T)
    s = hydrostatics(load_hull(path, draft=T, trim_deg=trim))
    t = math.radians(trim)
    xb_hull, zb_hull = L**2 * math.tan(t) / (12 * T), math.tan(t) ** 2 * L**2 / (24 * T) - T / 2
    xb, zb = math.cos(t) * xb_hull + math.sin(t) * zb_hull, -math.sin(t) * xb_hull + math.cos(t) * zb_hull
    assert s.volume_m3 == pytest.approx(L * B * T, rel=1e-6)
    assert s.centre_of_buoyancy_m[0] == pytest.approx(xb, rel=1e-5), "LCB of the trimmed barge"
    assert s.centre_of_buoyancy_m[2] == pytest.approx(zb, rel=1e-5)


def test_repairable_meshes_are_repaired_and_said_so(tmp_path):
    barge = box_hull(100.0, 20.0, 5.0, 10.0)
    inverted = tmp_path / "inside_out.stl"
    trimesh.Trimesh(barge.vertices, barge.faces[:, ::-1], process=False).export(inverted)
    hull = load_hull(inverted)
    assert hydrostatics(hull).volume_m3 == pytest.approx(10000.0, rel=1e-6)
    assert any("flipped" in note for note in hull.notes)
    faces = barge.faces.copy()
    faces[3] = faces[3, ::-1]
    one_flipped = tmp_path / "one_flipped.stl"
    trimesh.Trimesh(barge.vertices, faces, process=False).export(one_flipped)
    hull = load_hull(one_flipped)
    assert hydrostatics(hull).volume_m3 == pytest.approx(10000.0, rel=1e-6)
    assert any("winding" in note for note in hull.notes)
    model = export(barge, tmp_path / "model.stl", lambda v: v / 50.0)
    assert any("scale" in note for note in load_hull(model).notes)
    assert hydrostatics(load_hull(model, scale=50)).volume_m3 == pytest.approx(10000.0, rel=1e-5)


def test_bad_meshes_are_refused_with_an_actionable_message(tmp_path):
    barge = box_hull(100.0, 20.0, 5.0, 10.0)
    empty = tmp_path / "empty.obj"
    empty.write_text("# no faces\nv 0 0 0\n")
    with pytest.raises(MarinesimError, match="no faces"):
        load_hull(empty)
    nan = tmp_path / "nan.obj"
    nan.write_text("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(FileFormatError, match="not finite"):
        load_hull(nan)
    above = export(barge, tmp_path / "above.stl", lambda v: v + [0, 0, 10.0])
    with pytest.raises(ParameterError, match="nothing below the waterline.*give the draft"):
        load_hull(above)
    with pytest.raises(ParameterError, match="draft must be > 0"):
        load_hull(above, draft=-2.0)
    holed = tmp_path / "holed.stl"
    bottom = np.flatnonzero(np.isclose(barge.vertices[barge.faces][:, :, 2], -5.0).all(axis=1))[0]
    trimesh.Trimesh(barge.vertices, np.delete(barge.faces, bottom, axis=0), process=False).export(holed)
    with pytest.raises(FileFormatError, match="not closed below the waterline"):
        load_hull(holed)
    with pytest.raises(ParameterError, match="axes"):
        load_hull(TANKER, axes="x,x,z")
    with pytest.raises(ParameterError, match="units"):
        load_hull(TANKER, units="furlong")
    with pytest.raises(ParameterError, match="trim"):
        load_hull(TANKER, trim_deg=45.0)
    with pytest.raises(FileFormatError, match="unknown hull format"):
        load_hull(ROOT / "README.md")
    garbage = tmp_path / "garbage.stl"
    garbage.write_bytes(b"\x00\x01 not a mesh")
    with pytest.raises(FileFormatError, match=str(garbage.name)):
        load_hull(garbage)


def test_shipped_samples_are_what_their_generators_make():
    """hulls/wigley.stl and hulls/box_barge.stl are the documented generator calls (float32 STL)."""
    for name, hull in (("wigley.stl", wigley_hull(100.0, 10.0, 6.25, nx=80, nz=16)),
                       ("box_barge.stl", box_hull(100.0, 20.0, 5.0, 10.0))):
        shipped = hydrostatics(load_hull(ROOT / "hulls" / name))
        made = hydrostatics(hull)
        assert shipped.volume_m3 == pytest.approx(made.volume_m3, rel=1e-6), name
        assert shipped.wetted_area_m2 == pytest.approx(made.wetted_area_m2, rel=1e-6), name


def test_a_gzipped_stl_is_the_stl_and_a_damaged_one_is_one_error(tmp_path):
    """Hull files often travel gzipped (.stl.gz): read as the STL inside, to the same hydrostatics; a cut archive
    and one that would expand beyond the bound are refused naming the file, before anything is allocated."""
    import gzip

    from marinesim.hull import mesh as mesh_module

    source = ROOT / "hulls" / "wigley.stl"
    packed = tmp_path / "wigley.stl.gz"
    packed.write_bytes(gzip.compress(source.read_bytes()))
    assert hydrostatics(load_hull(packed)).volume_m3 == hydrostatics(load_hull(source)).volume_m3
    cut = tmp_path / "cut.stl.gz"
    cut.write_bytes(packed.read_bytes()[:400])
    with pytest.raises(FileFormatError, match=r"cut\.stl\.gz: cannot decompress"):
        load_hull(cut)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(mesh_module, "MAX_GUNZIPPED_BYTES", 1000)
        with pytest.raises(FileFormatError, match="decompresses to more than"):
            load_hull(packed)
