"""A WAMIT run's files read against each other (marinesim/vessel/wamit_forces.py, wamit.py, hull/wamit_pot.py):
cut or mismatched files refused naming the file and what it lacks; each body of a run of several placed by the
.pot that names it and read by its number or .gdf name; a WAMIT 7.2 report (no density printed) read with
WAMIT's default density; a .frc with zero radii of gyration standing beside the scenario's mass. Every case is
staged on copies of the MSS tanker's and the IEA-15 semisubmersible's real files, cut or edited in tmp_path."""

from __future__ import annotations

import lzma
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT, cli
from marinesim.errors import FileFormatError
from marinesim.hull import hydrostatics, load_hull
from marinesim.sea.dispersion import k_from_omega
from marinesim.vessel.body import RigidBody
from marinesim.vessel.rao import make_table
from marinesim.vessel.read import read_rao
from marinesim.vessel.wamit_forces import read_force_set
from marinesim.vessel.write import write_wamit

TANKER = ROOT / "rao" / "tanker"
IEA = ROOT / "tests" / "data" / "iea15"
PEAK_SHARE = 0.01
"""Largest |computed - WAMIT .4| as a share of the DOF's largest |RAO| (tests/test_vessel_wamit_forces.py)."""


def copy_set(folder: Path, suffixes=(".1", ".3", ".hst", ".frc", ".cfg", ".gdf")) -> Path:
    for suffix in suffixes:
        shutil.copyfile(TANKER / f"tanker{suffix}", folder / f"tanker{suffix}")
    return folder / "tanker.3"


