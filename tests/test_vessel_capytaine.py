"""Capytaine: a box barge solved here with Capytaine, its NetCDF read through marinesim.

References: the free-floating long-wave limits (heave -> 1, pitch -> k cos beta, roll ->
k sin beta) and Capytaine's own ``post_pro.rao`` (in its exp(-i w t) convention: conjugated).
"""

import math

import capytaine
import numpy as np
import pytest
import xarray
from hypothesis import HealthCheck, given, settings, strategies as st

from marinesim.errors import FileFormatError, MarinesimError
from marinesim.vessel import read_rao

pytestmark = pytest.mark.slow

LENGTH, BEAM, DRAFT = 40.0, 10.0, 3.0
OMEGA = np.array([0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0, 1.1, 1.2, 1.4, 1.7, 2.0])
DIRECTIONS = np.linspace(0.0, math.pi, 5)


@pytest.fixture(scope="module")
def barge(tmp_path_factory):
    """(dataset, path of its NetCDF as Capytaine writes it) for a 40 x 10 m barge, draft 3 m."""
    mesh = capytaine.mesh_parallelepiped(size=(LENGTH, BEAM, DRAFT + 1.0), resolution=(12, 4, 3),
                                         center=(0.0, 0.0, (1.0 - DRAFT) / 2))
    body = capytaine.FloatingBody(mesh=mesh, dofs=capytaine.rigid_body_dofs(rotation_center=(0, 0, 0)),
                                  center_of_mass=(0.0, 0.0, -0.5)).immersed_part()
    body.inertia_matrix = body.compute_rigid_body_inertia(rho=1025.0)  # the same rho as the BEM problems:
    body.hydrostatic_stiffness = body.compute_hydrostatic_stiffness(rho=1025.0)  # else heave -> 1.025
    problems = xarray.Dataset(coords={"omega": OMEGA, "wave_direction": DIRECTIONS,
                                      "radiating_dof": list(body.dofs), "water_depth": [np.inf], "rho": [1025.0]})
    dataset = capytaine.BEMSolver().fill_dataset(problems, body)
    path = tmp_path_factory.mktemp("capytaine") / "barge.nc"
    capytaine.export_dataset(path, dataset)
    return dataset, path


def test_long_wave_limits_of_the_solved_barge(barge):
    _, path = barge
    table = read_rao(path)
    w = np.array([OMEGA[0]])
    k = w[0] ** 2 / table.g
    for beta in (0.0, math.pi / 4, math.pi / 2, 3 * math.pi / 4, math.pi, 1.5 * math.pi):
        h = table(w, np.array([beta]))[0]
        assert h[2] == pytest.approx(1.0, abs=0.01)                          # heave -> 1
        assert abs(h[4]) == pytest.approx(k * abs(math.cos(beta)), abs=0.03 * k)  # pitch -> k |cos b|
        if abs(math.cos(beta)) > 0.5:  # pitch = i k cos(beta) in marinesim's exp(+i w t)
            assert math.degrees(np.angle(h[4] * np.sign(math.cos(beta)))) == pytest.approx(90.0, abs=3.0)
        assert abs(h[3]) == pytest.approx(k * abs(math.sin(beta)), abs=0.1 * k)   # roll -> k |sin b|


def test_raos_equal_capytaines_own_conjugated(barge):
    dataset, path = barge
    table = read_rao(path)
    theirs = capytaine.post_pro.rao(dataset).transpose("omega", "wave_direction", "radiating_dof").values
    for b, beta in enumerate(DIRECTIONS):
        ours = table(OMEGA, np.full(OMEGA.size, beta))
        np.testing.assert_allclose(ours, np.conj(theirs[:, b, :]), rtol=1e-6, atol=1e-9)


