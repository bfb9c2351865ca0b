"""Capytaine's phase reference: the RAO is per unit wave at the reference point (the rotation centre),
wherever the mesh's origin lies (CONVENTIONS, "Transfer functions").

The same 80 x 16 m barge, draft 4 m, is solved here twice with Capytaine (coarse mesh, a second or
so): meshed with its origin at its centre, and with its origin 40 m aft of the centre (the body at
x = 40 m), rotating about its centre both times. Capytaine's forces refer to the wave at the mesh
origin, so read naively the second table's phases differ by k 40 cos(beta) (99 deg at 0.65 rad/s in
head seas); referred to the rotation centre the two tables are one.
"""

import math

import capytaine
import numpy as np
import pytest
import xarray

from marinesim.vessel import read_rao
from marinesim.vessel.capytaine import read_capytaine

LENGTH, BEAM, DRAFT = 80.0, 16.0, 4.0
SHIFT = 40.0
"""m: the second mesh's origin lies this far aft of the barge's centre."""
OMEGA = np.array([0.15, 0.4, 0.65, 0.8])
DIRECTIONS = np.radians([0.0, 45.0, 90.0, 135.0, 180.0])


def solve(centre_x: float, depth: float):
    """Capytaine's dataset of the barge centred at ``centre_x`` (m, mesh frame), rotating about its centre."""
    mesh = capytaine.mesh_parallelepiped(size=(LENGTH, BEAM, DRAFT + 1.0), resolution=(10, 3, 2),
                                         center=(centre_x, 0.0, (1.0 - DRAFT) / 2))
    body = capytaine.FloatingBody(mesh=mesh, dofs=capytaine.rigid_body_dofs(rotation_center=(centre_x, 0.0, 0.0)),
                                  center_of_mass=(centre_x, 0.0, -0.5)).immersed_part()
    body.inertia_matrix = body.compute_rigid_body_inertia(rho=1025.0)
    body.hydrostatic_stiffness = body.compute_hydrostatic_stiffness(rho=1025.0)
    problems = xarray.Dataset(coords={"omega": OMEGA, "wave_direction": DIRECTIONS, "radiating_dof": list(body.dofs),
                                      "water_depth": [depth], "rho": [1025.0]})
    return capytaine.BEMSolver().fill_dataset(problems, body, progress_bar=False)


@pytest.fixture(scope="module", params=[math.inf, 30.0], ids=["deep", "depth30"])
def barges(request, tmp_path_factory):
    """(centred table, shifted table, shifted dataset, its NetCDF path) in deep water and in 30 m."""
    folder = tmp_path_factory.mktemp("barges")
    tables = []
    for name, centre in (("centred", 0.0), ("shifted", SHIFT)):
        dataset = solve(centre, request.param)
        path = folder / f"{name}.nc"
        capytaine.export_dataset(path, dataset)
        tables.append(read_rao(path))
    return tables[0], tables[1], dataset, path


def test_shifted_mesh_gives_the_same_rao(barges):
    # referred to the wave at the mesh origin the shifted barge's phases would differ by k 40 cos(beta)
    # (finite-depth k in 30 m); the amplitudes agree either way
    centred, shifted, _, _ = barges
    assert shifted.reference_point == (SHIFT, 0.0, 0.0) and centred.reference_point == (0.0, 0.0, 0.0)
    for beta in DIRECTIONS:
        a = centred(OMEGA, np.full(OMEGA.size, beta))
        b = shifted(OMEGA, np.full(OMEGA.size, beta))
        # each DOF to 1e-5 of its largest value (sway, roll, yaw vanish in head seas): the two meshes sit at
        # different absolute positions, where Capytaine's finite-depth Green function differs by ~1e-6;
        # the wrong reference would be off by |2 sin(k 40 cos(beta) / 2)|, of order 1
        for j in range(6):
            scale = np.abs(centred.values[..., j]).max()
            np.testing.assert_allclose(b[:, j], a[:, j], rtol=0, atol=1e-5 * scale,
                                       err_msg=f"beta {math.degrees(beta):g} deg, dof {j}")


def test_long_wave_phases_refer_to_the_reference_point(barges):
    # at the rotation centre the long-wave pitch is +i k cos(beta) and surge -i cos(beta) / tanh(kh):
    # 90 deg lead and lag; referred to the mesh origin 40 m aft they would be off by k 40 cos(beta)
    _, shifted, _, _ = barges
    for beta in (0.0, math.pi):
        h = shifted(OMEGA[:1], np.array([beta]))[0]
        sign = math.copysign(1.0, math.cos(beta))
        assert math.degrees(np.angle(h[4] * sign)) == pytest.approx(90.0, abs=1.0)
        assert math.degrees(np.angle(h[0] * sign)) == pytest.approx(-90.0, abs=1.0)


def test_dataset_without_rotation_centre_assumes_the_mesh_origin(barges, tmp_path):
    # Capytaine 2.x stores no rotation_center: the mesh origin is the reference point, the RAOs are
    # Capytaine's own (conjugated, no shift), and a note says what was assumed
    _, _, dataset, _ = barges
    path = tmp_path / "v2.nc"
    capytaine.export_dataset(path, dataset.drop_vars("rotation_center"))
    table = read_capytaine(path)
    assert table.reference_point == (0.0, 0.0, 0.0)
    assert any("no rotation_center" in note and "(0, 0, 0)" in note for note in table.notes)
    theirs = capytaine.post_pro.rao(dataset).transpose("omega", "wave_direction", "radiating_dof").values
    for b, beta in enumerate(DIRECTIONS):
        ours = table(OMEGA, np.full(OMEGA.size, beta))
        np.testing.assert_allclose(ours, np.conj(theirs[:, b, :]), rtol=1e-9, atol=1e-12)
