"""WAMIT force sets (.1 + .3 + .hst + .frc) solved for RAOs, the PER column per IPEROUT, and .3 files
told from .4 files.

The independent reference is WAMIT's own ``tanker.4``, shipped with the ``.1/.3/.hst/.frc`` it came
from, and the far-field (Haskind) relation between the exciting forces of the ``.3`` and the damping of
the ``.1``, which no reader code enters.
"""

import math
import shutil
import subprocess
import sys
import os
from pathlib import Path

import numpy as np
import pytest

from conftest import HANG_S, ROOT
from marinesim import formats
from marinesim.errors import FileFormatError
from marinesim.sea.dispersion import k_from_omega
from marinesim.vessel import read_rao
from marinesim.vessel.wamit_forces import read_force_set

TANKER = ROOT / "rao" / "tanker"
SET = (".1", ".3", ".hst", ".frc", ".cfg", ".gdf", ".4")
PEAK_SHARE = 0.01
"""Largest |computed - WAMIT .4| as a share of that DOF's largest |RAO| in the table (0.82 % measured)."""


def copy_set(folder: Path, suffixes=SET, stem: str = "tanker") -> Path:
    """The tanker's files copied to ``folder`` as ``stem.*``; returns the path of the ``.3``."""
    for suffix in suffixes:
        shutil.copyfile(TANKER / f"tanker{suffix}", folder / f"{stem}{suffix}")
    return folder / f"{stem}.3"


def replace_per(path: Path, convert) -> None:
    """Rewrite the first column of ``path`` (positive PER values only) by ``convert(period_s)``."""
    lines = []
    for line in path.read_text().splitlines():
        parts = line.split()
        if parts and float(parts[0]) > 0:
            line = f"{convert(float(parts[0])):.10e} " + " ".join(parts[1:])
        lines.append(line)
    path.write_text("\n".join(lines) + "\n")


def worst_share(computed, reference):
    """Per DOF: max |computed - reference| over headings and frequencies, over the DOF's largest |reference|."""
    return (np.abs(computed.values - reference.values).max(axis=(0, 1, 2))
            / np.abs(reference.values).max(axis=(0, 1, 2)))


def test_tanker_raos_from_forces_equal_wamits_own_4():
    """All 6 modes, 58 periods and 19 headings. A failure means a normalisation (rho, g, ULEN powers),
    the mass, the external damping of the .frc or the phase convention is wrong: each of those moves
    some RAO by far more than 1 % of its peak (the roll damping alone by 280 %).

    The agreement is 0.8 % of each DOF's peak (modulus 0.7 %, phase 2.7 deg where |RAO| > 10 % of the
    peak), not the 7 printed digits: the shipped .4 is not the exact solution of the shipped .1/.3 (the
    force it implies differs from the .3 by 0.1-0.4 %, at random, in every mode; the .1 and .3 agree with
    each other to 0.3 %, test below)."""
    computed, wamit = read_rao(TANKER / "tanker.3"), read_rao(TANKER / "tanker.4")
    assert computed.source_format == "wamit-forces"
    np.testing.assert_allclose(computed.omega, wamit.omega, rtol=1e-12)
    np.testing.assert_allclose(computed.beta, wamit.beta, atol=1e-12)
    assert np.all(worst_share(computed, wamit) < PEAK_SHARE), worst_share(computed, wamit)
    peak = np.abs(wamit.values).max(axis=(0, 1, 2))
    large = np.abs(wamit.values) > 0.1 * peak
    ours, theirs = computed.values[large], wamit.values[large]
    assert np.max(np.abs(np.abs(ours) - np.abs(theirs)) / np.abs(theirs)) < 0.01
    assert np.max(np.degrees(np.abs(np.angle(ours / theirs)))) < 3.0
    assert any("external damping surge 4.1e+05, roll 1.56e+09" in note for note in computed.notes)