def test_roll_damping_in_percent_of_critical(barge):
    # the extra damping is 2 zeta sqrt(K44 (M44 + A44(w_n))); passing the same matrix to
    # Capytaine's rao reproduces ours, and 10 % of critical cuts the beam-sea roll peak
    dataset, path = barge
    undamped, damped = read_rao(path), read_rao(path, roll_damping=0.10)
    note = next(n for n in damped.notes if "roll damping" in n)
    b44 = float(note.split("(")[1].split()[0])
    k44 = float(dataset["hydrostatic_stiffness"].sel(influenced_dof="Roll", radiating_dof="Roll"))
    m44 = float(dataset["inertia_matrix"].sel(influenced_dof="Roll", radiating_dof="Roll"))
    a44 = dataset["added_mass"].sel(influenced_dof="Roll", radiating_dof="Roll").values
    natural = math.sqrt(k44 / (m44 + np.interp(math.sqrt(k44 / m44), OMEGA, a44)))
    assert b44 == pytest.approx(0.2 * math.sqrt(k44 * (m44 + np.interp(natural, OMEGA, a44))), rel=0.02)
    dissipation = xarray.zeros_like(dataset["hydrostatic_stiffness"])
    dissipation.loc[{"influenced_dof": "Roll", "radiating_dof": "Roll"}] = b44
    theirs = capytaine.post_pro.rao(dataset, dissipation=dissipation)
    theirs = theirs.transpose("omega", "wave_direction", "radiating_dof").values
    ours = damped(OMEGA, np.full(OMEGA.size, math.pi / 2))
    np.testing.assert_allclose(ours, np.conj(theirs[:, 2, :]), rtol=1e-4, atol=1e-9)
    fine = np.linspace(OMEGA[0], OMEGA[-1], 2000)
    beam = np.full(fine.size, math.pi / 2)
    assert np.abs(damped(fine, beam)[:, 3]).max() < 0.8 * np.abs(undamped(fine, beam)[:, 3]).max()


def test_dataset_without_coefficients_is_refused(barge, tmp_path):
    dataset, _ = barge
    path = tmp_path / "partial.nc"
    capytaine.export_dataset(path, dataset.drop_vars(["added_mass", "inertia_matrix"]))
    with pytest.raises(FileFormatError, match="missing: added_mass, inertia_matrix"):
        read_rao(path)
    junk = tmp_path / "junk.nc"
    junk.write_bytes(b"CDF\x01 not really")
    with pytest.raises(FileFormatError, match="not a readable NetCDF dataset"):
        read_rao(junk)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(cut=st.floats(0.0, 1.0), flips=st.lists(st.tuples(st.floats(0.0, 1.0), st.integers(0, 255)), max_size=6))
def test_fuzz_capytaine_netcdf(barge, tmp_path_factory, cut, flips):
    # truncated or corrupted NetCDF: the project's error or a table, nothing else
    data = bytearray(barge[1].read_bytes())
    for where, value in flips:
        data[int(where * (len(data) - 1))] = value
    path = tmp_path_factory.mktemp("fuzz") / "barge.nc"
    path.write_bytes(bytes(data[: max(4, int(cut * len(data)))]))
    try:
        read_rao(path)
    except MarinesimError:
        pass


@pytest.mark.parametrize("depth, omega, dropped", [
    (np.inf, [0.0, 0.3, 0.7, 1.0, np.inf], "omega 0 and inf (added-mass limits"),
    (10.0, [0.01, 0.3, 0.7, 1.0], "0.01 rad/s (non-finite coefficients"),
])
def test_frequencies_capytaine_leaves_without_waves_or_values_are_dropped_with_a_note(tmp_path, depth, omega, dropped):
    """Capytaine solves omega = 0 and infinity (added mass only: its excitation is NaN there) and leaves NaN
    where its finite-depth Green function fails (kh < 0.1). Such datasets, as users have them, used to be refused
    whole; the usable frequencies now give the RAOs the same dataset gives without the others, and a note says
    which were dropped."""
    mesh = capytaine.mesh_parallelepiped(size=(LENGTH, BEAM, DRAFT + 1.0), resolution=(12, 4, 3),
                                         center=(0.0, 0.0, (1.0 - DRAFT) / 2))
    body = capytaine.FloatingBody(mesh=mesh, dofs=capytaine.rigid_body_dofs(rotation_center=(0, 0, 0)),
                                  center_of_mass=(0.0, 0.0, -0.5)).immersed_part()
    body.inertia_matrix = body.compute_rigid_body_inertia(rho=1025.0)
    body.hydrostatic_stiffness = body.compute_hydrostatic_stiffness(rho=1025.0)
    problems = xarray.Dataset(coords={"omega": omega, "wave_direction": [0.0, math.pi],
                                      "radiating_dof": list(body.dofs), "water_depth": [depth], "rho": [1025.0]})
    dataset = capytaine.BEMSolver().fill_dataset(problems, body)
    everything, usable = tmp_path / "all.nc", tmp_path / "usable.nc"
    capytaine.export_dataset(everything, dataset)
    capytaine.export_dataset(usable, dataset.sel(omega=[0.3, 0.7, 1.0]))
    table, reference = read_rao(everything), read_rao(usable)
    np.testing.assert_array_equal(table.omega, [0.3, 0.7, 1.0])
    np.testing.assert_allclose(table.values, reference.values, rtol=1e-12, atol=1e-15)
    assert any(note.startswith("frequencies dropped") and dropped in note for note in table.notes), table.notes


