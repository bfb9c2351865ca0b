"""The container ship of Son & Nomoto (1981, 1982), 4 DOF (surge, sway, yaw, roll): the S175 hull, as
Fossen's MSS toolbox carries it (``container.m``, MIT, L = 175 m).

Axes and signs as :mod:`marinesim.manoeuvring.state`. Non-dimensional by the present speed ``U``: ``u' = u /
U``, ``v' = v / U``, ``r' = r L / U``, ``p' = p L / U``, ``n' = n L / U``; forces by ``(rho/2) L^2 U^2``, moments by
``(rho/2) L^3 U^2``, masses by ``(rho/2) L^3``, inertias by ``(rho/2) L^5``. Hull forces are the published
polynomials in ``v', r', p', phi``; the propeller ``J = u_P U / (n D)``, ``K_T = 0.527 - 0.455 J``, ``u_P = u'
((1 - w_P) + tau ((v' + x_P r')^2 + c_pv v' + c_pr r'))``; the rudder ``F_N = -(6.13 Lambda / (Lambda + 2.25))
(A_R / L^2) (u_R^2 + v_R^2) sin(delta + atan2(v_R, u_R))`` (MSS's ``atan(v_R / u_R)`` round the circle: the
flow from aft going astern reverses the force) with ``u_R = epsilon u_P sqrt(1 + 8 k K_T / (pi
J^2))``, ``v_R = gamma v' + c_Rr r' + c_Rrrr r'^3 + c_Rrrv r'^2 v'``. The roll restoring moment is ``-W GM phi``
(linear: GM 0.3 m). Sway, roll and yaw accelerations come from the coupled mass matrix ``[[m + m_y, -m_y l_y,
m_y alpha_y], [-m_y l_y, I_x + J_x, 0], [m_y alpha_y, 0, I_z + J_z]]``. MSS's own rudder (10 deg, 5 deg/s)
and shaft lags are the steering gear's and the engine's here (:mod:`marinesim.manoeuvring.actuators`).
Astern (``n < 0``, outside the published model) the thrust is ``-rho n^2 D^4 (a_0 + a_1 J)`` with no race
over the rudder.

The coefficients are MSS's (``CRAFT/SHIP/models/container.m``, github.com/cybergalactic/MSS), copyright (c) 2004
Thor I. Fossen, MIT licence: the notice is in ``rao/LICENSE-MSS``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from marinesim.compiled import compiled

LENGTH_M = 175.0
RHO = 1025.0
G = 9.81
# Masses and inertias (by (rho/2) L^3, (rho/2) L^5), lever arms (by L)
M, MX, MY = 0.00792, 0.000238, 0.007049
IX, JX, IZ, JZ = 0.0000176, 0.0000034, 0.000456, 0.000419
ALPHA_Y, LX, LY = 0.05, 0.0313, 0.0313
NABLA, D_P, A_R, ASPECT = 21222.0, 6.533, 33.0376, 1.8219
T_P = 0.175
XUU, XVR, XRR, XPHIPHI, XVV = -0.0004226, -0.00311, 0.00020, -0.00020, -0.00386
KV, KR, KP, KPHI = 0.0003026, -0.000063, -0.0000075, -0.000021
KVVV, KRRR, KVVR, KVRR = 0.002843, -0.0000462, -0.000588, 0.0010565
KVVPHI, KVPHIPHI, KRRPHI, KRPHIPHI = -0.0012012, -0.0000793, -0.000243, 0.00003569
YV, YR, YP, YPHI = -0.0116, 0.00242, 0.0, -0.000063
YVVV, YRRR, YVVR, YVRR = -0.109, 0.00177, 0.0214, -0.0405
YVVPHI, YVPHIPHI, YRRPHI, YRPHIPHI = 0.04605, 0.00304, 0.009325, -0.001368
NV, NR, NP, NPHI = -0.0038545, -0.00222, 0.000213, -0.0001424
NVVV, NRRR, NVVR, NVRR = 0.001492, -0.00229, -0.0424, 0.00156
NVVPHI, NVPHIPHI, NRRPHI, NRPHIPHI = -0.019058, -0.0053766, -0.0038592, 0.0024195
KK, EPSILON, X_R, W_P, TAU, X_P = 0.631, 0.921, -0.5, 0.184, 1.09, -0.526
C_PV, C_PR, GAMMA = 0.0, 0.0, 0.088
C_RR, C_RRRR, C_RRRV = -0.156, -0.275, 1.96
C_RX, A_H, Z_R, X_H = 0.71, 0.237, 0.033, -0.48
MIN_SPEED = 0.5
"""The speed (m/s) below which the model is evaluated at this speed: its scaling divides by U, and its rudder inflow
polynomial in ``r' = r L / U`` (fitted for a ship under way) would grow without bound as she stops."""


@dataclass(frozen=True)
class SonNomotoContainer:
    """The S175 container ship (MSS ``container.m``), its metacentric height ``gm_m`` (m, 0.3 as published) and
    its backing thrust ``astern_kt`` (a_0, a_1)."""

    gm_m: float = 0.3
    astern_kt: tuple[float, float] = (0.0, 0.0)
    label: str = field(default="Son & Nomoto, 4 DOF (heel)", init=False)
    dof: int = field(default=4, init=False)

    def __post_init__(self) -> None:
        m22, m32, m42, m33, m44 = M + MY, -MY * LY, MY * ALPHA_Y, IX + JX, IZ + JZ
        det = m22 * m33 * m44 - m32**2 * m44 - m42**2 * m33
        coefficients = np.array([self.gm_m, *self.astern_kt, m22, m32, m42, m33, m44, det])
        coefficients.flags.writeable = False
        object.__setattr__(self, "_coefficients", coefficients)

    @property
    def length_m(self) -> float:
        return LENGTH_M

    def accelerations(self, u: float, v: float, r: float, p: float, phi: float, delta: float, n: float
                      ) -> tuple[float, float, float, float]:
        """(du/dt, dv/dt, dr/dt, dp/dt) (m/s^2, rad/s^2) for ``u``, ``v`` (m/s), ``r``, ``p`` (rad/s), heel ``phi``,
        rudder ``delta`` (rad) and propeller ``n`` (rev/s)."""
        return _accelerations(self._coefficients, u, v, r, p, phi, delta, n)