def snapshot(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def refused_in_one_line(folder: Path, *args: str) -> str:
    """Run ``marinesim`` with ``args``: exit 2, one line, no traceback, the folder's files unchanged."""
    before = snapshot(folder)
    result = cli(*args, cwd=folder)
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 2 and len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    assert snapshot(folder) == before
    return lines[0]


def periods_of(path: Path) -> list[str]:
    return list(dict.fromkeys(line.split()[0] for line in path.read_text().splitlines() if line.split()))


def test_an_hst_cut_after_the_heave_rows_is_refused(tmp_path):
    """Read as zeros, the missing C44 and C55 left roll and pitch without restoring: RAOs a hundred times the
    long-wave limit, flagged only as "check". The tanker's own .hst restores roll and pitch, and is read."""
    path = copy_set(tmp_path)
    full = read_rao(path)
    k = full.omega[0] ** 2 / full.g
    assert abs(full(full.omega[:1], np.array([math.pi]))[0, 4]) < 2 * k  # pitch near its long-wave limit k
    hst = tmp_path / "tanker.hst"
    hst.write_text("\n".join(hst.read_text().splitlines()[:18]) + "\n")
    with pytest.raises(FileFormatError, match=r"no rows of mode\(s\) 4, 5, 6") as error:
        read_rao(path)
    assert error.value.path == hst
    assert str(hst) in refused_in_one_line(tmp_path, "rao", str(path))


def test_a_3_cut_to_half_its_periods_is_refused(tmp_path):
    """A .3 of 29 of the .1's 58 periods gave a table of 29 periods with no word; the .3 names what it lacks."""
    path = copy_set(tmp_path)
    periods = periods_of(path)
    kept = set(periods[:len(periods) // 2])
    path.write_text("".join(line + "\n" for line in path.read_text().splitlines() if line.split()[0] in kept))
    with pytest.raises(FileFormatError, match=f"{len(periods) - len(kept)} of the {len(periods)} periods of "
                                              "tanker.1 missing") as error:
        read_rao(path)
    assert error.value.path == path
    assert "tanker.3" in refused_in_one_line(tmp_path, "rao", str(path))


def test_a_1_cut_inside_a_period_is_refused(tmp_path):
    """The .1 cut after the surge-surge line of its last period: that period's heave, roll... would have no added
    mass or damping (zeros), the motions there wrong by their whole radiation terms."""
    path = copy_set(tmp_path)
    one = tmp_path / "tanker.1"
    lines = one.read_text().splitlines()
    last = lines[-1].split()[0]
    first_of_last = next(n for n, line in enumerate(lines) if line.split()[0] == last)
    one.write_text("\n".join(lines[:first_of_last + 1]) + "\n")
    with pytest.raises(FileFormatError, match=r"no added mass and damping of mode\(s\) 2, 3, 4, 5, 6") as error:
        read_rao(path)
    assert error.value.path == one


def test_a_3_of_other_headings_than_the_pot_lists_is_refused(tmp_path):
    """The run's .pot (WAMIT 7 form) lists 19 headings 0..180 deg; a .3 cut to 0..90 deg is not that run's whole
    output. The same .pot with the whole .3 reads as the tanker's table."""
    path = copy_set(tmp_path)
    (tmp_path / "tanker.cfg").write_text("IALTFRC=2\nIPERIO=1\n")
    periods = " ".join(p for p in periods_of(tmp_path / "tanker.1") if float(p) > 0)
    (tmp_path / "tanker.pot").write_text(f"tanker\n-1\n1 1\n58\n{periods}\n-19\n0 10\n1\ntanker.gdf\n0 0 0 0\n"
                                         "1 1 1 1 1 1\n")
    np.testing.assert_allclose(read_rao(path).values, read_rao(TANKER / "tanker.3").values, rtol=1e-12)
    path.write_text("".join(line + "\n" for line in path.read_text().splitlines() if float(line.split()[1]) <= 90))
    with pytest.raises(FileFormatError, match="lacks heading.s. 100, 110, .*180 deg against the 19 the run's "
                                              "tanker.pot lists") as error:
        read_rao(path)
    assert error.value.path == path


def two_body_pot(folder: Path, name: str, second: str, xbody: tuple[float, float, float, float]) -> Path:
    """A WAMIT 7 .pot ``name`` of two bodies (the tanker's 19 headings 0..180 deg): the tanker at the origin and
    ``second`` at ``xbody``."""
    pot = folder / name
    pot.write_text("two bodies\n-1\n1 1\n1\n10.0\n-19\n0 10\n2\ntanker.gdf\n0 0 0 0\n1 1 1 1 1 1\n"
                   f"{second}\n{' '.join(f'{v:g}' for v in xbody)}\n1 1 1 1 1 1\n")
    return pot


def test_each_body_of_a_run_is_placed_by_the_pot_that_names_it(tmp_path):
    """Body 2 of a two-body run: the tanker's panels written 2 m higher in its body coordinates (waterline at
    body z = +2), placed 2 m down by the run's .pot, whose name is not the .gdf's. Read at its body-frame draft
    it lost a fifth of its volume with no note; placed, it has the tanker's volume and centre of buoyancy, and
    the note says the origin is below the free surface and the hull lowered."""
    lines = (TANKER / "tanker.gdf").read_text().splitlines()
    raised = lines[:4] + [" ".join([*line.split()[:2], f"{float(line.split()[2]) + 2.0:.5f}"]) for line in lines[4:]]
    (tmp_path / "barge.gdf").write_text("\n".join(raised) + "\n")
    two_body_pot(tmp_path, "run.pot", "barge.gdf", (50.0, 60.0, -2.0, 0.0))
    original, placed = hydrostatics(load_hull(TANKER / "tanker.gdf")), hydrostatics(load_hull(tmp_path / "barge.gdf"))
    assert placed.volume_m3 == pytest.approx(original.volume_m3, rel=1e-6)
    np.testing.assert_allclose(placed.centre_of_buoyancy_m, original.centre_of_buoyancy_m, atol=1e-4)
    note = load_hull(tmp_path / "barge.gdf").notes[0]
    assert "run.pot: body 2, ZBODY -2 m" in note and "2 m below the free surface" in note and "lowered" in note
    two_body_pot(tmp_path, "other.pot", "barge.gdf", (50.0, 60.0, -3.0, 0.0))
    with pytest.raises(FileFormatError, match="places barge.gdf at XBODY"):
        load_hull(tmp_path / "barge.gdf")


def test_a_single_body_raised_by_zbody_is_said_to_be_above(tmp_path):
    """ZBODY +1.5 puts the body origin above the free surface: the hull (waterline at body z = -1.5) is raised."""
    lines = (TANKER / "tanker.gdf").read_text().splitlines()
    lowered = lines[:4] + [" ".join([*line.split()[:2], f"{float(line.split()[2]) - 1.5:.5f}"]) for line in lines[4:]]
    (tmp_path / "low.gdf").write_text("\n".join(lowered) + "\n")
    (tmp_path / "low.cfg").write_text("IALTPOT=1\n")
    (tmp_path / "low.pot").write_text("low\n1\n3\n-1 0 0 1.5 0\n0 1 0\n")
    hull = load_hull(tmp_path / "low.gdf")
    assert hydrostatics(hull).volume_m3 == pytest.approx(hydrostatics(load_hull(TANKER / "tanker.gdf")).volume_m3,
                                                         rel=1e-6)
    assert "1.5 m above the free surface: the hull raised by 1.5 m" in hull.notes[0]


def test_the_body_of_a_two_body_4_is_read_by_its_number_or_gdf_name(tmp_path):
    """A .4 of two bodies (modes 1-6 and 7-12): body 1 the tanker at the origin, body 2 the tanker placed 50 m
    ahead, its phases relative to the wave at WAMIT's origin as WAMIT writes them. Read by --body 2 or its .gdf
    name it is the tanker's own table (phases referred to its origin); without --body it is refused, naming
    the bodies, where modes 7-12 were dropped with a note and body 1 read in its place."""
    tanker = read_rao(TANKER / "tanker.4")
    half = tanker.beta <= math.pi + 1e-9
    k = k_from_omega(tanker.omega, math.inf, tanker.g)
    lag = np.exp(-1j * k[None, :] * 50.0 * np.cos(tanker.beta[half])[:, None])
    for name, factor in (("one.4", 1.0), ("two.4", lag[..., None])):
        write_wamit(make_table(tanker.omega, tanker.beta[half], [0.0], (tanker.values[0][half] * factor)[None],
                               rho=tanker.rho, g=tanker.g, source=name, source_format="wamit"), tmp_path / name)
    rows = [line.split() for line in (tmp_path / "one.4").read_text().splitlines()]
    second = [line.split() for line in (tmp_path / "two.4").read_text().splitlines()]
    assert [r[:3] for r in rows] == [r[:3] for r in second]
    merged = []
    for start in range(0, len(rows), 6):
        merged += [" ".join(r) for r in rows[start:start + 6]]
        merged += [" ".join([r[0], r[1], str(int(r[2]) + 6), *r[3:]]) for r in second[start:start + 6]]
    (tmp_path / "run.4").write_text("\n".join(merged) + "\n")
    two_body_pot(tmp_path, "run.pot", "barge.gdf", (50.0, 0.0, 0.0, 0.0))
    for body in ("2", "barge", "barge.gdf"):
        read = read_rao(tmp_path / "run.4", body=body)
        scale = np.abs(tanker.values).max(axis=(0, 1, 2))
        assert np.all(np.abs(read.values - tanker.values).max(axis=(0, 1, 2)) < 1e-5 * scale)
        assert any("body 2 (barge.gdf) of a run of 2 bodies: its modes 7-12" in note for note in read.notes)
    with pytest.raises(FileFormatError, match=r"a run of 2 bodies, 1 \(tanker.gdf\), 2 \(barge.gdf\)"):
        read_rao(tmp_path / "run.4")
    with pytest.raises(FileFormatError, match="no body 'hull'"):
        read_rao(tmp_path / "run.4", body="hull")
    assert "--body" in refused_in_one_line(tmp_path, "rao", str(tmp_path / "run.4"))
    assert cli("rao", str(tmp_path / "run.4"), "--body", "2", cwd=tmp_path).returncode == 0


def test_a_two_body_force_set_needs_the_bodys_mass_from_the_scenario(tmp_path):
    """The tanker's .1/.3/.hst written as body 2 of a run of two (modes 7-12, the run's .pot naming it): its .frc
    holds one body, so the mass, and the external matrices WAMIT's .4 was solved with, come from the scenario (the
    .frc's would be another body's); solved with them, surge, heave and pitch are the tanker's (WAMIT's own .4,
    within PEAK_SHARE)."""
    path = copy_set(tmp_path, (".1", ".3", ".hst", ".frc"))
    for suffix, columns in ((".1", (1, 2)), (".3", (2,)), (".hst", (0, 1))):
        file = tmp_path / f"tanker{suffix}"
        rows = [line.split() for line in file.read_text().splitlines()]
        for row in rows:
            for c in columns:
                row[c] = str(int(row[c]) + 6)
        file.write_text("\n".join(" ".join(row) for row in rows) + "\n")
    two_body_pot(tmp_path, "tanker.pot", "tanker2.gdf", (0.0, 0.0, 0.0, 0.0))
    with pytest.raises(FileFormatError, match="its mass is not read from tanker.frc"):
        read_rao(path, body="2")
    frc = read_force_set(TANKER / "tanker.3").frc
    m = frc.mass[0, 0]
    cog = np.array(frc.cog)
    at_cog = np.diag(frc.mass[3:, 3:]) - m * (cog @ cog - cog * cog)
    body = RigidBody(m, tuple(cog), tuple(np.sqrt(at_cog / m)), frc.stiffness, frc.damping)
    read, wamit = read_rao(path, body="2", rigid_body=body), read_rao(TANKER / "tanker.4")
    share = np.abs(read.values - wamit.values).max(axis=(0, 1, 2)) / np.abs(wamit.values).max(axis=(0, 1, 2))
    assert np.all(share[[0, 2, 4]] < PEAK_SHARE), share
    assert any("other bodies held still" in note for note in read.notes)


def test_a_wamit_7_2_report_without_the_density_is_read_with_1025(tmp_path):
    """WAMIT 7.2 prints no water density. The IEA-15 report (7.3, 1025 kg/m^3 printed) with its density cut out
    of the header, solved with the hull's mass, gives the RAOs of the report as printed (same rho), with a note;
    it was refused for the missing line. The density scales the report's forces and added mass against the
    scenario's mass: another would change every RAO."""
    from test_vessel_wamit_out import VOLTURN

    text = lzma.decompress((IEA / "IEA-15-240-RWT-UMaineSemi.out.xz").read_bytes()).decode()
    assert "Water density:" in text and "1025." in text.split("Water density:")[1].split()[0]
    (tmp_path / "printed.out").write_text(text)
    cut = "\n".join(line.split("Water density:")[0].rstrip() for line in text.splitlines())
    (tmp_path / "v72.out").write_text(cut.replace("WAMIT  Version 7.311", "WAMIT  Version 7.2  ") + "\n")
    printed, read = read_rao(tmp_path / "printed.out", rigid_body=VOLTURN), read_rao(tmp_path / "v72.out",
                                                                                    rigid_body=VOLTURN)
    assert read.rho == 1025.0
    np.testing.assert_allclose(read.values, printed.values, rtol=1e-12)
    assert any("prints no water density" in note and "1025" in note for note in read.notes)


def test_a_frc_with_zero_radii_stands_beside_the_scenarios_mass(tmp_path):
    """The tanker's set with a form-1 .frc whose radii of gyration are zero (VCG at the tanker's) and the
    scenario's mass, centre of gravity and radii: the .frc's centre of gravity sets the gravity terms the .hst
    holds, the scenario's mass the rest, so surge, heave and pitch equal WAMIT's .4 (within PEAK_SHARE). Alone,
    that .frc is refused: it gives the body no inertia."""
    path = copy_set(tmp_path, (".1", ".3", ".hst", ".gdf"))
    frc = read_force_set(TANKER / "tanker.3").frc
    (tmp_path / "tanker.frc").write_text(f"tanker, no radii\n1 0 1 1 0 0 0 0 1\n{frc.cog[2]}\n0 0 0\n0 0 0\n0 0 0\n"
                                         "0\n0\n")
    with pytest.raises(FileFormatError, match="positive mass and inertia"):
        read_rao(path)
    m = frc.mass[0, 0]
    cog = np.array(frc.cog)
    at_cog = np.diag(frc.mass[3:, 3:]) - m * (cog @ cog - cog * cog)
    read = read_rao(path, rigid_body=RigidBody(m, tuple(cog), tuple(np.sqrt(at_cog / m)), external_damping=frc.damping))
    wamit = read_rao(TANKER / "tanker.4")
    share = np.abs(read.values - wamit.values).max(axis=(0, 1, 2)) / np.abs(wamit.values).max(axis=(0, 1, 2))
    assert np.all(share[[0, 2, 4]] < PEAK_SHARE), share