def test_a_single_heading_dataset_is_a_partial_table(barge, tmp_path):
    """Capytaine run for head seas only (one wave_direction): a table covering 165..195 deg whose RAOs there are
    the full dataset's (a single heading is allowed; the table says what it covers)."""
    dataset, _ = barge
    path = tmp_path / "head.nc"
    capytaine.export_dataset(path, dataset.sel(wave_direction=[math.pi]))
    table, whole = read_rao(path), read_rao(barge[1])
    assert table.covered_text() == "165..195 deg (tabulated 180)"
    head = np.full(OMEGA.size, math.pi)
    np.testing.assert_allclose(table(OMEGA, head), whole(OMEGA, head), rtol=1e-12, atol=1e-15)


def test_a_body_of_a_two_body_dataset_moves_as_capytaine_solves_them_coupled(tmp_path):
    """Two barges side by side 30 m apart, solved by Capytaine as one dataset: the table of each body is its six
    DOFs of the coupled 12-DOF equation of motion, equal to Capytaine's own post_pro.rao for that body
    (conjugated, and referred to the wave at the body's rotation centre); without a body name, or with an unknown
    one, the file is refused naming its bodies."""
    def barge(name: str, y: float):
        mesh = capytaine.mesh_parallelepiped(size=(LENGTH, BEAM, DRAFT + 1.0), resolution=(12, 4, 3),
                                             center=(0.0, y, (1.0 - DRAFT) / 2))
        return capytaine.FloatingBody(mesh=mesh, dofs=capytaine.rigid_body_dofs(rotation_center=(0, y, 0)),
                                      center_of_mass=(0.0, y, -0.5), name=name).immersed_part()

    both = barge("port", 15.0) + barge("starboard", -15.0)
    both.inertia_matrix = both.compute_rigid_body_inertia(rho=1025.0)
    both.hydrostatic_stiffness = both.compute_hydrostatic_stiffness(rho=1025.0)
    omega, directions = np.array([0.3, 0.6, 0.9]), np.array([0.0, math.pi / 2])
    problems = xarray.Dataset(coords={"omega": omega, "wave_direction": directions, "radiating_dof": list(both.dofs),
                                      "water_depth": [np.inf], "rho": [1025.0]})
    dataset = capytaine.BEMSolver().fill_dataset(problems, both)
    path = tmp_path / "two.nc"
    capytaine.export_dataset(path, dataset)
    theirs = capytaine.post_pro.rao(dataset).transpose("omega", "wave_direction", "radiating_dof")
    for name, y in (("port", 15.0), ("starboard", -15.0)):
        table = read_rao(path, body=name)
        assert table.reference_point == pytest.approx((0.0, y, 0.0))
        columns = theirs.sel(radiating_dof=[f"{name}__{d}" for d in ("Surge", "Sway", "Heave", "Roll", "Pitch",
                                                                     "Yaw")]).values
        k = omega**2 / 9.81
        for b, beta in enumerate(directions):
            shift = np.exp(1j * k * y * math.sin(beta))[:, None]
            ours = table(omega, np.full(omega.size, beta))
            np.testing.assert_allclose(ours, np.conj(columns[:, b, :]) * shift, rtol=1e-6, atol=1e-9)
    with pytest.raises(FileFormatError, match="a dataset of bodies port, starboard: name the one"):
        read_rao(path)
    with pytest.raises(FileFormatError, match="no body 'bow'"):
        read_rao(path, body="bow")


