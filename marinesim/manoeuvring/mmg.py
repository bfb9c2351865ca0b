"""The MMG standard method (Yasukawa & Yoshimura 2015, J. Mar. Sci. Technol. 20:37-52): hull, propeller
and rudder forces, 3 DOF about midship.

Axes and signs as :mod:`marinesim.manoeuvring.state` (y to starboard, r clockwise, rudder positive to
starboard). With ``U = sqrt(u^2 + v^2)``, the drift angle ``beta = asin(-v / U)`` (within +-90 deg: going astern
the flow is not a drift of 180 deg), ``v' = v / U`` and
``r' = r L / U``:

- motion: ``(m + m_x) du/dt - (m + m_y) v r - x_G m r^2 = X``, ``(m + m_y) dv/dt + (m + m_x) u r + x_G m
  dr/dt = Y``, ``(I_zG + x_G^2 m + J_z) dr/dt + x_G m (dv/dt + u r) = N``, each force the hull's, the
  propeller's (X only) and the rudder's;
- hull: ``X_H = (rho/2) L d U^2 (-R'_0 + X'_vv v'^2 + X'_vr v' r' + X'_rr r'^2 + X'_vvvv v'^4)``, ``Y_H`` and
  ``N_H`` (times L) the cubic polynomials ``Y'_v v' + Y'_r r' + Y'_vvv v'^3 + Y'_vvr v'^2 r' + Y'_vrr v' r'^2 +
  Y'_rrr r'^3``; the resistance ``R'_0`` with the sign of ``u``, so that it opposes the motion astern too;
- propeller: ``X_P = (1 - t_P) rho n^2 D_P^4 K_T(J_P)``, ``K_T = k_0 + k_1 J + k_2 J^2``, ``J_P = u (1 - w_P) /
  (n D_P)``, the wake in a turn ``(1 - w_P) / (1 - w_P0) = 1 + (1 - exp(-C_1 |beta_P|)) (C_2 - 1)``, ``beta_P =
  beta - x'_P r'`` (``C_2`` by the sign of ``beta_P``); astern (``n <
  0``) the thrust is ``-rho n^2 D_P^4 (a_0 + a_1 J)``, ``J = u (1 - w_P0) / (|n| D_P)`` (the method covers
  ahead only: this is a first-order backing characteristic for the crash stop);
- rudder: ``F_N = (rho/2) A_R U_R^2 f_alpha sin(alpha_R)``, ``alpha_R = delta - atan2(v_R, u_R)``,
  ``u_R = epsilon u (1 - w_P) sqrt(eta {1 + kappa (sqrt(1 + 8 K_T / (pi J_P^2)) - 1)}^2 + 1 - eta)``,
  ``eta = D_P / H_R``, ``v_R = U gamma_R beta_R``, ``beta_R = beta - l'_R r'`` (``gamma_R`` by the sign of
  ``beta_R``); ``X_R = -(1 - t_R) F_N sin(delta)``, ``Y_R = -(1 + a_H) F_N cos(delta)``, ``N_R = -(x_R + a_H
  x_H) F_N cos(delta)`` with ``x_R``, ``x_H`` in metres (not their ratios to L).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from marinesim.compiled import compiled
from marinesim.constants import RHO_SEAWATER


@dataclass(frozen=True)
class Mmg:
    """A ship by the MMG standard method: particulars (m, m^3), non-dimensional hydrodynamic coefficients named
    as in Yasukawa & Yoshimura (2015), masses and inertias by ``(rho/2) L^2 d`` and ``(rho/2) L^4 d``."""

    lpp: float
    breadth: float
    draft: float
    volume: float
    x_g: float
    k_zz: float              # yaw radius of gyration / Lpp
    m_x: float
    m_y: float
    j_z: float
    r_0: float
    x_vv: float
    x_vr: float
    x_rr: float
    x_vvvv: float
    y_v: float
    y_r: float
    y_vvv: float
    y_vvr: float
    y_vrr: float
    y_rrr: float
    n_v: float
    n_r: float
    n_vvv: float
    n_vvr: float
    n_vrr: float
    n_rrr: float
    d_p: float
    t_p: float
    w_p0: float
    k_0: float
    k_1: float
    k_2: float
    x_p: float               # propeller position / Lpp
    a_r: float               # movable rudder area, m^2
    h_r: float               # rudder span, m
    t_r: float
    a_h: float
    x_h: float               # / Lpp
    x_r: float               # / Lpp
    gamma_r_port: float      # flow straightening, beta_R < 0
    gamma_r_starboard: float  # beta_R > 0
    l_r: float               # / Lpp
    epsilon: float
    kappa: float
    f_alpha: float           # rudder normal force gradient (1/rad)
    c_1: float = 2.0         # the wake in a turn: C_1, and C_2 for beta_P > 0 and <= 0
    c_2_plus: float = 1.6
    c_2_minus: float = 1.1
    astern_kt: tuple[float, float] = (0.0, 0.0)
    rho: float = RHO_SEAWATER
    label: str = field(default="MMG standard method, 3 DOF", init=False)
    dof: int = field(default=3, init=False)

    def __post_init__(self) -> None:
        rho, lpp, d = self.rho, self.lpp, self.draft
        mass = rho * self.volume
        half = 0.5 * rho * lpp**2 * d
        m_x, m_y = self.m_x * half, self.m_y * half
        inertia = mass * (self.k_zz * lpp) ** 2 + self.x_g**2 * mass + self.j_z * half * lpp**2
        # [[m + m_y, x_G m], [x_G m, I]] (dv/dt, dr/dt) = (Y', N'): its inverse, once
        a, b, c = mass + m_y, self.x_g * mass, inertia
        det = a * c - b * b
        derived = {"mass": mass, "mass_x": m_x, "mass_y": m_y, "i11": c / det, "i12": -b / det, "i22": a / det,
                   "force": 0.5 * rho * lpp * d, "kappa_squared": self.kappa**2,
                   "kt_astern_0": self.astern_kt[0], "kt_astern_1": self.astern_kt[1]}
        values = [derived[name] if name in derived else getattr(self, name) for name in _COEFFICIENTS]
        coefficients = np.array(values, dtype=float)
        coefficients.flags.writeable = False
        object.__setattr__(self, "_coefficients", coefficients)

    @property
    def length_m(self) -> float:
        return self.lpp

    @property
    def coefficients(self) -> np.ndarray:
        """Her coefficients and what follows from them, in :func:`mmg_accelerations`' order (:data:`_COEFFICIENTS`;
        read-only)."""
        return self._coefficients

    def accelerations(self, u: float, v: float, r: float, p: float, phi: float, delta: float, n: float,
                      more: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> tuple[float, float, float, float]:
        """(du/dt, dv/dt, dr/dt, dp/dt) (m/s^2, rad/s^2) at midship for surge ``u``, sway ``v`` (m/s), yaw rate
        ``r`` (rad/s), rudder ``delta`` (rad) and propeller ``n`` (rev/s), with ``more`` surge and sway force (N) and
        yaw moment (N m) of a model built on this one; roll is not modelled (dp/dt = 0)."""
        return (*mmg_accelerations(self._coefficients, u, v, r, delta, n, *more), 0.0)


_COEFFICIENTS = ("lpp", "rho", "force", "mass", "mass_x", "mass_y", "i11", "i12", "i22", "x_g", "r_0", "x_vv",
                 "x_vr", "x_rr", "x_vvvv", "y_v", "y_r", "y_vvv", "y_vvr", "y_vrr", "y_rrr", "n_v", "n_r", "n_vvv",
                 "n_vvr", "n_vrr", "n_rrr", "d_p", "t_p", "w_p0", "k_0", "k_1", "k_2", "x_p", "h_r", "a_r", "t_r",
                 "a_h", "x_h", "x_r", "gamma_r_port", "gamma_r_starboard", "l_r", "epsilon", "kappa", "kappa_squared",
                 "f_alpha", "c_1", "c_2_plus", "c_2_minus", "kt_astern_0", "kt_astern_1")
""":func:`mmg_accelerations`' coefficients in order: :class:`Mmg`'s fields, her masses (kg; ``mass_x``, ``mass_y``
the added masses), the inverse of her sway-yaw mass matrix (``i11``, ``i12``, ``i22``), ``force`` = (rho/2) L d
(kg/m), kappa squared and the backing thrust's two coefficients."""


