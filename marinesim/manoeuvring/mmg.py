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
        set_ = object.__setattr__
        set_(self, "_mass", (mass, m_x, m_y))
        set_(self, "_inverse", (c / det, -b / det, a / det))
        set_(self, "_force", 0.5 * rho * lpp * d)

    @property
    def length_m(self) -> float:
        return self.lpp

    def accelerations(self, u: float, v: float, r: float, p: float, phi: float, delta: float, n: float,
                      more: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> tuple[float, float, float, float]:
        """(du/dt, dv/dt, dr/dt, dp/dt) (m/s^2, rad/s^2) at midship for surge ``u``, sway ``v`` (m/s), yaw rate
        ``r`` (rad/s), rudder ``delta`` (rad) and propeller ``n`` (rev/s), with ``more`` surge and sway force (N) and
        yaw moment (N m) of a model built on this one; roll is not modelled (dp/dt = 0)."""
        lpp, rho = self.lpp, self.rho
        mass, m_x, m_y = self._mass
        speed = math.hypot(u, v)
        if speed > 1e-9:
            vv, rr = v / speed, r * lpp / speed
            beta = math.asin(-vv)  # within +-90 deg: going astern the flow is not a drift of 180 deg
        else:
            vv = rr = beta = 0.0
        q = self._force * speed * speed
        x_h = q * (-math.copysign(self.r_0, u) + self.x_vv * vv * vv + self.x_vr * vv * rr + self.x_rr * rr * rr
                   + self.x_vvvv * vv**4)
        y_h = q * (self.y_v * vv + self.y_r * rr + self.y_vvv * vv**3 + self.y_vvr * vv * vv * rr
                   + self.y_vrr * vv * rr * rr + self.y_rrr * rr**3)
        n_h = q * lpp * (self.n_v * vv + self.n_r * rr + self.n_vvv * vv**3 + self.n_vvr * vv * vv * rr
                         + self.n_vrr * vv * rr * rr + self.n_rrr * rr**3)
        # propeller: K_T n^2 D^4 = (k_0 n^2 + k_1 n u_P / D + k_2 u_P^2 / D^2) D^4, finite as n goes to 0
        d_p = self.d_p
        beta_p = beta - self.x_p * rr
        c_2 = self.c_2_plus if beta_p > 0.0 else self.c_2_minus
        u_p = u * (1.0 - self.w_p0) * (1.0 + (1.0 - math.exp(-self.c_1 * abs(beta_p))) * (c_2 - 1.0))
        ahead = n * n * self.k_0 + n * u_p * self.k_1 / d_p + u_p * u_p * self.k_2 / (d_p * d_p) if n > 0.0 else 0.0
        if n < 0.0:
            thrust = -rho * d_p**4 * (n * n * self.astern_kt[0] - n * u * (1.0 - self.w_p0) * self.astern_kt[1] / d_p)
        else:
            thrust = rho * d_p**4 * ahead
        x_p = (1.0 - self.t_p) * thrust
        # rudder: the inflow sped up by the propeller race (ahead only); 8 K_T / (pi J^2) = 8 K_T n^2 D^2 / (pi u_P^2)
        eta = d_p / self.h_r
        if n > 0.0 and u_p > 0.0:
            race = 1.0 + 8.0 * ahead * d_p * d_p / (math.pi * u_p * u_p)
            race = 1.0 + self.kappa * (math.sqrt(race) - 1.0) if race > 0.0 else 1.0 - self.kappa
            u_r = self.epsilon * u_p * math.sqrt(eta * race * race + 1.0 - eta)
        elif n > 0.0:
            # at rest or going astern with the propeller ahead: the race alone, momentum theory (J = 0)
            u_r = self.epsilon * math.sqrt(eta * self.kappa**2 * 8.0 * max(self.k_0, 0.0) / math.pi) * n * d_p
        else:
            u_r = self.epsilon * u_p
        beta_r = beta - self.l_r * rr
        gamma = self.gamma_r_starboard if beta_r > 0.0 else self.gamma_r_port
        v_r = speed * gamma * beta_r
        alpha_r = delta - math.atan2(v_r, u_r) if (u_r or v_r) else delta
        f_n = 0.5 * rho * self.a_r * (u_r * u_r + v_r * v_r) * self.f_alpha * math.sin(alpha_r)
        cos_d = math.cos(delta)
        x_r = -(1.0 - self.t_r) * f_n * math.sin(delta)
        y_r = -(1.0 + self.a_h) * f_n * cos_d
        n_r = -(self.x_r + self.a_h * self.x_h) * lpp * f_n * cos_d
        # motion
        x = x_h + x_p + x_r + more[0] + (mass + m_y) * v * r + self.x_g * mass * r * r
        y = y_h + y_r + more[1] - (mass + m_x) * u * r
        nn = n_h + n_r + more[2] - self.x_g * mass * u * r
        i11, i12, i22 = self._inverse
        return x / (mass + m_x), i11 * y + i12 * nn, i12 * y + i22 * nn, 0.0
