"""The WAMIT .gdf panel reader (marinesim.hull.gdf): header and mirror planes, and malformed files
refused naming the line and the field."""

import pytest

from conftest import ROOT
from marinesim.errors import FileFormatError
from marinesim.hull import hydrostatics, load_hull
from marinesim.hull.gdf import read_gdf, read_gdf_header

TANKER = ROOT / "hulls" / "tanker.gdf"


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


def test_the_iea15_semisubmersible_gdf_as_its_mesher_wrote_it(tmp_path):
    """The IEA-15 MW VolturnUS-S panels as the reference turbine ships them for WAMIT (tests/data/iea15): a panel
    number after each fourth vertex, a closing '0 NPAND' line, the interior free-surface panels of the irregular-
    frequency removal at z = 0, and volumes by x and z 0.08 % apart. Read, they give the volume and waterplane
    WAMIT printed for them (VOLZ 20132.0 m^3, C(3,3) 443.05 m^2 at ULEN 1) and its centre of buoyancy to 0.1 %;
    a failure means a panel number read as a coordinate, the NPAND line refused, or the hull taken as open."""
    import lzma
    import re

    data = ROOT / "tests" / "data" / "iea15"
    path = tmp_path / "IEA-15-240-RWT.gdf"
    path.write_bytes(lzma.decompress((data / "IEA-15-240-RWT.gdf.xz").read_bytes()))
    printed = lzma.decompress((data / "IEA-15-240-RWT-UMaineSemi.out.xz").read_bytes()).decode()
    volz = float(re.search(r"VOLX,VOLY,VOLZ\):\s+\S+\s+\S+\s+(\S+)", printed).group(1))
    c33 = float(re.search(r"C\(3,3\),C\(3,4\),C\(3,5\):\s+(\S+)", printed).group(1))
    zb = float(re.search(r"\(Xb,Yb,Zb\):\s+\S+\s+\S+\s+(\S+)", printed).group(1))
    statics = hydrostatics(load_hull(path))
    assert statics.volume_m3 == pytest.approx(volz, abs=0.05)
    assert statics.waterplane_area_m2 == pytest.approx(c33, abs=0.005)
    assert statics.centre_of_buoyancy_m[2] == pytest.approx(zb, rel=1e-3)
    lines = path.read_text().splitlines()
    lines[-1] = "2   NPAND"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(FileFormatError, match="NPAND > 0: dipole panels"):
        read_gdf(path)
