"""A ship from her main particulars (L, B, T, Cb) alone, for vessels without published coefficients.

Axes and signs as :mod:`marinesim.manoeuvring.state`. Sway and yaw (Fossen 2021, section 7.x and his
Python Vehicle Simulator's ``clarke83``, MIT; Clarke, Gedling & Hine 1983): added masses and linear hull
derivatives from multiple regression on model tests, with ``S = pi (T/L)^2``,

- ``-Y'_vdot/S = 1 + 0.16 Cb B/T - 5.1 (B/L)^2``, ``-N'_rdot/S = 1/12 + 0.017 Cb B/T - 0.33 B/L`` (the cross
  terms ``Y'_rdot`` and ``N'_vdot`` left out, as the MMG method leaves them),
- ``-Y'_v/S = 1 + 0.4 Cb B/T``, ``-Y'_r/S = -1/2 + 2.2 B/L - 0.08 B/T``, ``-N'_v/S = 1/2 + 2.4 T/L``,
  ``-N'_r/S = 1/4 + 0.039 B/T - 0.56 B/L``,

taken as the hull's (the rigid body's ``m u r`` is added separately). A linear model turns ever faster with more
rudder; a real hull does not, so the cross-flow drag of strip theory is added: ``Y = -(rho/2) T C_D int |v + x r| (v
+ x r) dx``, ``N = -(rho/2) T C_D int x |v + x r| (v + x r) dx`` over ``-L/2..L/2`` (Gauss-Legendre), ``C_D``
Hoerner's 2-D cross-flow drag of a section with ``B/2T`` (Fossen's digitisation). Surge: the ITTC 1957 friction line
with a form factor, ``R = (rho/2) S_w (1 + k) C_F u|u|``, ``C_F = 0.075 / (log10 Re - 2)^2``, ``k = 0.1 + 0.4 Cb``,
the wetted area by Mumford ``S_w = 1.7 L T + V / T``; surge added mass ``0.05 m``; ``(m + m_y) v r`` the speed lost
in a turn. The propeller and the rudder are the MMG standard method's (:mod:`marinesim.manoeuvring.mmg`) with
generic interaction coefficients: a four-bladed propeller of diameter ``0.65 T`` (``K_T = 0.33 - 0.24 J - 0.17
J^2``, roughly a Wageningen B4-55 of pitch ratio 0.8), Taylor's wake ``w_P0 = 0.5 Cb - 0.05`` (the same in a turn:
the ship is symmetric port and starboard), thrust deduction ``0.6 w_P0``; a rudder of area ``A_R`` (default ``L T /
60``, the classification societies' minimum) and ``0.7 T`` span, so of aspect ratio ``(0.7 T)^2 / A_R`` (29.4 T/L by
default: 1.2 for the tanker, 2.1 for the supply vessel) and Fujii's ``f_alpha = 6.13 Lambda / (Lambda + 2.25)``,
``t_R = 1 - 0.28 Cb - 0.55``, ``a_H = 0.4``, ``x'_H = -0.45``, ``x'_R = -0.5``, ``gamma_R = 0.5``, ``l'_R = -0.9``,
``epsilon = 1``, ``kappa = 0.5``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from marinesim.constants import RHO_SEAWATER
from marinesim.compiled import compiled
from marinesim.manoeuvring.mmg import Mmg

HOERNER = (np.array([0.0109, 0.1766, 0.3530, 0.4519, 0.4728, 0.4929, 0.4933, 0.5585, 0.6464, 0.8336, 0.9880, 1.3081,
                     1.6392, 1.8600, 2.3129, 2.6000, 3.0088, 3.4508, 3.7379, 4.0031]),
           np.array([1.9661, 1.9657, 1.8976, 1.7872, 1.5837, 1.2786, 1.2108, 1.0836, 0.9986, 0.8796, 0.8284, 0.7599,
                     0.6914, 0.6571, 0.6307, 0.5962, 0.5868, 0.5859, 0.5599, 0.5593]))
"""Hoerner's 2-D cross-flow drag coefficient against B / 2T (Fossen's digitisation in his Python Vehicle Simulator,
``lib/gnc.py``, MIT licence, copyright Thor I. Fossen; the notice as ``rao/LICENSE-MSS``)."""
KINEMATIC_VISCOSITY = 1.19e-6
"""Sea water at 15 deg C (m^2/s), ITTC."""
STRIPS = 8
"""Gauss-Legendre points of the cross-flow drag integral (a pure drift's exactly; a pure turn's ``|x|^3`` to 1e-3)."""


def hoerner(breadth: float, draft: float) -> float:
    """Hoerner's 2-D cross-flow drag coefficient of a section of ``breadth`` and ``draft`` (m)."""
    return float(np.interp(breadth / (2.0 * draft), *HOERNER))


