"""A vessel keeping station under the weather: her low-frequency motion in the horizontal plane, on dynamic
positioning or moorings.

Axes as :mod:`marinesim.manoeuvring.state` (north, east, psi clockwise from north; body x forward, y to
starboard). The low-frequency equations (Fossen 2021, ch. 6 and 10)::

    eta' = R(psi) nu,    M nu' + D (nu - nu_c) = tau_thrusters + tau_environment + tau_moorings

``M`` the mass with the low-frequency added mass, ``D`` the linear damping (3, 3), ``nu_c`` the current in body
axes (the hull feels the water's velocity relative to her: the current's load is ``D nu_c``), ``tau_environment``
the wind's and the waves' second-order loads (:class:`Environment`). The wave-frequency motion is the RAO
response's, added on top by the session: it reaches the DP only through the measured position.

Stepped like any ship by :class:`~marinesim.manoeuvring.voyage.Voyage`: the vessel's states by the classical
Runge-Kutta step, the thrusters' forces (first-order lags) exact over it, the DP computer (:mod:`.dp`) once per
step with its demand held over the step (zero-order hold, as a DP computer's cycle). Her ``extra`` states:
:data:`EXTRA` then one per virtual thruster force.

Instructor faults (``Orders.faults``): ``thruster:NAME`` lost; ``drive-off:NAME`` stuck at full thrust along its
own axis (ahead for a main propeller or an azimuth, to starboard for a tunnel thruster); ``reference drift``, the
position reference drifting north at :data:`REFERENCE_DRIFT_M_S`; ``line:NAME`` a mooring line parted.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Protocol

import numpy as np

from marinesim.compiled import compiled, read_only
from marinesim.errors import ParameterError, require_within
from marinesim.manoeuvring.autopilot import wrap
from marinesim.manoeuvring.state import Orders, ShipState
from marinesim.station.dp import Dp, rotation
from marinesim.station.moorings import Moorings, moorings_force
from marinesim.station.thrusters import Thrusters
from marinesim.station.wind import WindLoads, wind_load_at

EXTRA = ("z_north", "z_east", "z_psi", "xi1_north", "xi1_east", "xi1_psi", "xi2_north", "xi2_east", "xi2_psi",
         "eta_north", "eta_east", "eta_psi", "nu_u", "nu_v", "nu_r", "b_north", "b_east", "b_psi",
         "ref_north", "ref_east", "ref_psi", "drift_north", "drift_east", "ff_x", "ff_y", "ff_n")
"""The DP computer's states kept in ``ShipState.extra``: the error's integral (m s, m s, rad s), the observer's
(wave model, estimated position and velocity, bias: :meth:`Dp.observe`), the set point the reference model has
reached, the position reference's drift (m, a fault) and the wind feed-forward (N, N, N m: the wind sensor's
load, filtered over :data:`WIND_FILTER_S`); then the virtual thrust forces (N)."""


def _span(first: str, last: str) -> slice:
    return slice(EXTRA.index(first), EXTRA.index(last) + 1)


INTEGRAL, OBSERVER, BIAS = _span("z_north", "z_psi"), _span("xi1_north", "b_psi"), _span("b_north", "b_psi")
SET_POINT, REFERENCE_DRIFT = _span("ref_north", "ref_psi"), _span("drift_north", "drift_east")
FEED_FORWARD = _span("ff_x", "ff_n")
"""Where the DP computer's states lie in ``extra``: the observer's in :meth:`Dp.observe`'s order."""
WIND_FILTER_S = 10.0
"""The DP's wind feed-forward follows the measured wind's load with this time constant (s): a gust shorter than
it moves her before her thrusters answer, as on a real DP."""
REFERENCE_DRIFT_M_S = 0.05
"""How fast a drifting position reference walks off (m/s, north): 3 m a minute, as a DGNSS losing its
corrections."""
FAULTS = ("thruster:NAME", "drive-off:NAME", "reference drift", "line:NAME")


