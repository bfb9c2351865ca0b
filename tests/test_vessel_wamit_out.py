"""WAMIT's report (marinesim/vessel/wamit_out.py) against WAMIT's numeric files of the same runs: the MSS tanker
(WAMIT 6.3, motions in the report) and the IEA-15 MW VolturnUS-S (WAMIT 7.3, 200 m depth, no mass and no
gravity in the run: RAOs only with the scenario's mass). The report prints phases in whole degrees, so a value
read from it can differ from the numeric file's by sin(0.5 deg) = 0.87 % of its modulus, and no more."""

from __future__ import annotations

import lzma
import math
import shutil

import numpy as np
import pytest

from conftest import ROOT
from marinesim.errors import FileFormatError
from marinesim.vessel.body import RigidBody
from marinesim.vessel.read import detect_format, read_rao

TANKER = ROOT / "rao" / "tanker"
IEA = ROOT / "tests" / "data" / "iea15"
HALF_DEGREE = math.sin(math.radians(0.5))
VOLTURN = RigidBody(mass_kg=1.7838e7, cog_m=(0.0, 0.0, -14.94),
                    radii_of_gyration_m=(math.sqrt(1.2632e10 / 1.7838e7),) * 2 + (math.sqrt(2.3667e10 / 1.7838e7),))
"""The VolturnUS-S hull's mass, centre of gravity and inertia (IEA-15-240-RWT reference, NREL/TP-5000-76773)."""


@pytest.fixture
def tanker_out(tmp_path):
    path = tmp_path / "tanker.out"
    path.write_bytes(lzma.decompress((ROOT / "tests" / "data" / "mss" / "tanker.out.xz").read_bytes()))
    return path


@pytest.fixture
def iea(tmp_path):
    """The IEA-15 report and its force set side by side, as WAMIT wrote them (tests/data/iea15)."""
    for name in ("IEA-15-240-RWT-UMaineSemi.out", "IEA-15-240-RWT-UMaineSemi.3"):
        (tmp_path / name).write_bytes(lzma.decompress((IEA / f"{name}.xz").read_bytes()))
    for suffix in (".1", ".hst", ".frc"):
        shutil.copy(IEA / f"IEA-15-240-RWT-UMaineSemi{suffix}", tmp_path)
    return tmp_path / "IEA-15-240-RWT-UMaineSemi.out"


def test_the_tanker_report_gives_the_rao_of_its_numeric_file(tanker_out):
    """Every RAO of the report equals WAMIT's .4 of the same run within the report's printed precision (the
    phase's half degree, the modulus's six digits); a failure means a mode, heading or period matched wrongly,
    a convention (phase sign, rotations per ULEN) converted twice, or a drift-force table read as motions."""
    report, numeric = read_rao(tanker_out), read_rao(TANKER / "tanker.4")
    assert detect_format(tanker_out) == "wamit-out"
    picked = np.isin(np.round(2 * np.pi / numeric.omega, 2), [7.86, 10.44, 13.91])
    np.testing.assert_allclose(report.omega, numeric.omega[picked], rtol=1e-6)
    np.testing.assert_allclose(report.beta, numeric.beta)
    expected = numeric.values[:, :, picked]
    # values of 1e-11 (yaw in head seas: zero but for the solver's rounding) carry no phase worth comparing
    bound = np.abs(expected) * (HALF_DEGREE + 1e-5) + 1e-8 * np.abs(expected).max(axis=(0, 1, 2))
    assert (np.abs(report.values - expected) <= bound).all()
    assert np.abs(expected).max(axis=(0, 1, 2))[2] > 0.5  # heave near 1 m/m: the comparison is of real motions


def test_the_tanker_report_solved_with_the_scenario_mass_equals_the_force_set(tanker_out, tmp_path):
    """With the scenario's mass, the RAOs are solved from the report's forces. They equal the RAOs solved from
    the .1/.3/.hst of the same run with the same mass and external damping to within what the report's
    whole-degree force phases allow: 0.87 % of each force, amplified near the roll resonance (13-14 s here) to
    under 2 % of each mode's peak."""
    for suffix in (".1", ".3", ".hst", ".gdf", ".cfg", ".frc"):
        shutil.copy(TANKER / f"tanker{suffix}", tmp_path)
    damping = np.zeros((6, 6))
    damping[0, 0], damping[3, 3] = 4.1e5, 1.56e9  # the .frc's external damping, given by the scenario here
    body = RigidBody(9.462021e7, (3.93, 0.0, 2.5), (16.84, 63.79, 66.30), external_damping=damping)
    (tmp_path / "tanker.frc").unlink()  # the force set then takes everything from the scenario, as the report does
    report, forces = read_rao(tanker_out, rigid_body=body), read_rao(tmp_path / "tanker.3", rigid_body=body)
    picked = np.isin(np.round(2 * np.pi / forces.omega, 2), [7.86, 10.44, 13.91])
    expected = forces.values[:, :, picked]
    peak = np.abs(expected).max(axis=(0, 1, 2))
    assert (np.abs(report.values - expected).max(axis=(0, 1, 2)) <= 0.02 * peak).all()
    assert any("solved from the report" in note for note in report.notes)


