"""Hydrostatic summary of a hull at its waterline, exact for the triangulated wetted surface.

All volume and waterplane quantities come from the wetted surface alone (z <= 0, outward
normals) by the divergence theorem, the waterplane lid at z = 0 closing the volume:

- volume ``V = int z n_z dS``; centre of buoyancy ``V x_B = int x z n_z dS``, ``V y_B = int y z n_z dS``,
  ``V z_B = int (z^2 / 2) n_z dS`` (the lid contributes nothing: z = 0 there);
- waterplane ``A_wp = -int n_z dS``, its centroid (the centre of flotation) and second moments
  ``I = -int f(x, y) n_z dS`` for f = x, y, x^2, y^2 (any f(x, y) has zero flux through a closed
  surface, so the lid's integral is minus the wetted surface's);
- metacentric radii ``BM_T = I_T / V`` and ``BM_L = I_L / V`` about the centre of flotation.

Every integrand is at most quadratic, so the edge-midpoint rule on each triangle is exact.
Works for closed meshes and for wetted-surface-only meshes (WAMIT ``.gdf``) alike.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import TYPE_CHECKING

from marinesim.constants import RHO_SEAWATER, G

if TYPE_CHECKING:
    from marinesim.hull.mesh import Hull


@dataclass(frozen=True)
class Hydrostatics:
    volume_m3: float
    displacement_t: float  # rho V / 1000
    wetted_area_m2: float
    waterplane_area_m2: float
    centre_of_buoyancy_m: tuple[float, float, float]  # body frame, z below the waterline < 0
    centre_of_flotation_m: tuple[float, float]
    bm_transverse_m: float
    bm_longitudinal_m: float
    waterline_length_m: float  # 0 for a body that does not cross the waterline
    waterline_beam_m: float
    draft_m: float  # deepest point below the waterline
    length_overall_m: float
    rho_kg_m3: float

    @property
    def froude_length_m(self) -> float:
        """The length for Froude numbers: at the waterline, else (submerged body) overall."""
        return self.waterline_length_m or self.length_overall_m

    def froude(self, speed_m_s: float, g: float = G) -> float:
        """The Froude number at ``speed_m_s`` (m/s) on :attr:`froude_length_m`."""
        return froude_number(speed_m_s, self.froude_length_m, g)

    def as_dict(self) -> dict:
        return asdict(self)


def froude_number(speed_m_s: float, length_m: float, g: float = G) -> float:
    """Fn = U / sqrt(g L) (U in m/s, L in m: the waterline length, :attr:`Hydrostatics.froude_length_m`)."""
    return speed_m_s / math.sqrt(g * length_m)


def hydrostatics(hull: Hull, rho: float = RHO_SEAWATER) -> Hydrostatics:
    """The hydrostatic summary of ``hull`` floating at z = 0 in water of density ``rho`` (kg/m^3)."""
    import numpy as np  # here, not above: the package imports this module, and listing its formats imports no numpy

    wet = hull.wetted()
    volume = wet.integral(lambda p: p[..., 2], normal=2)
    buoyancy = tuple(wet.integral(f, normal=2) / volume for f in (
        lambda p: p[..., 0] * p[..., 2], lambda p: p[..., 1] * p[..., 2], lambda p: 0.5 * p[..., 2] ** 2))
    area = -wet.integral(lambda p: np.ones(p.shape[:-1]), normal=2)
    if area > 1e-9 * hull.overall_length_m**2:  # else a submerged body: no waterplane
        xf = -wet.integral(lambda p: p[..., 0], normal=2) / area
        yf = -wet.integral(lambda p: p[..., 1], normal=2) / area
        i_transverse = -wet.integral(lambda p: p[..., 1] ** 2, normal=2) - area * yf**2
        i_longitudinal = -wet.integral(lambda p: p[..., 0] ** 2, normal=2) - area * xf**2
    else:
        xf = yf = i_transverse = i_longitudinal = 0.0
    corners = wet.corners
    at_waterline = corners[np.abs(corners[:, 2]) <= 1e-9 * max(hull.overall_length_m, 1.0)]
    lwl, bwl = (float(np.ptp(at_waterline[:, k])) for k in (0, 1)) if len(at_waterline) else (0.0, 0.0)
    return Hydrostatics(
        volume_m3=volume, displacement_t=rho * volume / 1000.0, wetted_area_m2=float(wet.areas.sum()),
        waterplane_area_m2=area, centre_of_buoyancy_m=buoyancy, centre_of_flotation_m=(xf, yf),
        bm_transverse_m=i_transverse / volume, bm_longitudinal_m=i_longitudinal / volume,
        waterline_length_m=lwl, waterline_beam_m=bwl, draft_m=float(-corners[:, 2].min()),
        length_overall_m=hull.overall_length_m, rho_kg_m3=rho,
    )


def format_hydrostatics(h: Hydrostatics) -> str:
    xb, yb, zb = h.centre_of_buoyancy_m
    return "\n".join([
        f"length overall {h.length_overall_m:.2f} m; at the waterline L {h.waterline_length_m:.2f} m, "
        f"B {h.waterline_beam_m:.2f} m; draft {h.draft_m:.2f} m",
        f"displaced volume {h.volume_m3:,.1f} m^3 ({h.displacement_t:,.1f} t at rho {h.rho_kg_m3:g} kg/m^3)",
        f"wetted surface {h.wetted_area_m2:,.1f} m^2, waterplane {h.waterplane_area_m2:,.1f} m^2",
        f"centre of buoyancy ({xb:.2f}, {yb:.2f}, {zb:.2f}) m, centre of flotation x {h.centre_of_flotation_m[0]:.2f} m",
        f"BM transverse {h.bm_transverse_m:.2f} m, longitudinal {h.bm_longitudinal_m:.1f} m",
    ])
