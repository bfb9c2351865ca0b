"""An offshore crane on a moving vessel and its load: a point mass on an elastic, tension-only wire hanging from the
boom tip (a spherical pendulum whose wire stretches and goes slack), and its landing on a deck that heaves.

Frames as CONVENTIONS: the crane is given in the body frame (x forward, y port, z up; its heights taken above the
water, the body origin on the waterline), the load moves in the Earth frame E (x east, y north, z up, m). The load is
a point: the hook, the rigging and the load's bottom are one point at the end of the wire (the rigging's height
belongs in the wire length); air and sea drag on it are not modelled. The wire's tension is
``T = EA/L max(d - L, 0) + c (d - L)'`` while stretched, never below 0 (a wire does not push), with ``d`` the
tip-to-load distance, ``L`` the unstretched length paid out and ``c = 2 zeta sqrt(EA/L m)`` (``zeta`` the axial
mode's damping ratio). A landing spot is a horizontal deck plane at the height it gives, everywhere under the load;
it pushes up only (``N = k_c p + c_c p'`` for a penetration ``p > 0``, never below 0; no friction), with a stiffness
that makes the load's contact period :data:`CONTACT_STEPS` steps and a damping ratio :data:`CONTACT_DAMPING`.

The load is stepped on a fixed grid ``k h`` from t = 0 by velocity Verlet (kick-drift-kick; the damping forces take
the velocity predicted at the step's end), ``h`` a power of two of seconds, at most :data:`MAX_STEP_S`, and at most a
:data:`STEPS_PER_PERIOD` th of the wire's axial period ``2 pi sqrt(m L / EA)`` at the crane's shortest wire. Orders
(:meth:`Lift.hoist`, :meth:`Lift.slew`) given at ``t`` act from step ``ceil(t / h)`` on, and an order drops what was
computed past that step, so the motion at any time is a function of the orders alone, whatever was asked before and
in what order. The steps are computed ahead in blocks of :data:`BLOCK_STEPS`, the vessel's motion asked for one
block at a time; only :data:`BLOCKS_KEPT` blocks are held, an older one is stepped again from its first state when
asked for, to the same bits. Between steps the load's position and velocity are cubic Hermite interpolants of the
steps' positions, velocities and accelerations.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from marinesim.constants import G
from marinesim.errors import ParameterError, require_at_least, require_finite, require_positive, require_within

TipMotion = Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]
"""``tip_motion(times (n,), points (n, 3)) -> (positions (n, 3), velocities (n, 3))``: where the body-frame points
(m) are in the E frame at those times (m, m/s), row by row (a row's answer depends on that row alone)."""
Spot = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]
"""``spot(times (n,)) -> (z (n,), z_dot (n,))``: the landing deck's height (m, E frame) and its vertical velocity
(m/s), row by row."""

STEPS_PER_PERIOD = 20
"""Steps per axial period of the wire at its shortest."""
MAX_STEP_S = 2.0 ** -7
"""The longest step (7.8 ms)."""
MIN_STEP_S = 2.0 ** -10
"""The shortest step a lift may need (0.98 ms); a stiffer wire or a lighter load is refused."""
CONTACT_STEPS = 20
"""The load's period on the deck's contact spring, in steps."""
CONTACT_DAMPING = 0.5
"""The deck contact's damping ratio (of the load on the contact spring)."""
BLOCK_STEPS = 4096
"""Steps per block."""
BLOCKS_KEPT = 16
"""Blocks held in memory (some 5 MB); older ones are stepped again when asked for."""
SAMPLED = ("load_x_m", "load_y_m", "load_z_m", "load_vx_m_s", "load_vy_m_s", "load_vz_m_s", "tip_x_m", "tip_y_m",
           "tip_z_m", "tip_vx_m_s", "tip_vy_m_s", "tip_vz_m_s", "wire_length_m", "slew_deg", "tension_kn", "swing_deg",
           "slack", "deck_force_kn", "load_above_spot_m", "relative_velocity_m_s", "landed")
"""What :meth:`Lift.sample` gives."""