def test_the_iea15_report_without_motions_needs_the_mass_and_then_equals_its_force_set(iea):
    """The VolturnUS-S run has no mass (IMASS = 0) and its centre of gravity at the origin, so its restoring
    holds no gravity: the report alone is refused in one line naming the scenario keys; with the hull's mass the
    report's RAOs equal those of the run's .1/.3/.hst/.frc, both with the weight's restoring at the scenario's
    centre of gravity (the report's figures are printed to 5-7 digits and whole degrees: within 2 % of each
    mode's peak)."""
    with pytest.raises(FileFormatError, match="mass_kg, cog_m and radii_of_gyration_m"):
        read_rao(iea)
    report = read_rao(iea, rigid_body=VOLTURN)
    forces = read_rao(iea.with_suffix(".3"), rigid_body=VOLTURN)
    assert report.depth == 200.0  # the report says so; the force set has no .pot and is read as deep water
    np.testing.assert_allclose(report.omega, [0.4, 0.6, 1.0], rtol=1e-6)
    assert report.beta.size == 36  # -180 and 180 deg are the same waves, kept once
    peak = np.abs(forces.values).max(axis=(0, 1, 2))
    assert (np.abs(report.values - forces.values).max(axis=(0, 1, 2)) <= 0.02 * peak).all()


def test_the_weight_restoring_is_the_scenario_mass_at_its_centre_of_gravity(iea):
    """The run's restoring holds no gravity; the scenario's mass 14.94 m below the origin adds
    -m g z_g = +2.61e9 N m/rad to roll and pitch. The same terms given as an external stiffness to the force
    set read without its .frc (whose gravity terms are then kept as WAMIT's: none) give the same RAOs; a sign
    error or a missing term would show as a roll and pitch resonance in the wrong place."""
    stiffness = np.zeros((6, 6))
    stiffness[3, 3] = stiffness[4, 4] = -VOLTURN.mass_kg * 9.80665 * VOLTURN.cog_m[2]
    iea.with_suffix(".frc").unlink()
    by_hand = RigidBody(VOLTURN.mass_kg, VOLTURN.cog_m, VOLTURN.radii_of_gyration_m, external_stiffness=stiffness)
    forces = read_rao(iea.with_suffix(".3"), rigid_body=by_hand)
    assert any("kept as WAMIT computed them" in note for note in forces.notes)
    report = read_rao(iea, rigid_body=VOLTURN)
    peak = np.abs(forces.values).max(axis=(0, 1, 2))
    assert (np.abs(report.values - forces.values).max(axis=(0, 1, 2)) <= 0.02 * peak).all()
    without = read_rao(iea.with_suffix(".3"), rigid_body=VOLTURN)
    assert np.abs(without.values - forces.values)[..., 3:5].max() > 0.1 * peak[3:5].max()


@pytest.mark.parametrize("edit,words", [
    (lambda t: t.replace("Gravity:", "Grav:"), "lacks Gravity"),
    (lambda t: t.replace("Wave period (sec) =  7.860000E+00", "Wave period (sec) =  -7.86"), "wave period > 0"),
    (lambda t: t.replace("RESPONSE AMPLITUDE OPERATORS", "RESPONSE AMPLITUDE OPERATORS\n 1 0.5 3", 1),
     "a row before its 'Wave Heading"),
    (lambda t: t.replace("Mod[RAO(I)]    Pha[RAO(I)]\n\n     1 ", "Mod[RAO(I)]    Pha[RAO(I)]\n\n     1 7 ", 1),
     "expected I Mod Pha, got 4 values"),
    (lambda t: t.split("Wave period (sec)")[0], "no 'Wave period (sec) =' blocks"),
])
def test_a_flawed_report_is_refused_naming_the_line(tanker_out, edit, words):
    """A header value missing, a negative period, a row of motions before its heading or with four values, no
    period at all."""
    tanker_out.write_text(edit(tanker_out.read_text()))
    with pytest.raises(FileFormatError, match=words.replace("(", r"\(").replace(")", r"\)")) as error:
        read_rao(tanker_out)
    assert str(tanker_out) in str(error.value)
    assert ", line " in str(error.value) or "lacks" in words or "blocks" in words