@dataclass(frozen=True)
class Clarke:
    """A ship of ``length`` (Lpp), ``breadth``, ``draft`` (m) and block coefficient ``cb``; her centre of gravity
    ``x_g`` (m ahead of midship), yaw radius of gyration ``k_zz`` (/ L), rudder area ``rudder_area`` (m^2; 0: L T /
    60) and backing thrust ``astern_kt``."""

    length: float
    breadth: float
    draft: float
    cb: float
    x_g: float = 0.0
    k_zz: float = 0.25
    rudder_area: float = 0.0
    astern_kt: tuple[float, float] = (0.0, 0.0)
    rho: float = RHO_SEAWATER
    label: str = field(default="from main particulars (Clarke 1983), 3 DOF", init=False)
    dof: int = field(default=3, init=False)

    def __post_init__(self) -> None:
        l, b, t, cb = self.length, self.breadth, self.draft, self.cb
        s = math.pi * (t / l) ** 2
        area = self.rudder_area or l * t / 60.0
        span = 0.7 * t
        aspect = span * span / area
        w_p0 = max(0.5 * cb - 0.05, 0.0)
        # The MMG method's frame with Clarke's derivatives: its hull polynomials hold the linear terms, and its
        # propeller and rudder the generic coefficients above; cross-flow drag and resistance are added here.
        half = 0.5 * self.rho * l * l * t
        mmg = Mmg(lpp=l, breadth=b, draft=t, volume=cb * l * b * t, x_g=self.x_g, k_zz=self.k_zz,
                  m_x=0.05 * self.rho * cb * l * b * t / half,
                  m_y=s * (1.0 + 0.16 * cb * b / t - 5.1 * (b / l) ** 2) * l / t,
                  j_z=s * (1.0 / 12.0 + 0.017 * cb * b / t - 0.33 * b / l) * l / t,
                  r_0=0.0, x_vv=0.0, x_vr=0.0, x_rr=0.0, x_vvvv=0.0,
                  y_v=-s * (1.0 + 0.4 * cb * b / t) * l / t, y_r=-s * (-0.5 + 2.2 * b / l - 0.08 * b / t) * l / t,
                  y_vvv=0.0, y_vvr=0.0, y_vrr=0.0, y_rrr=0.0,
                  n_v=-s * (0.5 + 2.4 * t / l) * l / t, n_r=-s * (0.25 + 0.039 * b / t - 0.56 * b / l) * l / t,
                  n_vvv=0.0, n_vvr=0.0, n_vrr=0.0, n_rrr=0.0,
                  d_p=0.65 * t, t_p=0.6 * w_p0, w_p0=w_p0, k_0=0.33, k_1=-0.24, k_2=-0.17, x_p=-0.48,
                  a_r=area, h_r=span, t_r=1.0 - 0.28 * cb - 0.55, a_h=0.4, x_h=-0.45, x_r=-0.5,
                  gamma_r_port=0.5, gamma_r_starboard=0.5, l_r=-0.9, epsilon=1.0, kappa=0.5,
                  f_alpha=6.13 * aspect / (aspect + 2.25), c_1=0.0, astern_kt=self.astern_kt, rho=self.rho)
        points, weights = np.polynomial.legendre.leggauss(STRIPS)
        wetted = 1.7 * l * t + cb * l * b
        set_ = object.__setattr__
        set_(self, "_mmg", mmg)
        strips = np.column_stack([0.5 * l * points, 0.5 * l * weights])
        strips.flags.writeable = False
        set_(self, "_strips", strips)
        set_(self, "_cross", 0.5 * self.rho * t * hoerner(b, t))
        set_(self, "_resistance", (0.5 * self.rho * wetted * (1.0 + 0.1 + 0.4 * cb), l / KINEMATIC_VISCOSITY))

    @property
    def length_m(self) -> float:
        return self.length

    def resistance(self, u: float) -> float:
        """Calm-water resistance (N) at surge ``u`` (m/s), opposing it."""
        return _ittc(*self._resistance, u)

    def accelerations(self, u: float, v: float, r: float, p: float, phi: float, delta: float, n: float
                      ) -> tuple[float, float, float, float]:
        """(du/dt, dv/dt, dr/dt, 0) (m/s^2, rad/s^2) at midship (see the module)."""
        return self._mmg.accelerations(u, v, r, p, phi, delta, n, _hull(self._strips, self._cross, *self._resistance,
                                                                        u, v, r))


@compiled
def _ittc(scale: float, re_per_speed: float, u: float) -> float:
    """The ITTC 1957 line's resistance (N) at surge ``u`` (m/s): ``scale`` (rho/2) S_w (1 + k) (kg/m), the Reynolds
    number ``re_per_speed`` u (no less than 1e5)."""
    re = max(abs(u) * re_per_speed, 1e5)
    return scale * 0.075 / (math.log10(re) - 2.0) ** 2.0 * u * abs(u)


@compiled
def _hull(strips: np.ndarray, cross: float, scale: float, re_per_speed: float, u: float, v: float, r: float
          ) -> tuple[float, float, float]:
    """What this model adds to the MMG frame's forces: (X N, Y N, N N m), the resistance and the cross-flow drag
    summed over the ``strips`` ((k, 2): each point's x (m) and weight (m)), ``cross`` (rho/2) T C_D (kg/m^2)."""
    y = nn = 0.0
    for k in range(strips.shape[0]):
        x, weight = strips[k, 0], strips[k, 1]
        w = v + x * r
        drag = -cross * abs(w) * w * weight
        y += drag
        nn += x * drag
    return -_ittc(scale, re_per_speed, u), y, nn