def test_the_frc_roll_damping_is_included(tmp_path):
    """Without the .frc's external roll damping the roll peak in beam seas grows several times (wave damping
    alone): the RAOs above equal the .4 only because that damping is in the equation of motion."""
    path = copy_set(tmp_path)
    frc = (tmp_path / "tanker.frc").read_text().replace("1560000000.00", "0.00")
    (tmp_path / "tanker.frc").write_text(frc)
    undamped, wamit = read_rao(path), read_rao(TANKER / "tanker.4")
    beam = list(np.round(np.degrees(wamit.beta))).index(90.0)
    assert np.abs(undamped.values[0, beam, :, 3]).max() > 2.0 * np.abs(wamit.values[0, beam, :, 3]).max()


def test_far_field_damping_equals_the_exciting_forces():
    """Haskind's far-field relation in deep water, B_jj = k w / (4 pi rho g^2) * integral |F_j(beta)|^2 dbeta,
    ties the .1 damping (normalised by rho w L^k) to the .3 forces (by rho g A L^m) with no RAO involved:
    within 0.5 % for every mode between 5.9 and 50 s (0.3 % found; shorter waves vary too fast over the
    10 deg heading steps to integrate, longer ones damp too little for the printed digits), so both files
    are made dimensional the same way. A wrong power of ULEN, of w or a missing rho g would break it by
    orders of magnitude."""
    fs = read_force_set(TANKER / "tanker.3")
    beta = np.radians(fs.headings_deg)
    assert beta[0] == 0.0 and beta[-1] == pytest.approx(math.pi)
    circle = np.concatenate([beta, 2 * math.pi - beta[-2::-1]])
    g, rho = fs.settings.g, fs.rho
    for k in np.flatnonzero((fs.periods > 5.9) & (fs.periods < 50.0)):
        w = fs.omega[k]
        for j in range(6):
            power = np.abs(fs.forces[:, k, j]) ** 2
            integral = np.trapezoid(np.concatenate([power, power[-2::-1]]), circle)
            haskind = w ** 3 / g * integral / (4 * math.pi * rho * g ** 2)
            assert haskind == pytest.approx(fs.damping[k, j, j], rel=0.005), (fs.periods[k], j + 1)


@pytest.mark.parametrize("kind, convert", [
    (2, lambda t: 2 * math.pi / t),
    (3, lambda t: (2 * math.pi / t) ** 2 / 9.80665),
])
def test_iperout_reads_frequencies_and_wavenumbers_not_periods(tmp_path, kind, convert):
    """The same run written with IPEROUT = 2 (rad/s) or 3 (K ULEN): read back it is the same table, at the
    same frequencies. Read as periods (IPEROUT ignored, as before), 0.6 rad/s would become 10 rad/s."""
    path = copy_set(tmp_path)
    for suffix in (".1", ".3", ".4"):
        replace_per(tmp_path / f"tanker{suffix}", convert)
    (tmp_path / "tanker.cfg").write_text(f"IALTFRC=2\nIPERIN=1\nIPEROUT={kind}\n")
    reference = read_rao(TANKER / "tanker.3")
    for read in (read_rao(path), read_rao(path.with_suffix(".4"))):
        np.testing.assert_allclose(read.omega, reference.omega, rtol=1e-9)
        assert any(f"(IPEROUT)" in note for note in read.notes)
    np.testing.assert_allclose(read_rao(path).values, reference.values, rtol=1e-6, atol=1e-12)


def test_iperout_4_is_the_finite_depth_wavenumber(tmp_path):
    """IPEROUT = 4: PER = nu ULEN with nu tanh(nu H) = w^2 / g, H from the .pot (v7 form: HBOT on line 2).
    In 40 m of water the long waves are shorter than in deep water: read as K ULEN they would give the
    wrong frequency by up to tanh(kH)^-1/2."""
    path = copy_set(tmp_path, (".4",))
    replace_per(path.with_suffix(".4"), lambda t: k_from_omega(2 * math.pi / t, 40.0, 9.80665))
    (tmp_path / "tanker.cfg").write_text("IPEROUT=4\n")
    (tmp_path / "tanker.pot").write_text("finite depth\n 40.0\n")
    read = read_rao(path.with_suffix(".4"))
    np.testing.assert_allclose(read.omega, read_rao(TANKER / "tanker.4").omega, rtol=1e-9)
    assert read.depth == 40.0
    (tmp_path / "tanker.pot").unlink()
    with pytest.raises(FileFormatError, match="finite-depth wavenumber.*water depth is needed"):
        read_rao(path.with_suffix(".4"))