@compiled
def _accelerations(c: np.ndarray, u: float, v: float, r: float, p: float, phi: float, delta: float, n: float
                   ) -> tuple[float, float, float, float]:
    """:meth:`SonNomotoContainer.accelerations` of the vessel of ``c`` (her metacentric height (m), the backing
    thrust's two coefficients, the mass matrix's five terms and its determinant), compiled."""
    gm_m, astern_0, astern_1, m22, m32, m42, m33, m44, det = c
    L = LENGTH_M
    speed = max(math.hypot(u, v), MIN_SPEED)
    u_, v_, r_, p_ = u / speed, v / speed, r * L / speed, p * L / speed
    w = RHO * G * NABLA / (RHO * L * L * speed * speed / 2.0)
    gm = gm_m / L
    u_p = u_ * ((1.0 - W_P) + TAU * ((v_ + X_P * r_) ** 2.0 + C_PV * v_ + C_PR * r_))
    v_r = GAMMA * v_ + C_RR * r_ + C_RRRR * r_**3.0 + C_RRRV * r_ * r_ * v_
    thrust_scale = 2.0 * D_P**4.0 / (speed * speed * L * L)
    if n > 0.0:
        # K_T n^2 = 0.527 n^2 - 0.455 n u_P U / D (J = u_P U / (n D)): finite as n goes to 0
        kt_n2 = 0.527 * n * n - 0.455 * n * u_p * speed / D_P
        thrust = thrust_scale * kt_n2
        # u_R = epsilon u_P sqrt(1 + 8 k K_T / (pi J^2)) = epsilon sqrt(u_P^2 + 8 k K_T n^2 D^2 / (pi U^2))
        u_r = EPSILON * math.sqrt(max(u_p * u_p + 8.0 * KK * kt_n2 * D_P * D_P / (math.pi * speed * speed), 0.0))
        u_r = -u_r if u_p < 0.0 else u_r
    elif n < 0.0:
        thrust = -thrust_scale * (n * n * astern_0 - n * u_p * speed * astern_1 / D_P)
        u_r = u_p * EPSILON
    else:
        thrust, u_r = 0.0, u_p * EPSILON
    # MSS's atan(v_R / u_R), taken round the circle: a flow from aft (going astern) reverses the rudder's force
    alpha_r = delta + math.atan2(v_r, u_r)
    f_n = -((6.13 * ASPECT) / (ASPECT + 2.25)) * (A_R / L**2.0) * (u_r * u_r + v_r * v_r) * math.sin(alpha_r)
    cos_d = math.cos(delta)
    x = (XUU * u_ * abs(u_) + (1.0 - T_P) * thrust + XVR * v_ * r_ + XVV * v_ * v_ + XRR * r_ * r_
         + XPHIPHI * phi * phi + C_RX * f_n * math.sin(delta) + (M + MY) * v_ * r_)
    y = (YV * v_ + YR * r_ + YP * p_ + YPHI * phi + YVVV * v_**3.0 + YRRR * r_**3.0 + YVVR * v_ * v_ * r_
         + YVRR * v_ * r_ * r_ + YVVPHI * v_ * v_ * phi + YVPHIPHI * v_ * phi * phi + YRRPHI * r_ * r_ * phi
         + YRPHIPHI * r_ * phi * phi + (1.0 + A_H) * f_n * cos_d - (M + MX) * u_ * r_)
    k = (KV * v_ + KR * r_ + KP * p_ + KPHI * phi + KVVV * v_**3.0 + KRRR * r_**3.0 + KVVR * v_ * v_ * r_
         + KVRR * v_ * r_ * r_ + KVVPHI * v_ * v_ * phi + KVPHIPHI * v_ * phi * phi + KRRPHI * r_ * r_ * phi
         + KRPHIPHI * r_ * phi * phi - (1.0 + A_H) * Z_R * f_n * cos_d + MX * LX * u_ * r_ - w * gm * phi)
    nn = (NV * v_ + NR * r_ + NP * p_ + NPHI * phi + NVVV * v_**3.0 + NRRR * r_**3.0 + NVVR * v_ * v_ * r_
          + NVRR * v_ * r_ * r_ + NVVPHI * v_ * v_ * phi + NVPHIPHI * v_ * phi * phi + NRRPHI * r_ * r_ * phi
          + NRPHIPHI * r_ * phi * phi + (X_R + A_H * X_H) * f_n * cos_d)
    a = speed * speed / L
    return (x * a / (M + MX),
            -((-m33 * m44 * y + m32 * m44 * k + m42 * m33 * nn) / det) * a,
            ((-m42 * m33 * y + m32 * m42 * k + nn * m22 * m33 - nn * m32**2.0) / det) * a / L,
            ((-m32 * m44 * y + k * m22 * m44 - k * m42**2.0 + m32 * m42 * nn) / det) * a / L)