class Environment(Protocol):
    """What the weather does to a vessel at ``t`` (s), she at (north, east, psi) moving at (u, v, r)."""

    def wind_load(self, t: float, psi: float, u: float, v: float) -> np.ndarray:
        """The wind's load alone (3,): what the DP's wind sensor and the vessel's coefficients make of it."""

    wind_loads: WindLoads | None
    """The vessel's wind loads (None: no wind)."""

    def wind(self, t: float) -> tuple[float, float]:
        """The wind at 10 m (m/s, from rad clockwise from north) at ``t``, gusts and all."""

    def drift(self, t: float, psi: float) -> np.ndarray:
        """The waves' second-order load alone (X N, Y N, N N m; body axes), (3,), on heading ``psi`` (rad)."""

    def current(self, t: float) -> tuple[float, float]:
        """The current (north m/s, east m/s) at ``t``."""

    def wave_motion(self, t: float) -> tuple[float, float, float]:
        """The wave-frequency motion of the vessel's origin (north m, east m, psi rad) at ``t``: in her measured
        position."""


class Calm:
    """No wind, no current, no waves."""

    wind_loads = None

    def wind_load(self, t: float, psi: float, u: float, v: float) -> np.ndarray:
        return np.zeros(3)

    def wind(self, t: float) -> tuple[float, float]:
        return 0.0, 0.0

    def drift(self, t: float, psi: float) -> np.ndarray:
        return np.zeros(3)

    def current(self, t: float) -> tuple[float, float]:
        return 0.0, 0.0

    def wave_motion(self, t: float) -> tuple[float, float, float]:
        return 0.0, 0.0, 0.0


