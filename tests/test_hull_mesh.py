"""Hulls: the .gdf reader, placement (units, axes, draft, trim), the checks, and hydrostatics.

Independent references: WAMIT's own hydrostatics of the tanker panels (the .hst restoring
coefficients and the .frc mass, computed by another program), the analytic box, the analytic
Wigley hull (with scipy quadrature of its wetted area), and a trimmed box worked out by hand.
"""

import math
from pathlib import Path

import numpy as np
import pytest
import trimesh
from scipy.integrate import dblquad, quad

from marinesim.errors import FileFormatError, MarinesimError, ParameterError
from marinesim.hull import box_hull, hydrostatics, load_hull, wigley_half_breadth, wigley_hull
from marinesim.hull.gdf import read_gdf, read_gdf_header

ROOT = Path(__file__).resolve().parent.parent
TANKER = ROOT / "hulls" / "tanker.gdf"
RHO = 1025.0


def export(hull, path: Path, transform=None) -> Path:
    vertices = hull.vertices if transform is None else transform(hull.vertices)
    trimesh.Trimesh(vertices, hull.faces, process=False).export(path)
    return path


def test_tanker_hydrostatics_match_wamit_hst_and_frc():
    """WAMIT's .hst (nondimensional by rho g ULEN^n, ULEN = 1) and .frc for these very panels:
    C33 = A_wp, C35 = -A_wp x_F, C55 - C44 = int (x^2 - y^2) dA_wp (the z_B and z_G terms cancel),
    C44 = I_T + V (z_B - z_G) with the .frc's z_G, which it gives to 0.1 m; the .frc mass is rho V and
    the CoG lies above the centre of buoyancy in x. A wrong mirror (ISY) would halve everything; a
    wrong vertex order would make the volume negative."""
    statics = hydrostatics(load_hull(TANKER), RHO)
    hst = {(int(i), int(j)): v for i, j, v in np.loadtxt(ROOT / "rao" / "tanker" / "tanker.hst")}
    frc = (ROOT / "rao" / "tanker" / "tanker.frc").read_text().splitlines()
    xg, _, zg = (float(v) for v in frc[3].split())
    mass = float(frc[5].split()[0])
    xb, yb, zb = statics.centre_of_buoyancy_m
    area = statics.waterplane_area_m2
    assert area == pytest.approx(hst[3, 3], rel=1e-5), "waterplane area differs from WAMIT's C33"
    assert -area * statics.centre_of_flotation_m[0] == pytest.approx(hst[3, 5], rel=1e-4), "LCF differs from C35"
    i_t = statics.bm_transverse_m * statics.volume_m3
    i_l = statics.bm_longitudinal_m * statics.volume_m3 + area * statics.centre_of_flotation_m[0] ** 2
    assert i_l - i_t == pytest.approx(hst[5, 5] - hst[4, 4], rel=1e-5), "waterplane inertia differs from WAMIT's"
    assert zb - (hst[4, 4] - i_t) / statics.volume_m3 == pytest.approx(zg, abs=0.05), "GM_T differs from C44"
    assert RHO * statics.volume_m3 == pytest.approx(mass, rel=1e-4), "displacement differs from the .frc mass"
    assert xb == pytest.approx(xg, abs=0.01), "LCB is not under the CoG of the free-floating tanker"
    assert abs(yb) < 1e-9, "the mirrored hull is not symmetric"
    assert statics.draft_m == pytest.approx(10.0) and statics.waterline_beam_m == pytest.approx(46.0)


def test_gdf_header_and_mirror_planes(tmp_path):
    """A quarter of a box given with ISX = ISY = 1 becomes the whole box: both mirrors and the
    quadrilateral split must be right for the analytic volume, area and BM."""
    L, B, T = 40.0, 10.0, 4.0
    panels = [  # x >= 0, y >= 0 quarter of the wetted surface, listed clockwise seen from outside ...
        [(0, B / 2, 0), (0, B / 2, -T), (L / 2, B / 2, -T), (L / 2, B / 2, 0)],  # side, +y
        [(0, 0, -T), (0, B / 2, -T), (0, B / 2, -T), (0, 0, -T)],  # degenerate panel: dropped
        [(0, 0, -T), (L / 2, 0, -T), (L / 2, B / 2, -T), (0, B / 2, -T)],  # bottom, -z
        [(L / 2, 0, 0), (L / 2, B / 2, 0), (L / 2, B / 2, -T), (L / 2, 0, -T)],  # bow, +x
    ]
    text = ["quarter box", "2.5 9.81   ULEN GRAV", "1 1   ISX ISY", f"{len(panels)}"]
    text += [" ".join(f"{c:g}" for c in vertex) for panel in panels for vertex in panel[::-1]]  # ... so reversed
    path = tmp_path / "quarter.gdf"
    path.write_text("\n".join(text) + "\n")
    header = read_gdf_header(path)
    assert (header.ulen, header.g, header.isx, header.isy) == (2.5, 9.81, 1, 1)
    hull = load_hull(path)
    assert hull.notes == (), "the mirrored panels needed repair: their vertex order is wrong"
    statics = hydrostatics(hull)
    assert statics.volume_m3 == pytest.approx(L * B * T, rel=1e-12)
    assert statics.waterplane_area_m2 == pytest.approx(L * B, rel=1e-12)
    assert statics.bm_transverse_m == pytest.approx(B**2 / (12 * T), rel=1e-12)
    assert statics.wetted_area_m2 == pytest.approx(L * B + 2 * (L + B) * T, rel=1e-12)


