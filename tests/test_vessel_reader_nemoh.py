"""The NEMOH reader on a real NEMOH v3.0.2 project (the OC3-Hywind spar from WEC-Sim, tests/data/nemoh/README.md):
RAOs solved from NEMOH's forces and coefficients, its exp(-i w t) convention converted once, checked against
physics; ``Motion/RAO.dat`` read in the layout NEMOH's postprocessor writes."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from marinesim.errors import FileFormatError
from marinesim.sea.dispersion import k_from_omega
from marinesim.vessel.nemoh import nemoh_to_internal, read_coefficient_dat, read_excitation, read_nemoh, read_nemoh_raos, sniff
from marinesim.vessel.rao import long_wave_limit

SPAR = Path(__file__).parent / "data" / "nemoh" / "oc3_hywind"
SURGE, SWAY, HEAVE, ROLL, PITCH, YAW = range(6)


@pytest.fixture(scope="module")
def spar():
    return read_nemoh_raos(SPAR)


@pytest.fixture
def project(tmp_path):
    copy = tmp_path / "oc3"
    shutil.copytree(SPAR, copy)
    return copy


def test_settings_and_reference_point(spar):
    """rho, g and infinite depth (DEPTH 0) from Nemoh.cal; the RAOs refer to the rotation centre, the CoG 78 m down."""
    assert (spar.rho, spar.g, spar.depth) == (1025.0, 9.81, math.inf)
    assert spar.reference_point == (0.0, 0.0, -78.0)
    assert list(spar.headings_deg) == [0.0] and spar.omega.size == 128


def test_long_wave_limits(spar):
    """At 0.025 rad/s (a 99 km wave) the free spar follows the wave: heave 1, surge -i, pitch +i k (lead, rad/m).
    Left in NEMOH's exp(-i w t) convention surge would be +i and pitch -i k; the solve with a wrong sign of the
    damping term or a transposed heading would break them too."""
    expected = long_wave_limit(spar.omega[:1], np.zeros(1), spar.g)[0]
    got = spar.values[0, 0]
    assert abs(got[HEAVE] - 1.0) < 0.01
    assert abs(got[SURGE] - expected[SURGE]) < 0.01
    k = k_from_omega(spar.omega[:1], spar.depth, spar.g)[0]
    assert abs(got[PITCH] - expected[PITCH]) < 0.1 * k and abs(got[PITCH].imag / k - 1.0) < 0.03
    assert abs(got[SWAY]) < 1e-3 and abs(got[ROLL]) < 0.01 * k  # waves along x move nothing sideways


def test_heave_force_tends_to_hydrostatic_stiffness():
    """The heave exciting force of a long wave is the hydrostatic force C33 a, in phase with the crest: an
    independent check of the force file (modulus, phase in radians) against the stiffness file."""
    omega, _, forces = read_excitation(SPAR / "results" / "ExcitationForce.tec")
    c33 = float((SPAR / "Mechanics" / "Kh.dat").read_text().split()[14])
    f3 = nemoh_to_internal(forces[0, 0, HEAVE])
    assert abs(f3 / c33 - 1.0) < 0.02


def test_heave_resonance_where_mass_and_stiffness_put_it(spar):
    """The heave response turns from in phase (0 deg) to in antiphase (180 deg) with the wave between the two
    tabulated frequencies that bracket the undamped natural frequency sqrt(C33 / (M + A33)), computed here from
    the stiffness, mass and added-mass files, while the heave force keeps its phase there."""
    _, _, forces = read_excitation(SPAR / "results" / "ExcitationForce.tec")
    _, added = read_coefficient_dat(SPAR / "results" / "CM.dat")
    c33 = float((SPAR / "Mechanics" / "Kh.dat").read_text().split()[14])
    m33 = float((SPAR / "Mechanics" / "Inertia.dat").read_text().split()[14])
    response = spar.values[0, :, HEAVE] / nemoh_to_internal(forces[0, :, HEAVE])
    flip = int(np.flatnonzero(np.sign(response.real[1:]) != np.sign(response.real[:-1]))[0])
    natural = [math.sqrt(c33 / (m33 + added[i, 2, 2])) for i in (flip, flip + 1)]
    assert spar.omega[flip] < natural[0] and natural[1] < spar.omega[flip + 1]
    assert abs(math.degrees(np.angle(spar.values[0, flip, HEAVE]))) < 5.0
    assert abs(math.degrees(np.angle(spar.values[0, flip + 1, HEAVE]))) > 175.0


def test_rao_dat_is_read_as_nemoh_writes_it(spar, project):
    """A Motion/RAO.dat in the layout of NEMOH v3's postprocessor (SAVE_RAO: exp(-i w t) values, |rotations| in
    deg/m, phases atan2 in degrees, freq F10.3, values E14.7) is preferred to the coefficients and gives the same
    RAOs within the printed precision."""
    nemoh = np.conj(spar.values[0])  # NEMOH's convention
    amplitude = np.abs(nemoh) * np.where(np.arange(6) >= 3, 180.0 / math.pi, 1.0)
    phase = np.degrees(np.angle(nemoh))
    (project / "Motion").mkdir()
    lines = ['VARIABLES="w (rad/s)" "|X| (m/m)" "|Y| (m/m)" "|Z| (m/m)" "|phi| (deg)" "|theta| (deg)" "|psi| (deg)" '
             '"ang(x) (deg)" "ang(y) (deg)" "ang(z) (deg)" "ang(phi) (deg)" "ang(theta) (deg)" "ang(psi) (deg)"',
             f'ZONE T="RAO - beta=     0.000 (deg)", I= {spar.omega.size:4d}, F=POINT']
    for i, w in enumerate(spar.omega):
        lines.append(f"{w:10.3f} " + " ".join(f"{v:14.7E}" for v in (*amplitude[i], *phase[i])))
    (project / "Motion" / "RAO.dat").write_text("\n".join(lines) + "\n")
    read = read_nemoh_raos(project / "Nemoh.cal")
    assert read.source.endswith("RAO.dat")
    assert np.allclose(read.omega, spar.omega, atol=5e-4)
    assert np.allclose(read.values, spar.values, rtol=1e-5, atol=1e-9)


def test_mass_from_hull_inertia_when_no_mass_matrix(spar, project):
    """Without Mechanics/Inertia.dat the mass comes from mesh/Hydrostatics.dat (3.288e7 kg at G) and the hull
    inertia about G: here G is the rotation centre, so the RAOs are those of the 6 x 6 matrix."""
    (project / "Mechanics" / "Inertia.dat").unlink()
    fallback = read_nemoh_raos(project)
    assert np.allclose(fallback.values, spar.values, rtol=1e-5, atol=1e-9)
    assert "Inertia_hull.dat" in fallback.notes[0]


def test_no_mass_is_refused(project):
    (project / "Mechanics" / "Inertia.dat").unlink()
    (project / "Mesh" / "Inertia_hull.dat").unlink()
    with pytest.raises(FileFormatError, match="no mass for the RAOs"):
        read_nemoh_raos(project)


def test_the_single_heading_makes_a_partial_table(spar):
    """NEMOH ran the spar at 0 deg only: the table covers 345..15 deg and answers with those RAOs."""
    table = read_nemoh(SPAR / "results" / "ExcitationForce.tec")
    assert table.covered_text() == "345..15 deg (tabulated 0)"
    np.testing.assert_allclose(table(spar.omega, np.zeros(spar.omega.size)), spar.values[0])


def test_sniff():
    assert sniff((SPAR / "Nemoh.cal").read_bytes())
    assert not sniff(b"0.1 0 1 1.0 0 1.0 0\n")


def test_malformed_files_name_the_line(project, tmp_path):
    """A damaged coefficient names its file and line; a truncated force file is refused; a stray file is not a
    NEMOH project."""
    ca = project / "results" / "CA.dat"
    lines = ca.read_text().splitlines()
    lines[5] = lines[5].replace("E", "Q", 1)
    ca.write_text("\n".join(lines) + "\n")
    with pytest.raises(FileFormatError, match="CA.dat, line 6"):
        read_nemoh_raos(project)
    shutil.copy(SPAR / "results" / "CA.dat", ca)
    force = project / "results" / "ExcitationForce.tec"
    force.write_text("\n".join(force.read_text().splitlines()[:20]) + "\n")
    with pytest.raises(FileFormatError, match="frequencies differ"):
        read_nemoh_raos(project)
    stray = tmp_path / "alone.dat"
    stray.write_text("1 2 3\n")
    with pytest.raises(FileFormatError, match="no Nemoh.cal"):
        read_nemoh_raos(stray)


def test_the_scenarios_mass_replaces_nemohs(spar, project):
    """The spar's own mass given by a scenario (3.288e7 kg at its centre of gravity 78 m down, in the body frame
    whose z = 0 is the waterline; NEMOH rotates about that point) gives NEMOH's RAOs: a centre of gravity taken
    about the wrong point would couple surge and pitch. 10 % more mass changes the heave (a mass left unused
    would not)."""
    from marinesim.vessel.body import RigidBody

    m = 0.3288402e8
    radii = (math.sqrt(0.4956638e11 / m), math.sqrt(0.4956640e11 / m), math.sqrt(0.2766477e10 / m))
    same = read_nemoh(project, rigid_body=RigidBody(m, (0.0, 0.0, -78.0), radii))
    np.testing.assert_allclose(same.values[0, :, :, :], read_nemoh(project).values[0], rtol=1e-6,
                               atol=1e-9 * np.abs(spar.values).max())
    assert any("the scenario's mass" in note for note in same.notes)
    heavier = read_nemoh(project, rigid_body=RigidBody(1.1 * m, (0.0, 0.0, -78.0), radii))
    assert not np.allclose(heavier.values[..., HEAVE], same.values[..., HEAVE], rtol=1e-3)