def test_header_lines_and_modes_above_6_are_skipped(tmp_path):
    """NUMHDR = 1 puts a header line on every numeric output, and a generalised mode 7 adds lines to each;
    the RAOs of modes 1-6 are those of the plain set, and a note says mode 7 was left out."""
    path = copy_set(tmp_path)
    (tmp_path / "tanker.cfg").write_text("IALTFRC=2\nIPERIO=1\nNUMHDR=1\n")
    for suffix, extra in ((".1", "  0.105000E+01     7     7  1.0E+00  1.0E+00"),
                          (".3", "  0.105000E+01  0.000000E+00     7  1.0E+00  0.0E+00  1.0E+00  0.0E+00"),
                          (".hst", "     7     7   1.0E+00")):
        file = tmp_path / f"tanker{suffix}"
        lines = file.read_text().splitlines()
        file.write_text("\n".join([" WAMIT  Version 7.4   header line"] + lines[:40] + [extra] + lines[40:]) + "\n")
    read, plain = read_rao(path), read_rao(TANKER / "tanker.3")
    np.testing.assert_array_equal(read.values, plain.values)
    assert any("modes 7" in note and "ignored" in note for note in read.notes)
    assert any("header line 1" in note for note in read.notes)


def test_a_partial_heading_set_makes_a_table_of_what_it_covers(tmp_path):
    """A .3 computed for 0-90 deg only cannot give a sea from the other side: the table covers 0..90 deg (and the
    margin), is not wrapped round the circle, and within it equals the RAOs solved from the whole set."""
    (tmp_path / "whole").mkdir()
    whole = read_rao(copy_set(tmp_path / "whole"))
    path = copy_set(tmp_path)
    three = tmp_path / "tanker.3"
    three.write_text("\n".join(line for line in three.read_text().splitlines()
                               if float(line.split()[1]) <= 90.0) + "\n")
    table = read_rao(path)
    assert table.covered_text() == "345..105 deg (tabulated 0..90)"
    beta = np.radians(np.full(table.omega.size, 45.0))
    np.testing.assert_allclose(table(table.omega, beta), whole(table.omega, beta), rtol=1e-12, atol=1e-12)


def test_alternative_form_1_mass_from_the_displaced_volume(tmp_path):
    """IALTFRC = 1: mass rho V (V of the .gdf), CG above the centre of buoyancy at VCG, inertia
    rho V r |r| from the radii of gyration. With the tanker's radii (its form-2 matrix), heave and pitch
    (which the external damping of form 2 barely touches) equal WAMIT's .4 as closely as form 2 does; roll,
    without the form-2 roll damping, peaks higher (and surge at 100-200 s differs by 10 %: form 2's surge
    damping of 4.1e5 N s/m is missing too)."""
    path = copy_set(tmp_path, (".1", ".3", ".hst", ".gdf"))
    frc2 = read_force_set(TANKER / "tanker.3").frc
    radii = np.sqrt(np.diag(frc2.mass)[3:] / frc2.mass[0, 0])
    (tmp_path / "tanker.frc").write_text(
        "tanker, alternative form 1\n1 0 1 1 0 0 0 0 1\n2.5\n"
        + "\n".join(" ".join(f"{radii[r]:.6f}" if r == c else "0.0" for c in range(3)) for r in range(3))
        + "\n0\n0\n")
    read, wamit = read_rao(path), read_rao(TANKER / "tanker.4")
    share = worst_share(read, wamit)
    assert np.all(share[[2, 4]] < PEAK_SHARE), share
    assert np.abs(read.values[..., 3]).max() > 2.0 * np.abs(wamit.values[..., 3]).max()
    assert any("IALTFRC 1" in note and "displaced volume" in note for note in read.notes)