@compiled
def mmg_accelerations(c: np.ndarray, u: float, v: float, r: float, delta: float, n: float, more_x: float,
                      more_y: float, more_n: float) -> tuple[float, float, float]:
    """(du/dt, dv/dt, dr/dt) (m/s^2, rad/s^2) at midship of the ship of coefficients ``c``
    (:attr:`Mmg.coefficients`) for surge ``u``, sway ``v`` (m/s), yaw rate ``r`` (rad/s), rudder ``delta`` (rad)
    and propeller ``n`` (rev/s), with ``more_x``, ``more_y`` (N) and ``more_n`` (N m) of a model built on hers: the
    module's formulas, compiled (the same values as in Python to the last bit or two: numba's ``hypot`` is not
    CPython's)."""
    (lpp, rho, force, mass, m_x, m_y, i11, i12, i22, x_g, r_0, x_vv, x_vr, x_rr, x_vvvv, y_v, y_r, y_vvv, y_vvr,
     y_vrr, y_rrr, n_v, n_r, n_vvv, n_vvr, n_vrr, n_rrr, d_p, t_p, w_p0, k_0, k_1, k_2, x_p, h_r, a_r, t_r, a_h,
     x_h, x_r, gamma_port, gamma_starboard, l_r, epsilon, kappa, kappa_squared, f_alpha, c_1, c_2_plus, c_2_minus,
     kt_astern_0, kt_astern_1) = c
    speed = math.hypot(u, v)
    if speed > 1e-9:
        vv, rr = v / speed, r * lpp / speed
        beta = math.asin(-vv)  # within +-90 deg: going astern the flow is not a drift of 180 deg
    else:
        vv = rr = beta = 0.0
    q = force * speed * speed
    x_h_force = q * (-math.copysign(r_0, u) + x_vv * vv * vv + x_vr * vv * rr + x_rr * rr * rr + x_vvvv * vv**4.0)
    y_h = q * (y_v * vv + y_r * rr + y_vvv * vv**3.0 + y_vvr * vv * vv * rr + y_vrr * vv * rr * rr + y_rrr * rr**3.0)
    n_h = q * lpp * (n_v * vv + n_r * rr + n_vvv * vv**3.0 + n_vvr * vv * vv * rr + n_vrr * vv * rr * rr
                     + n_rrr * rr**3.0)
    # propeller: K_T n^2 D^4 = (k_0 n^2 + k_1 n u_P / D + k_2 u_P^2 / D^2) D^4, finite as n goes to 0
    beta_p = beta - x_p * rr
    c_2 = c_2_plus if beta_p > 0.0 else c_2_minus
    u_p = u * (1.0 - w_p0) * (1.0 + (1.0 - math.exp(-c_1 * abs(beta_p))) * (c_2 - 1.0))
    ahead = n * n * k_0 + n * u_p * k_1 / d_p + u_p * u_p * k_2 / (d_p * d_p) if n > 0.0 else 0.0
    if n < 0.0:
        thrust = -rho * d_p**4.0 * (n * n * kt_astern_0 - n * u * (1.0 - w_p0) * kt_astern_1 / d_p)
    else:
        thrust = rho * d_p**4.0 * ahead
    x_p_force = (1.0 - t_p) * thrust
    # rudder: the inflow sped up by the propeller race (ahead only); 8 K_T / (pi J^2) = 8 K_T n^2 D^2 / (pi u_P^2)
    eta = d_p / h_r
    if n > 0.0 and u_p > 0.0:
        race = 1.0 + 8.0 * ahead * d_p * d_p / (math.pi * u_p * u_p)
        race = 1.0 + kappa * (math.sqrt(race) - 1.0) if race > 0.0 else 1.0 - kappa
        u_r = epsilon * u_p * math.sqrt(eta * race * race + 1.0 - eta)
    elif n > 0.0:
        # at rest or going astern with the propeller ahead: the race alone, momentum theory (J = 0)
        u_r = epsilon * math.sqrt(eta * kappa_squared * 8.0 * max(k_0, 0.0) / math.pi) * n * d_p
    else:
        u_r = epsilon * u_p
    beta_r = beta - l_r * rr
    gamma = gamma_starboard if beta_r > 0.0 else gamma_port
    v_r = speed * gamma * beta_r
    alpha_r = delta - math.atan2(v_r, u_r) if (u_r != 0.0 or v_r != 0.0) else delta
    f_n = 0.5 * rho * a_r * (u_r * u_r + v_r * v_r) * f_alpha * math.sin(alpha_r)
    cos_d = math.cos(delta)
    x_r_force = -(1.0 - t_r) * f_n * math.sin(delta)
    y_r_force = -(1.0 + a_h) * f_n * cos_d
    n_r_force = -(x_r + a_h * x_h) * lpp * f_n * cos_d
    # motion
    x = x_h_force + x_p_force + x_r_force + more_x + (mass + m_y) * v * r + x_g * mass * r * r
    y = y_h + y_r_force + more_y - (mass + m_x) * u * r
    nn = n_h + n_r_force + more_n - x_g * mass * u * r
    return x / (mass + m_x), i11 * y + i12 * nn, i12 * y + i22 * nn