@dataclass(frozen=True)
class Station:
    """``name`` with low-frequency mass ``m`` and damping ``d`` (3, 3; body axes, about her origin) under
    ``environment``; on DP (``thrusters`` and ``dp``) or moored (``moorings``), or both."""

    name: str
    m: np.ndarray
    d: np.ndarray
    environment: Environment
    thrusters: Thrusters | None = None
    dp: Dp | None = None
    moorings: Moorings | None = None
    pull: float = 0.0
    """A constant thrust astern along her own axis (N) on moorings: a shuttle tanker keeping her hawser taut."""
    turn_about: str | None = None
    """On DP with moorings: the line about whose far end her heading orders turn her (a shuttle tanker's DP in its
    tandem mode, weathervaning about the FPSO's stern: her hawser's fixed point keeps its place in her body frame);
    None: she turns about her origin. Either way her DP holds against her lines through its integral and bias."""
    kind = "station"

    def __post_init__(self) -> None:
        if (self.thrusters is None) != (self.dp is None):
            raise ParameterError(f"{self.name}: dynamic positioning needs both thrusters and a DP computer")
        if self.thrusters is None and self.moorings is None:
            raise ParameterError(f"{self.name}: a vessel keeping station needs thrusters (DP) or moorings")
        if self.turn_about is not None and (self.dp is None or self.moorings is None
                                            or self.turn_about not in self.moorings.names):
            raise ParameterError(f"{self.name}: turning about line {self.turn_about!r} needs DP and moorings with "
                                 f"that line")
        object.__setattr__(self, "_pivot", None if self.turn_about is None else self._pivot_of(self.turn_about))
        object.__setattr__(self, "_m_inv", np.linalg.inv(np.asarray(self.m, float)))
        object.__setattr__(self, "_d", np.asarray(self.d, float))

    def _pivot_of(self, line: str) -> tuple[float, float, float, float]:
        """Line ``line``'s far end (north m, east m from the set point) and where it lies in her body frame on her
        set point (x m forward, y m to starboard)."""
        north, east = self.moorings.lines[self.moorings.names.index(line)].anchor
        c, s = math.cos(self.moorings.heading), math.sin(self.moorings.heading)
        return north, east, north * c + east * s, -north * s + east * c

    @property
    def label(self) -> str:
        """One word for the conning strip."""
        return "DP" if self.dp is not None else "MOORED"

    def describe(self) -> str:
        if self.dp is not None:
            return (f"on dynamic positioning: {len(self.thrusters.units)} thrusters"
                    + (" and moorings" if self.moorings is not None else ""))
        return "moored: held by her lines"

    # -- orders ---------------------------------------------------------------------------------

    def start(self, speed: float, psi: float) -> tuple[ShipState, Orders]:
        """Her state and orders at rest on heading ``psi`` (rad, clockwise from north), the set point where she is.
        On DP she starts settled, as a trainee takes her over: the thrusters already balance the weather of the
        start (wind, current, waves' drift and her lines' pull), the observer's bias and the controller's integral
        already hold it (the wind's share is the feed-forward's)."""
        if speed > 0.0:
            raise ParameterError(f"{self.name} keeps station: she has no speed")
        extra = np.zeros(len(EXTRA) + (self.thrusters.width if self.thrusters is not None else 0))
        extra[EXTRA.index("eta_psi")] = extra[EXTRA.index("ref_psi")] = psi
        if self.dp is not None:
            self.thrusters.forget()
            env = self.environment
            current = np.asarray(self.d, float) @ np.array([*_in_body(*env.current(0.0), psi), 0.0])
            wind = env.wind_load(0.0, psi, 0.0, 0.0)
            load = wind + env.drift(0.0, psi) + current
            if self.moorings is not None:
                load = load + self.moorings.force(0.0, 0.0, psi)
            turn = rotation(psi)
            extra[BIAS] = turn @ load
            extra[INTEGRAL] = turn @ (load - wind) / self.dp.ki
            extra[FEED_FORWARD] = wind
            extra[len(EXTRA):] = self.thrusters.allocate(-load)
        return ShipState(psi=psi, extra=tuple(extra.tolist())), Orders(autopilot=self.dp is not None, course=psi,
                                                                       engine=self.label.lower())

    def order(self, orders: Orders, state: ShipState, *, rudder_deg: float | None = None, engine: str | None = None,
              speed_kn: float | None = None, autopilot: bool | None = None, course_deg: float | None = None,
              set_north_m: float | None = None, set_east_m: float | None = None,
              fault: str | None = None) -> Orders:
        """A heading (``course_deg``, compass) or position (``set_north_m``, ``set_east_m``: m from the start) set
        point for the DP, or an instructor's ``fault`` (:data:`FAULTS`); helm and engine orders are refused."""
        if any(o is not None for o in (rudder_deg, engine, speed_kn, autopilot)):
            raise ParameterError(f"{self.name}: {self.describe()}; she takes set points, not helm or engine orders")
        if self.turn_about is not None and (set_north_m is not None or set_east_m is not None):
            raise ParameterError(f"{self.name} turns about line {self.turn_about}'s far end: she takes heading set "
                                 f"points, her position follows from them")
        new = orders
        if (course_deg is not None or set_north_m is not None or set_east_m is not None) and self.dp is None:
            raise ParameterError(f"{self.name} is moored: she takes no set points")
        if course_deg is not None:
            new = replace(new, course=math.radians(require_within("course", course_deg, 0.0, 360.0, "deg") % 360.0))
        if set_north_m is not None:
            new = replace(new, north=require_within("set point north", set_north_m, -500.0, 500.0, "m"))
        if set_east_m is not None:
            new = replace(new, east=require_within("set point east", set_east_m, -500.0, 500.0, "m"))
        if fault is not None:
            new = replace(new, faults=new.faults | {self._fault(fault)})
        return new

    def _fault(self, fault: str) -> str:
        kind, _, name = fault.partition(":")
        if kind in ("thruster", "drive-off") and self.thrusters is not None:
            self.thrusters.index(name)
            return fault
        if fault == "reference drift" and self.dp is not None:
            return fault
        if kind == "line" and self.moorings is not None:
            self.moorings.with_failed(name)
            return fault
        raise ParameterError(f"fault {fault!r}: {self.name} can have "
                             + ", ".join(f for f in FAULTS if self._offers(f)))

    def _offers(self, fault: str) -> bool:
        if fault.startswith(("thruster", "drive-off", "reference")):
            return self.dp is not None
        return self.moorings is not None

    # -- stepping -------------------------------------------------------------------------------

    def step(self, s: ShipState, orders: Orders, h: float, t: float = 0.0) -> tuple[ShipState, tuple[float, ...]]:
        """The state ``h`` s after ``s`` (at ``t`` s) under ``orders``, and the derivatives of (north, east, psi,
        u, v, r, p, phi) at ``s``. What does not hang on her state is taken at the stages' times (start, middle, end
        of the step) and handed to the compiled stages (:func:`_runge_kutta`): the thrusters' forces (their lags
        exact over the step), the current, the wind, and the waves' drift on her heading at the step's start (at a
        DP's fastest turn, 10 deg/min, she turns 0.017 deg in a 0.1 s step; the drift's heading is rounded to 0.1
        deg)."""
        extra = np.array(s.extra)
        n_dp = len(EXTRA)
        lines = self._lines(orders.faults)
        f_now = extra[n_dp:]
        f_order, lag = f_now, None
        if self.dp is not None:
            f_order, lag, extra[:n_dp] = self._dp_cycle(s, orders, extra[:n_dp], f_now, h, t)
        env = self.environment
        times = (t, t + 0.5 * h, t + h)
        thrusts = np.zeros((3, 3))
        if lag is not None:
            extra[n_dp:] = _lagged(f_order, f_now, lag, self.thrusters.b, h, thrusts)
        y, k1 = _runge_kutta(np.array([s.north, s.east, s.psi, s.u, s.v, s.r], dtype=float), float(h), thrusts,
                             np.array([env.current(at) for at in times], dtype=float),
                             np.array([env.wind(at) for at in times], dtype=float),
                             np.array([env.drift(at, s.psi) for at in times], dtype=float), float(self.pull),
                             self._m_inv, self._d,
                             *(_NO_WIND if env.wind_loads is None else env.wind_loads.packed),
                             *(_NO_LINES if lines is None else lines.packed))
        after = ShipState(*y.tolist(), r_ref=0.0, extra=tuple(extra.tolist()))
        return after, (*k1.tolist(), 0.0, 0.0)

    def _dp_cycle(self, s: ShipState, orders: Orders, dp: np.ndarray, f_now: np.ndarray, h: float, t: float
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """One cycle of the DP computer at ``t``: (the thrusters' orders (m,), their time constants (m,), its
        states ``h`` s on (len(EXTRA),))."""
        computer, thrusters, env = self.dp, self.thrusters, self.environment
        z, est, ref, drift, feed = dp[INTEGRAL], dp[OBSERVER], dp[SET_POINT], dp[REFERENCE_DRIFT], dp[FEED_FORWARD]
        wave = env.wave_motion(t)
        measured = np.array([s.north + wave[0] + drift[0], s.east + wave[1] + drift[1], s.psi + wave[2]])
        tau = computer.command(est, ref, z, feed)
        lost = frozenset(f.partition(":")[2] for f in orders.faults if f.startswith("thruster:"))
        stuck = {name: thrusters.stuck(name)
                 for name in (f.partition(":")[2] for f in orders.faults if f.startswith("drive-off:"))}
        f_order = thrusters.allocate(tau, lost - stuck.keys(), stuck)
        saturated = _short(thrusters.b, f_order, tau)
        out = dp.copy()
        out[OBSERVER] = computer.observe(est, measured, thrusters.b @ f_now, h)
        if not saturated:
            out[INTEGRAL] = z + h * computer.error(est, ref)
        course = _unwrapped(orders.course, ref[2])
        out[SET_POINT] = (computer.reference(ref, (orders.north, orders.east, course), h) if self._pivot is None
                          else computer.reference_about(ref, self._pivot, course, h))
        if "reference drift" in orders.faults:
            out[REFERENCE_DRIFT.start] = drift[0] + REFERENCE_DRIFT_M_S * h
        out[FEED_FORWARD] = feed + (env.wind_load(t, s.psi, s.u, s.v) - feed) * (1.0 - math.exp(-h / WIND_FILTER_S))
        return f_order, thrusters.lag(), out

    def _lines(self, faults: frozenset[str]) -> Moorings | None:
        """Her moorings less the lines parted by ``faults``."""
        if self.moorings is None:
            return None
        return self.moorings.with_failed(*(f.partition(":")[2] for f in faults if f.startswith("line:")))

    @property
    def line_names(self) -> tuple[str, ...]:
        return () if self.moorings is None else self.moorings.names

    @property
    def unit_faults(self) -> tuple[str, ...]:
        """The faults an instructor fails one unit with, in order: each thruster lost (DP), else each line parted."""
        if self.thrusters is not None:
            return tuple(f"thruster:{unit.name}" for unit in self.thrusters.units)
        return tuple(f"line:{name}" for name in self.line_names)

    def line_tensions(self, s: ShipState, faults: frozenset[str]) -> np.ndarray:
        """Each mooring line's fairlead tension (N, (n_lines,)) in state ``s`` with ``faults``."""
        return self._lines(faults).tensions(s.north, s.east, s.psi)

    def settled(self, s: ShipState, orders: Orders, rates: tuple[float, ...]) -> bool:
        """Never: the weather keeps working on her."""
        return False

    # -- what she shows -------------------------------------------------------------------------

    def thruster_use(self, extra: np.ndarray) -> np.ndarray:
        """Each thruster's thrust as a fraction of its rating, (T, n) from her ``extra`` states (T, len(extra))."""
        if self.thrusters is None:
            return np.zeros((len(extra), 0))
        return np.array([self.thrusters.use(row[len(EXTRA):]) for row in np.atleast_2d(extra)])

    def set_point(self, extra: np.ndarray) -> np.ndarray:
        """The set point the reference model has reached (T, 3: north m, east m, psi rad) from ``extra`` (T, k)."""
        extra = np.atleast_2d(extra)
        if self.dp is None:
            return np.zeros((len(extra), 3))
        return extra[:, SET_POINT]


_NO_WIND = (*read_only(np.empty(0), np.empty(0), np.empty((3, 0))), 1.0, 1.0, 1.0, 1.0)
"""No wind loads, packed as :attr:`WindLoads.packed` for :func:`_runge_kutta`."""
_NO_LINES = read_only(np.empty((0, 4)), np.empty((0, 13)), np.empty((0, 8)), np.empty(0, dtype=np.int64),
                       np.empty(0))
"""No mooring lines, packed as :attr:`Moorings.packed`."""


@compiled
def _lagged(f_order: np.ndarray, f_now: np.ndarray, lag: np.ndarray, b: np.ndarray, h: float, thrusts: np.ndarray
            ) -> np.ndarray:
    """The virtual forces (m,) ``h`` s on from ``f_now`` following their orders ``f_order`` with time constants
    ``lag`` (s), exactly (first order); their force (X N, Y N, N N m) at the step's start, middle and end into
    ``thrusts`` (3, 3) through ``b`` (3, m)."""
    for stage in range(3):
        f = f_order + (f_now - f_order) * np.exp(-(0.5 * h * stage) / lag)
        for i in range(3):
            thrusts[stage, i] = 0.0
            for j in range(f.size):
                thrusts[stage, i] += b[i, j] * f[j]
    return f_order + (f_now - f_order) * np.exp(-h / lag)


@compiled
def _short(b: np.ndarray, f: np.ndarray, tau: np.ndarray) -> bool:
    """Whether the virtual forces ``f`` (m,) through ``b`` (3, m) fall short of the demand ``tau`` (3,): a component
    off by more than 1e-3 of the demand's largest and 1 N (the thrusters saturate)."""
    slack = 1e-3 * max(abs(tau[0]), abs(tau[1]), abs(tau[2])) + 1.0
    for i in range(3):
        given = 0.0
        for j in range(f.size):
            given += b[i, j] * f[j]
        if abs(given - tau[i]) > slack:
            return True
    return False


@compiled
def _runge_kutta(y0: np.ndarray, h: float, thrusts: np.ndarray, current: np.ndarray, wind: np.ndarray,
                 drift: np.ndarray, pull: float, m_inv: np.ndarray, d: np.ndarray, params: np.ndarray,
                 angles: np.ndarray, table: np.ndarray, frontal_area: float, lateral_area: float, length: float,
                 rho_air: float, ends_at: np.ndarray, lines: np.ndarray, pieces: np.ndarray, first: np.ndarray,
                 intact: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The classical Runge-Kutta step of (north, east, psi, u, v, r) from ``y0`` (6,) over ``h`` (s), and the
    derivatives at ``y0`` (6,). At the stages' times (start, middle, end; rows of (3, k)): the thrusters' force
    ``thrusts`` (N, N, N m), the ``current`` (north, east m/s), the ``wind`` (m/s, from rad) and the waves'
    ``drift`` (N, N, N m); ``pull`` (N) astern; the wind loads and the lines packed as :attr:`WindLoads.packed`
    and :attr:`Moorings.packed` (none: empty)."""
    with_wind = params.size + angles.size > 0

    def rates(stage: int, y: np.ndarray) -> np.ndarray:
        north, east, psi, u, v, r = y[0], y[1], y[2], y[3], y[4], y[5]
        c, s = math.cos(psi), math.sin(psi)
        u_c, v_c = _in_body(current[stage, 0], current[stage, 1], psi)
        relative = (u - u_c, v - v_c, r)  # through the water
        load = (0.0, 0.0, 0.0)
        if with_wind and not wind[stage, 0] <= 0.0:  # as Weather.wind_load: a NaN wind gives a NaN load
            load = wind_load_at(u, v, psi, wind[stage, 0], wind[stage, 1], params, angles, table, frontal_area,
                                lateral_area, length, rho_air)
        force = np.empty(3)
        for i in range(3):
            force[i] = thrusts[stage, i] + (load[i] + drift[stage, i]) - (
                d[i, 0] * relative[0] + d[i, 1] * relative[1] + d[i, 2] * relative[2])
        if pull:
            force[0] -= pull
        if ends_at.shape[0]:
            x, y_, n = moorings_force(north, east, psi, ends_at, lines, pieces, first, intact)
            force[0] += x
            force[1] += y_
            force[2] += n
        out = np.empty(6)
        out[0], out[1], out[2] = u * c - v * s, u * s + v * c, r
        for i in range(3):
            out[3 + i] = m_inv[i, 0] * force[0] + m_inv[i, 1] * force[1] + m_inv[i, 2] * force[2]
        return out

    k1 = rates(0, y0)
    k2 = rates(1, y0 + 0.5 * h * k1)
    k3 = rates(1, y0 + 0.5 * h * k2)
    k4 = rates(2, y0 + h * k3)
    return y0 + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4), k1


@compiled
def _in_body(north: float, east: float, psi: float) -> tuple[float, float]:
    """A current (``north``, ``east`` m/s) in body axes on heading ``psi`` (rad): (u_c, v_c) m/s."""
    c, s = math.cos(psi), math.sin(psi)
    return north * c + east * s, east * c - north * s


def _unwrapped(course: float, near: float) -> float:
    """``course`` (rad) as the angle nearest ``near``: the reference model turns the short way."""
    return near + wrap(course - near)