def test_a_3_file_is_never_read_as_motions(tmp_path):
    """By name (.3), by content under an unknown extension, and renamed .4: a .3 read as motions gave heave
    std 1.42 m in an Hs 3 m sea. Its forces (pitch 1.5e3 rho g A at 1 s) exceed any motion RAO."""
    assert formats.detect(TANKER / "tanker.3", "rao").name == "wamit-forces"
    unknown = tmp_path / "forces.dat"
    shutil.copyfile(TANKER / "tanker.3", unknown)
    assert formats.detect(unknown, "rao").name == "wamit-forces"
    motions = tmp_path / "motions.dat"
    shutil.copyfile(TANKER / "tanker.4", motions)
    assert formats.detect(motions, "rao").name == "wamit"
    renamed = tmp_path / "renamed.4"
    shutil.copyfile(TANKER / "tanker.3", renamed)
    with pytest.raises(FileFormatError, match="exciting forces, not motions: this is a WAMIT .3 file"):
        read_rao(renamed)


BAD = {
    "no .hst": (".hst", None, None, "missing: tanker.hst"),
    ".1 short line": (".1", 40, lambda line: " ".join(line.split()[:4]), "expected 5 columns"),
    ".1 text": (".1", 40, lambda line: " ".join(line.split()[:3] + ["1.4x"] + line.split()[4:]), "expected Abar"),
    ".hst NaN": (".hst", 15, lambda line: line.replace("1.022150E+04", "nan"), "finite"),
    ".3 period not in .1": (".3", None, lambda text: text.replace("0.105000E+01", "0.107000E+01"),
                            "PER 1.07 has no added mass and damping in tanker.1"),
    ".frc no mass": (".frc", None, lambda text: "\n".join(text.splitlines()[:4] + ["0"] + text.splitlines()[11:]),
                     "IMASS = 0: the .frc gives no mass matrix"),
    ".frc short row": (".frc", 8, lambda line: " ".join(line.split()[:5]), "expected 6 values"),
    ".frc bad rho": (".frc", 3, lambda line: "1.025", "RHO must be in 500..2000"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_force_sets_are_refused_naming_file_and_line(tmp_path, case):
    """Each broken file gives one FileFormatError naming that file (and the line, where there is one),
    never a traceback or a table."""
    suffix, line, edit, message = BAD[case]
    path = copy_set(tmp_path)
    broken = tmp_path / f"tanker{suffix}"
    if edit is None:
        broken.unlink()
    elif line is None:
        broken.write_text(edit(broken.read_text()))
    else:
        lines = broken.read_text().splitlines()
        lines[line - 1] = edit(lines[line - 1])
        broken.write_text("\n".join(lines) + "\n")
    with pytest.raises(FileFormatError, match=message) as error:
        read_rao(path)
    assert error.value.path in (broken, path)
    if line is not None:
        assert error.value.line == line


def test_command_line_refuses_a_broken_set_in_one_line(tmp_path):
    """The command line's side: exit 2 and one line naming the file, no traceback."""
    path = copy_set(tmp_path)
    (tmp_path / "tanker.hst").write_text("3 3 oops\n")
    result = subprocess.run([sys.executable, "-m", "marinesim", "rao", str(path)], capture_output=True, text=True,
                            env=dict(os.environ, PYTHONPATH=str(ROOT)), timeout=HANG_S)
    stderr = result.stderr.strip().splitlines()
    assert result.returncode == 2 and "Traceback" not in result.stderr and len(stderr) == 1, result.stderr
    assert str(tmp_path / "tanker.hst") in stderr[0]


def test_the_scenarios_mass_and_external_damping_stand_in_for_the_frc(tmp_path):
    """The tanker's .1/.3/.hst without its .frc, with the mass, centre of gravity and radii of gyration of the
    .frc's matrix and its external damping given as a scenario gives them: surge, heave and
    pitch equal WAMIT's own .4 as the .frc's do (within PEAK_SHARE), and without the damping the beam-sea roll
    peak grows as above. Sway, roll and yaw differ (1.7, 1.1 and 9 % of their peaks) because the tanker's .frc
    leaves out couplings a rigid body has (sway-yaw m x_g, the product m x_g z_g). A failure means the
    parallel-axis mass matrix, the rho assumed without a .frc, or the external matrix is wrong."""
    from marinesim.vessel.body import RigidBody

    frc = read_force_set(TANKER / "tanker.3").frc
    m = frc.mass[0, 0]
    cog = (-frc.mass[4, 2] / m, frc.mass[3, 2] / m, frc.mass[4, 0] / m)  # m x_g, m y_g, m z_g as WAMIT lays them out
    assert cog == pytest.approx(frc.cog)
    c = np.array(cog)
    at_cog = np.diag(frc.mass[3:, 3:]) - m * (c @ c - c * c)  # the .frc's moments of inertia moved to the CoG
    body = RigidBody(m, cog, tuple(np.sqrt(at_cog / m)), external_damping=frc.damping)
    ours = body.mass_matrix()  # a rigid body's: it also has the sway-yaw coupling m x_g and the product m x_g z_g,
    np.testing.assert_allclose(np.diag(ours), np.diag(frc.mass), rtol=1e-9)  # which the tanker's .frc leaves out
    path = copy_set(tmp_path, (".1", ".3", ".hst"))
    computed, wamit = read_rao(path, rigid_body=body), read_rao(TANKER / "tanker.4")
    share = worst_share(computed, wamit)
    assert np.all(share[[0, 2, 4]] < PEAK_SHARE), share
    assert any("from the scenario: mass" in note for note in computed.notes)
    undamped = read_rao(path, rigid_body=RigidBody(m, cog, body.radii_of_gyration_m))
    beam = list(np.round(np.degrees(wamit.beta))).index(90.0)
    assert np.abs(undamped.values[0, beam, :, 3]).max() > 2.0 * np.abs(wamit.values[0, beam, :, 3]).max()
    with pytest.raises(FileFormatError, match="missing: tanker.frc"):
        read_rao(path)


def test_a_scenario_gives_the_mass_and_is_refused_where_the_file_has_its_own_raos(tmp_path):
    """[vessel] mass_kg, cog_m, radii_of_gyration_m and external_damping on the tanker's force set without a
    .frc: the export runs. The same keys on the .4 (WAMIT's RAOs, nothing solved here) or a mass without its
    centre of gravity end in one line naming the key, exit 2."""
    from conftest import VESSEL_SCENARIO, cli, write

    copy_set(tmp_path, (".1", ".3", ".hst", ".gdf"))
    damping = "[" + ", ".join("[" + ", ".join("1.56e9" if i == j == 3 else "0" for j in range(6)) + "]"
                              for i in range(6)) + "]"
    keys = (f"mass_kg = 9.462e7\ncog_m = [3.93, 0.0, 2.5]\nradii_of_gyration_m = [17.02, 63.8, 65.3]\n"
            f"external_damping = {damping}\n")
    base = VESSEL_SCENARIO.replace(f'hull = "{ROOT / "hulls" / "tanker.gdf"}"\n', "").replace(
        "speed_kn = 6.0", "speed_kn = 0.0").replace("duration_s = 120.0", "duration_s = 10.0")
    forces = write(tmp_path, base.replace(str(ROOT / "rao" / "tanker" / "tanker.4"), str(tmp_path / "tanker.3"))
                   .replace("[vessel]\n", "[vessel]\n" + keys), "forces.toml")
    result = cli("export", str(forces), "--out", "m.csv", "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    for text, expected in ((base.replace("[vessel]\n", "[vessel]\n" + keys), "apply to RAOs solved here"),
                           (base.replace("[vessel]\n", "[vessel]\nmass_kg = 9.462e7\n"), "vessel.mass_kg")):
        refused = cli("export", str(write(tmp_path, text, "bad.toml")), "--out", "b.csv", "--quiet", cwd=tmp_path)
        lines = refused.stderr.strip().splitlines()
        assert refused.returncode == 2 and len(lines) == 1 and expected in lines[0], refused.stderr