@pytest.mark.parametrize("line, text, expected", [
    (2, "1.0 abc ULEN GRAV", "GRAV"),
    (3, "0 2 ISX ISY", "ISY must be 0 or 1"),
    (4, "x", "NPAN"),
    (None, None, "file ends early"),
])
def test_malformed_gdf_names_line_and_field(tmp_path, line, text, expected):
    lines = TANKER.read_text().splitlines()[:40]  # header + 9 panels, but NPAN says 2375
    if line is not None:
        lines[line - 1] = text
    path = tmp_path / "bad.gdf"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(FileFormatError) as error:
        read_gdf(path)
    assert str(path) in str(error.value) and expected in str(error.value)
    if line is not None:
        assert f"line {line}" in str(error.value)


def test_box_hydrostatics_are_exact():
    L, B, T = 100.0, 20.0, 5.0
    s = hydrostatics(box_hull(L, B, T, 10.0), RHO)
    assert s.volume_m3 == pytest.approx(L * B * T, rel=1e-12)
    assert s.displacement_t == pytest.approx(RHO * L * B * T / 1000, rel=1e-12)
    assert s.waterplane_area_m2 == pytest.approx(L * B, rel=1e-12)
    assert s.wetted_area_m2 == pytest.approx(L * B + 2 * (L + B) * T, rel=1e-12)
    assert s.centre_of_buoyancy_m == pytest.approx((0.0, 0.0, -T / 2), abs=1e-9)
    assert s.bm_transverse_m == pytest.approx(B**2 / (12 * T), rel=1e-12)
    assert s.bm_longitudinal_m == pytest.approx(L**2 / (12 * T), rel=1e-12)
    assert (s.waterline_length_m, s.waterline_beam_m, s.draft_m) == pytest.approx((L, B, T))


def wigley_reference(L: float, B: float, T: float) -> dict[str, float]:
    """Analytic V, A_wp, z_B; I_T and the wetted area by scipy quadrature of the offsets."""
    def y(x, z):
        return wigley_half_breadth(x, z, L, B, T)

    def stretch(z, x):  # |dS / dx dz| on one side: sqrt(1 + Y_x^2 + Y_z^2)
        yx = -4 * B * x / L**2 * (1 - (z / T) ** 2)
        yz = -B * z / T**2 * (1 - (2 * x / L) ** 2)
        return math.sqrt(1 + yx**2 + yz**2)

    return {"volume": 4 * L * B * T / 9, "waterplane": 2 * L * B / 3, "zb": -3 * T / 8,
            "i_t": quad(lambda x: 2 * float(y(x, 0.0)) ** 3 / 3, -L / 2, L / 2)[0],
            "wetted": 2 * dblquad(stretch, -L / 2, L / 2, -T, 0.0, epsabs=1e-9)[0]}


def test_wigley_hydrostatics_converge_to_the_analytic_hull():
    """Flat triangles on the curved hull: errors of order h^2, so halving the panels divides each
    error by about 4, and the 80 x 16 mesh is within 0.1 % (an O(h) error would be ~2 %)."""
    L, B, T = 100.0, 10.0, 6.25
    ref = wigley_reference(L, B, T)
    errors = []
    for nx, nz in ((40, 8), (80, 16)):
        s = hydrostatics(wigley_hull(L, B, T, nx=nx, nz=nz))
        got = {"volume": s.volume_m3, "waterplane": s.waterplane_area_m2, "zb": s.centre_of_buoyancy_m[2],
               "i_t": s.bm_transverse_m * s.volume_m3, "wetted": s.wetted_area_m2}
        errors.append({key: abs(got[key] / ref[key] - 1) for key in ref})
        assert s.waterline_length_m == pytest.approx(L) and s.waterline_beam_m == pytest.approx(B)
        assert s.centre_of_buoyancy_m[0] == pytest.approx(0.0, abs=1e-9)
    for key in ref:
        assert errors[1][key] < 1e-3, f"{key} off by {100 * errors[1][key]:.3f} % on the 80 x 16 mesh"
        assert 3.0 < errors[0][key] / errors[1][key] < 5.0, f"{key} does not converge as h^2"


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