@dataclass(frozen=True, kw_only=True)
class Crane:
    """A pedestal crane of fixed outreach: the top of its pedestal ``pedestal_m`` (body frame, m, z above the
    waterline), its boom tip ``boom_height_m`` above that and ``radius_m`` out from the slew axis, slewed
    ``slew_deg`` (deg, 0 forward, positive to port: counter-clockwise seen from above) at the start. It hoists and
    lowers at up to ``hoist_speed_m_s``, slews at up to ``slew_rate_deg_s`` (deg/s), and pays out between
    ``min_wire_m`` and ``max_wire_m`` of wire. ``load_chart``: (radius m, safe working load t) pairs, radius
    increasing; the SWL is linear between them and the crane does not work outside their radii."""

    pedestal_m: tuple[float, float, float]
    boom_height_m: float
    radius_m: float
    slew_deg: float = 0.0
    hoist_speed_m_s: float
    slew_rate_deg_s: float
    max_wire_m: float
    min_wire_m: float = 0.5
    load_chart: tuple[tuple[float, float], ...]

    def __post_init__(self) -> None:
        pedestal = tuple(np.asarray(self.pedestal_m, dtype=float).ravel().tolist())
        if len(pedestal) != 3 or not all(math.isfinite(v) for v in pedestal):
            raise ParameterError(f"crane pedestal_m must be 3 finite numbers (x, y, z m, body frame), got "
                                 f"{self.pedestal_m!r}")
        object.__setattr__(self, "pedestal_m", pedestal)
        require_positive("crane boom_height_m", self.boom_height_m)
        require_at_least("crane radius_m", self.radius_m, 0.0)
        require_finite("crane slew_deg", self.slew_deg)
        require_positive("crane hoist_speed_m_s", self.hoist_speed_m_s)
        require_positive("crane slew_rate_deg_s", self.slew_rate_deg_s)
        require_positive("crane min_wire_m", self.min_wire_m)
        require_at_least("crane max_wire_m", self.max_wire_m, self.min_wire_m)
        chart = np.asarray(self.load_chart, dtype=float)
        if (chart.ndim != 2 or chart.shape[1] != 2 or not len(chart) or not np.all(np.isfinite(chart))
                or np.any(chart[:, 0] < 0.0) or np.any(np.diff(chart[:, 0]) <= 0.0) or np.any(chart[:, 1] <= 0.0)):
            raise ParameterError("crane load_chart must be (radius m, safe working load t) pairs, radii >= 0 and "
                                 f"increasing, loads > 0, got {self.load_chart!r}")
        object.__setattr__(self, "load_chart", tuple((float(r), float(t)) for r, t in chart))

    def tip(self, slew_deg: float | np.ndarray) -> np.ndarray:
        """The boom tip (body frame, m) slewed to ``slew_deg`` (deg): (3,) for one angle, (n, 3) for (n,)."""
        angle = np.radians(np.asarray(slew_deg, dtype=float))
        x, y, z = self.pedestal_m
        return np.stack([x + self.radius_m * np.cos(angle), y + self.radius_m * np.sin(angle),
                         np.full(angle.shape, z + self.boom_height_m)], axis=-1)

    def safe_working_load_t(self) -> float:
        """The chart's safe working load (t) at the crane's radius; refused outside the chart's radii."""
        radii, loads = np.array(self.load_chart).T
        if not radii[0] <= self.radius_m <= radii[-1]:
            raise ParameterError(f"crane radius_m {self.radius_m:g} m is outside its load chart "
                                 f"({radii[0]:g}..{radii[-1]:g} m)")
        return float(np.interp(self.radius_m, radii, loads))

    def check(self, load: Load, depth_m: float | None = None) -> None:
        """Refuse (:class:`ParameterError`) a ``load`` heavier than the chart's SWL at the crane's radius, a radius
        outside the chart, and, in water ``depth_m`` deep (m; None: deep water), a ``max_wire_m`` longer than from the
        tip (its body-frame height taken above the water) down to the sea floor."""
        swl = self.safe_working_load_t()
        tonnes = load.mass_kg / 1000.0
        if tonnes > swl:
            raise ParameterError(f"load {tonnes:.1f} t exceeds the crane's safe working load {swl:.1f} t at radius "
                                 f"{self.radius_m:.1f} m")
        if depth_m is not None:
            depth = require_positive("depth_m", depth_m)
            height = self.pedestal_m[2] + self.boom_height_m
            if self.max_wire_m > height + depth:
                raise ParameterError(f"crane max_wire_m {self.max_wire_m:g} m reaches below the sea floor: the tip is "
                                     f"{height:g} m above the water in {depth:g} m of water ({height + depth:g} m)")


