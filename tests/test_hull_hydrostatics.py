"""Hull hydrostatics (marinesim.hull.hydrostatics) against independent references: WAMIT's own
hydrostatics of the tanker panels (the .hst restoring coefficients and the .frc mass, computed by
another program), the analytic box, and the analytic Wigley hull (with scipy quadrature of its
wetted area)."""

import math

import numpy as np
import pytest
from scipy.integrate import dblquad, quad

from conftest import ROOT
from marinesim.hull import box_hull, hydrostatics, load_hull, wigley_half_breadth, wigley_hull

TANKER = ROOT / "hulls" / "tanker.gdf"
RHO = 1025.0


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