def test_a_centre_of_gravity_moved_by_the_scenario_moves_the_weights_restoring_as_capytaine_does(barge):
    """The scenario puts the barge's centre of gravity 2.5 m higher than the dataset's. The dataset's stiffness
    holds the weight at the old centre: the roll and pitch restoring must lose m g 2.5 m. Capytaine's own
    hydrostatics and inertia of the body with the raised centre, through its post_pro.rao, are the second
    implementation; without the correction the roll resonance of the tender barge sits far off (its RAOs
    differ by more than the tolerance at the roll peak)."""
    from marinesim.vessel.body import RigidBody

    dataset, path = barge
    mesh = capytaine.mesh_parallelepiped(size=(LENGTH, BEAM, DRAFT + 1.0), resolution=(12, 4, 3),
                                         center=(0.0, 0.0, (1.0 - DRAFT) / 2))
    cog = np.array([0.0, 0.0, 2.0])
    raised = capytaine.FloatingBody(mesh=mesh, dofs=capytaine.rigid_body_dofs(rotation_center=(0, 0, 0)),
                                    center_of_mass=tuple(cog)).immersed_part()
    inertia = raised.compute_rigid_body_inertia(rho=1025.0)
    moved = dataset.copy()
    moved["inertia_matrix"] = inertia
    moved["hydrostatic_stiffness"] = raised.compute_hydrostatic_stiffness(rho=1025.0)
    theirs = capytaine.post_pro.rao(moved).transpose("omega", "wave_direction", "radiating_dof").values
    mass = float(inertia.sel(influenced_dof="Surge", radiating_dof="Surge"))
    rotational = np.diag(inertia.sel(influenced_dof=["Roll", "Pitch", "Yaw"],
                                     radiating_dof=["Roll", "Pitch", "Yaw"]).values)
    at_cog = rotational - mass * (cog @ cog - cog * cog)
    ours = read_rao(path, rigid_body=RigidBody(mass, tuple(cog), tuple(np.sqrt(at_cog / mass))))
    for b, beta in enumerate(DIRECTIONS):
        np.testing.assert_allclose(ours(OMEGA, np.full(OMEGA.size, beta)), np.conj(theirs[:, b, :]),
                                   rtol=1e-6, atol=1e-9)


def test_the_scenarios_mass_moorings_and_damping_give_capytaines_own_raos(barge, tmp_path):
    """The barge's mass given as a scenario gives it (mass, centre of gravity, radii of gyration) replaces the
    dataset's inertia to the same RAOs; a mooring stiffness in surge, sway and yaw and a linear damping in roll
    give the RAOs Capytaine's own post_pro.rao gives with the same matrices, a second
    implementation. A failure means the parallel-axis mass matrix or the external matrices' signs or places are
    wrong (the moored surge falls by orders of magnitude in long waves, so a missing stiffness shows)."""
    from marinesim.vessel.body import RigidBody

    dataset, path = barge
    inertia = dataset["inertia_matrix"].sel(influenced_dof=["Roll", "Pitch", "Yaw"],
                                            radiating_dof=["Roll", "Pitch", "Yaw"]).values
    mass = float(dataset["inertia_matrix"].sel(influenced_dof="Surge", radiating_dof="Surge"))
    cog = np.array([0.0, 0.0, -0.5])
    at_cog = np.diag(inertia) - mass * (cog @ cog - cog * cog)
    same = RigidBody(mass, tuple(cog), tuple(np.sqrt(at_cog / mass)))
    np.testing.assert_allclose(read_rao(path, rigid_body=same).values, read_rao(path).values, rtol=1e-9, atol=1e-12)
    stiffness, damping = np.zeros((6, 6)), np.zeros((6, 6))
    stiffness[0, 0] = stiffness[1, 1] = 2.0e5
    stiffness[5, 5] = 5.0e7
    damping[3, 3] = 3.0e6
    moored = read_rao(path, rigid_body=RigidBody(external_stiffness=stiffness, external_damping=damping))
    dofs = list(dataset["radiating_dof"].values)
    as_array = lambda m: xarray.DataArray(m, coords={"influenced_dof": dofs, "radiating_dof": dofs})  # noqa: E731
    theirs = capytaine.post_pro.rao(dataset, dissipation=as_array(damping), stiffness=as_array(stiffness))
    theirs = theirs.transpose("omega", "wave_direction", "radiating_dof").values
    for b, beta in enumerate(DIRECTIONS):
        np.testing.assert_allclose(moored(OMEGA, np.full(OMEGA.size, beta)), np.conj(theirs[:, b, :]),
                                   rtol=1e-6, atol=1e-9)
    free = read_rao(path)
    assert abs(moored.values[0, 0, 0, 0]) < 0.05 * abs(free.values[0, 0, 0, 0])  # surge at 0.05 rad/s, following