@dataclass(frozen=True, kw_only=True)
class Load:
    """A load of ``mass_kg`` on a wire of axial stiffness ``wire_ea_n`` (EA, N; the default a 40 mm steel wire rope)
    whose axial mode has the damping ratio ``damping_ratio``; the deck crew's tag lines damp its swing with the ratio
    ``swing_damping_ratio`` of the pendulum's mode: a horizontal force ``-2 zeta m sqrt(g / L) (v - v_tip)`` against
    its horizontal velocity relative to the boom tip (the lines are held from the vessel)."""

    mass_kg: float
    wire_ea_n: float = 1.0e8
    damping_ratio: float = 0.05
    swing_damping_ratio: float = 0.0

    def __post_init__(self) -> None:
        require_positive("load mass_kg", self.mass_kg)
        require_positive("load wire_ea_n", self.wire_ea_n)
        require_within("load damping_ratio", self.damping_ratio, 0.0, 1.0)
        require_within("load swing_damping_ratio", self.swing_damping_ratio, 0.0, 1.0)


class _Program:
    """A piecewise linear schedule ordered in steps: from step ``k`` on, the value runs on at ``rate`` per second
    from what it was there, clipped to ``low..high``."""

    def __init__(self, h: float, start: float, low: float, high: float) -> None:
        self.h, self.low, self.high = h, low, high
        self.orders: list[tuple[int, int, float]] = []
        """(step, the order it was given in, rate per s), in time order."""
        self.steps = np.zeros(1, dtype=np.int64)
        self.values = np.array([start])
        self.rates = np.zeros(1)

    def order(self, k: int, rate: float) -> None:
        """From step ``k`` on the value moves at ``rate`` per second (the last order given for a step counts)."""
        self.orders.append((k, len(self.orders), rate))
        self.orders.sort()
        steps, values, rates = [0], [float(self.values[0])], [0.0]
        for step, _, r in self.orders:
            if step != steps[-1]:  # the value there as :meth:`at` gives it
                values.append(min(max(values[-1] + rates[-1] * (step * self.h - steps[-1] * self.h), self.low),
                                  self.high))
                steps.append(step)
                rates.append(r)
            else:
                rates[-1] = r
        self.steps, self.values, self.rates = np.array(steps, dtype=np.int64), np.array(values), np.array(rates)

    def rate(self, k: int) -> float:
        """The rate ordered (per s) from step ``k`` on."""
        return float(self.rates[max(int(np.searchsorted(self.steps, k, side="right")) - 1, 0)])

    def at(self, times: np.ndarray, left: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The value at ``times`` (s) in the intervals after steps ``left`` (-1: the start, t = 0), and its rate (per
        s; 0 when clipped, and at the start, from which the orders act)."""
        i = np.maximum(np.searchsorted(self.steps, left, side="right") - 1, 0)
        rates = np.where(left < 0, 0.0, self.rates[i])
        raw = self.values[i] + rates * (times - self.steps[i] * self.h)
        inside = (raw > self.low) & (raw < self.high)
        return np.clip(raw, self.low, self.high), np.where(inside, rates, 0.0)


class Lift:
    """The ``load`` on ``crane``'s wire, ``wire_m`` paid out (unstretched, m) at the start, the vessel moving the crane
    as ``tip_motion`` says, over the landing deck ``spot`` (None: none) in water ``depth_m`` deep (None: deep).

    The load starts hanging at rest under the tip, moving with it (the tip's velocity at t = 0), the wire stretched
    by ``m g L / EA``. Refused (:class:`ParameterError`): what :meth:`Crane.check` refuses, a wire outside the
    crane's range, a start below the deck, and a wire so stiff for the load that its step would be below
    :data:`MIN_STEP_S`. ``step_s`` (s), ``contact_stiffness_n_m`` (N/m) and ``contact_damping_n_s_m`` (N s/m) are
    the choices made for it."""

    def __init__(self, crane: Crane, load: Load, wire_m: float, tip_motion: TipMotion, spot: Spot | None = None,
                 depth_m: float | None = None) -> None:
        wire, period = self.check(crane, load, wire_m, depth_m)
        m = load.mass_kg
        self.crane, self.load, self.tip_motion, self.spot = crane, load, tip_motion, spot
        self.step_s = h = math.ldexp(1.0, math.frexp(min(period / STEPS_PER_PERIOD, MAX_STEP_S))[1] - 1)
        self.contact_stiffness_n_m = m * (2.0 * math.pi / (CONTACT_STEPS * h)) ** 2
        self.contact_damping_n_s_m = 2.0 * CONTACT_DAMPING * math.sqrt(self.contact_stiffness_n_m * m)
        self._wire = _Program(h, wire, crane.min_wire_m, crane.max_wire_m)
        self._slew = _Program(h, float(crane.slew_deg), -math.inf, math.inf)
        zero = np.zeros(1)
        (tip,), (velocity,) = tip_motion(zero, crane.tip(np.array([crane.slew_deg])))
        deck = -math.inf if spot is None else float(spot(zero)[0][0])
        position = (tip[0], tip[1], tip[2] - wire - m * G / (load.wire_ea_n / wire))
        if position[2] < deck:
            raise ParameterError(f"wire_m {wire:g} m puts the load {deck - position[2]:.3g} m below the landing deck "
                                 f"at the start")
        self._starts: list[tuple[float, ...]] = [self._first(position, tuple(velocity), tuple(tip), wire, deck)]
        """The state (position, velocity, acceleration) at each block's first step, as far as computed."""
        self._blocks: OrderedDict[int, np.ndarray] = OrderedDict()
        """Blocks held ((BLOCK_STEPS + 1, 9) each: the states of its steps and of the next block's first), last
        used last."""

    @staticmethod
    def check(crane: Crane, load: Load, wire_m: float, depth_m: float | None = None) -> tuple[float, float]:
        """Refuse (:class:`ParameterError`) what :meth:`Crane.check` refuses, a wire outside the crane's range and a
        wire so stiff for the load that its step would be below :data:`MIN_STEP_S`; the wire (m) and the axial period
        at the shortest wire (s) otherwise."""
        crane.check(load, depth_m)
        wire = require_within("wire_m", wire_m, crane.min_wire_m, crane.max_wire_m, "m")
        m, ea = load.mass_kg, load.wire_ea_n
        period = 2.0 * math.pi * math.sqrt(m * crane.min_wire_m / ea)
        if period / STEPS_PER_PERIOD < MIN_STEP_S:
            shortest = ea / m * (MIN_STEP_S * STEPS_PER_PERIOD / (2.0 * math.pi)) ** 2
            raise ParameterError(f"crane min_wire_m {crane.min_wire_m:g} m is too short for a {m:g} kg load on a wire "
                                 f"of EA {ea:g} N (axial period {1e3 * period:.3g} ms, steps under "
                                 f"{1e3 * MIN_STEP_S:.3g} ms); give at least {shortest:.3g} m, or a softer wire")
        return wire, period

    # -- orders ---------------------------------------------------------------------------------

    def step_of(self, t: float) -> int:
        """The step from which an order given at ``t`` (s) acts."""
        return math.ceil(require_at_least("order time", t, 0.0) / self.step_s - 1e-9)

    def hoist(self, t: float, speed_m_s: float) -> None:
        """From ``t`` (s) hoist at ``speed_m_s`` (m/s; positive up: the wire shortens; negative lowers), clipped to
        the crane's hoist speed; the wire stops at the crane's shortest and longest."""
        limit = self.crane.hoist_speed_m_s
        self._order(self._wire, t, -float(np.clip(require_finite("hoist speed_m_s", speed_m_s), -limit, limit)))

    def slew(self, t: float, rate_deg_s: float) -> None:
        """From ``t`` (s) slew at ``rate_deg_s`` (deg/s, positive to port), clipped to the crane's slew rate."""
        limit = self.crane.slew_rate_deg_s
        self._order(self._slew, t, float(np.clip(require_finite("slew rate_deg_s", rate_deg_s), -limit, limit)))

    def ordered(self, t: float) -> tuple[float, float]:
        """The hoist (m/s, positive up) and slew (deg/s, positive to port) ordered at ``t`` (s)."""
        k = self.step_of(t)
        return -self._wire.rate(k), self._slew.rate(k)

    def changed(self, t: float) -> None:
        """The vessel's motion from ``t`` (s) on is not what it was (a sea change): what was computed after step
        :meth:`step_of` ``(t)`` is dropped and stepped again when asked for."""
        self._drop(self.step_of(t))

    def _order(self, program: _Program, t: float, rate: float) -> None:
        k = self.step_of(t)
        program.order(k, rate)
        self._drop(k)

    def _drop(self, k: int) -> None:
        first = k // BLOCK_STEPS  # its first state (step <= k) stays: what changes acts after step k
        del self._starts[first + 1:]
        for index in [b for b in self._blocks if b >= first]:
            del self._blocks[index]

    # -- stepping -------------------------------------------------------------------------------

    def _first(self, position: tuple, velocity: tuple, tip: tuple, wire: float, deck: float) -> tuple[float, ...]:
        """The state at t = 0: ``position`` and ``velocity`` (E, m, m/s), and the acceleration there (the tip at
        ``tip``, moving as the load, the wire ``wire`` m long and still, the deck at ``deck``, still)."""
        start = (*position, *velocity, 0.0, 0.0, 0.0)
        stiffness = self.load.wire_ea_n / wire
        damping = 2.0 * self.load.damping_ratio * math.sqrt(stiffness * self.load.mass_kg)
        (row,) = self._step(start, [(*tip, *velocity, wire, 0.0, stiffness, damping, deck, 0.0)], 0.0)
        return row

    def _forcing(self, b: int) -> list[tuple[float, ...]]:
        """What block ``b``'s steps need at each step after its first: the tip's position and velocity (E), the wire's
        length and rate, its stiffness EA/L and damping, the deck's height and vertical velocity."""
        h = self.step_s
        steps = np.arange(b * BLOCK_STEPS, (b + 1) * BLOCK_STEPS + 1)
        times = steps * h
        wire, _ = self._wire.at(times, steps - 1)
        rate = np.diff(wire) / h
        tip, tip_velocity = self._tip(times[1:], steps[:-1])
        stiffness = self.load.wire_ea_n / wire[1:]
        damping = 2.0 * self.load.damping_ratio * np.sqrt(stiffness * self.load.mass_kg)
        deck, deck_rate = self._deck(times[1:])
        columns = np.column_stack([tip, tip_velocity, wire[1:], rate, stiffness, damping, deck, deck_rate])
        return columns.tolist()

    def _tip(self, times: np.ndarray, left: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The boom tip's position and velocity (E, (n, 3)) at ``times`` in the intervals after steps ``left``: the
        vessel's motion of the slewed tip, plus the slew's own velocity (its body-frame vector turned into E as the
        difference of two points' positions, which a rigid motion gives exactly)."""
        angle, rate = self._slew.at(times, left)
        body = self.crane.tip(angle)
        if not np.any(rate):
            positions, velocities = self.tip_motion(times, body)
            return np.asarray(positions, dtype=float), np.asarray(velocities, dtype=float)
        turn = np.radians(angle)
        slewing = np.radians(rate)[:, None] * self.crane.radius_m * np.column_stack(
            [-np.sin(turn), np.cos(turn), np.zeros(turn.shape)])
        positions, velocities = self.tip_motion(np.concatenate([times, times]), np.vstack([body, body + slewing]))
        positions, velocities, n = np.asarray(positions, dtype=float), np.asarray(velocities, dtype=float), times.size
        return positions[:n], velocities[:n] + (positions[n:] - positions[:n])

    def _deck(self, times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if self.spot is None:
            return np.full(times.shape, -math.inf), np.zeros(times.shape)
        z, z_dot = self.spot(times)
        return np.asarray(z, dtype=float), np.asarray(z_dot, dtype=float)

    def _step(self, state: tuple[float, ...], forcing: list[tuple[float, ...]], h: float) -> list[tuple[float, ...]]:
        """The states after each step of ``h`` s from ``state`` (x, y, z, vx, vy, vz, ax, ay, az; E, SI), one per row
        of ``forcing`` (:meth:`_forcing`'s, at the step's end): velocity Verlet, the damping on the velocity
        predicted at the step's end. With ``h`` 0 the one row gives the acceleration at ``state``."""
        x, y, z, vx, vy, vz, ax, ay, az = state
        inverse_mass, kc, cc, g = 1.0 / self.load.mass_kg, self.contact_stiffness_n_m, self.contact_damping_n_s_m, G
        swing = 2.0 * self.load.swing_damping_ratio
        half = 0.5 * h
        out = []
        for tx, ty, tz, tvx, tvy, tvz, length, length_rate, stiffness, damping, deck, deck_rate in forcing:
            vx += half * ax
            vy += half * ay
            vz += half * az
            x += h * vx
            y += h * vy
            z += h * vz
            px, py, pz = vx + half * ax, vy + half * ay, vz + half * az
            dx, dy, dz = x - tx, y - ty, z - tz
            distance = math.sqrt(dx * dx + dy * dy + dz * dz)
            stretch = distance - length
            ax = ay = 0.0
            az = -g
            if stretch > 0.0:
                stretching = (dx * (px - tvx) + dy * (py - tvy) + dz * (pz - tvz)) / distance - length_rate
                tension = stiffness * stretch + damping * stretching
                if tension > 0.0:
                    f = -tension * inverse_mass / distance
                    ax, ay, az = f * dx, f * dy, az + f * dz
            if swing:
                c = swing * math.sqrt(g / length)
                ax -= c * (px - tvx)
                ay -= c * (py - tvy)
            penetration = deck - z
            if penetration > 0.0:
                normal = kc * penetration + cc * (deck_rate - pz)
                if normal > 0.0:
                    az += normal * inverse_mass
            vx += half * ax
            vy += half * ay
            vz += half * az
            out.append((x, y, z, vx, vy, vz, ax, ay, az))
        return out

    def _block(self, b: int) -> np.ndarray:
        """Block ``b``'s states ((:data:`BLOCK_STEPS` + 1, 9)), the blocks before it stepped first if need be."""
        if b in self._blocks:
            self._blocks.move_to_end(b)
            return self._blocks[b]
        while len(self._starts) <= b:
            self._compute(len(self._starts) - 1)
        return self._compute(b)

    def _compute(self, b: int) -> np.ndarray:
        """Step block ``b`` from its first state and hold it."""
        states = [self._starts[b], *self._step(self._starts[b], self._forcing(b), self.step_s)]
        if len(self._starts) == b + 1:
            self._starts.append(states[-1])
        rows = self._blocks[b] = np.array(states)
        while len(self._blocks) > BLOCKS_KEPT:
            self._blocks.popitem(last=False)
        return rows

    # -- sampling -------------------------------------------------------------------------------

    def sample(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """The lift at ``times`` (s, >= 0), (n,) each (:data:`SAMPLED`): the load's and the boom tip's positions and
        velocities (E, m, m/s); the wire paid out (unstretched, m), the slew angle (deg), the wire's
        tension (kN) and its angle from the vertical (deg), ``slack`` (True: no tension); the deck's push on the load
        (kN), the load's height above the deck (m; negative: pressed into it), the speed at which the load and the
        deck close (m/s: the deck's vertical velocity less the load's; positive closing), ``landed`` (True: the deck
        pushes). Without a landing spot the last three are nan, nan and False."""
        t = np.asarray(times, dtype=float).ravel()
        if t.size and not (np.all(np.isfinite(t)) and t.min() >= 0.0):
            raise ParameterError("a lift is sampled at finite times from 0 s")
        h, m = self.step_s, self.load.mass_kg
        ends = np.ceil(t / h - 1e-9).astype(np.int64)  # an order at t acts after both ends of the step before
        left = np.maximum(ends - 1, 0)
        before, after = np.empty((t.size, 9)), np.empty((t.size, 9))
        blocks = left // BLOCK_STEPS
        for b in np.unique(blocks).tolist():
            at = np.flatnonzero(blocks == b)
            rows = self._block(b)
            j = left[at] - b * BLOCK_STEPS
            before[at], after[at] = rows[j], rows[j + 1]
        s = ((t - left * h) / h)[:, None]
        s2, s3 = s * s, s * s * s
        w0, w1, w2, w3 = 2.0 * s3 - 3.0 * s2 + 1.0, (s3 - 2.0 * s2 + s) * h, 3.0 * s2 - 2.0 * s3, (s3 - s2) * h
        position = w0 * before[:, :3] + w1 * before[:, 3:6] + w2 * after[:, :3] + w3 * after[:, 3:6]
        velocity = w0 * before[:, 3:6] + w1 * before[:, 6:] + w2 * after[:, 3:6] + w3 * after[:, 6:]
        wire, wire_rate = self._wire.at(t, ends - 1)
        slew, _ = self._slew.at(t, ends - 1)
        tip, tip_velocity = self._tip(t, ends - 1)
        dx, dy, dz = (position - tip).T
        distance = np.sqrt(dx * dx + dy * dy + dz * dz)
        stretch = distance - wire
        stiffness = self.load.wire_ea_n / wire
        damping = 2.0 * self.load.damping_ratio * np.sqrt(stiffness * m)
        relative = velocity - tip_velocity
        stretching = (dx * relative[:, 0] + dy * relative[:, 1] + dz * relative[:, 2]) / distance - wire_rate
        tension = np.where(stretch > 0.0, np.maximum(stiffness * stretch + damping * stretching, 0.0), 0.0)
        out = {"load_x_m": position[:, 0], "load_y_m": position[:, 1], "load_z_m": position[:, 2],
               "load_vx_m_s": velocity[:, 0], "load_vy_m_s": velocity[:, 1], "load_vz_m_s": velocity[:, 2],
               "tip_x_m": tip[:, 0], "tip_y_m": tip[:, 1], "tip_z_m": tip[:, 2],
               "tip_vx_m_s": tip_velocity[:, 0], "tip_vy_m_s": tip_velocity[:, 1], "tip_vz_m_s": tip_velocity[:, 2],
               "wire_length_m": wire,
               "slew_deg": slew, "tension_kn": tension / 1000.0,
               "swing_deg": np.degrees(np.arctan2(np.hypot(dx, dy), -dz)), "slack": tension <= 0.0}
        if self.spot is None:
            out.update(deck_force_kn=np.zeros(t.size), load_above_spot_m=np.full(t.size, math.nan),
                       relative_velocity_m_s=np.full(t.size, math.nan), landed=np.zeros(t.size, dtype=bool))
            return out
        deck, deck_rate = self._deck(t)
        above = position[:, 2] - deck
        closing = deck_rate - velocity[:, 2]
        normal = np.where(above < 0.0, np.maximum(-self.contact_stiffness_n_m * above
                                                  + self.contact_damping_n_s_m * closing, 0.0), 0.0)
        out.update(deck_force_kn=normal / 1000.0, load_above_spot_m=above, relative_velocity_m_s=closing,
                   landed=normal > 0.0)
        return out
