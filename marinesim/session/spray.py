"""Spray: sheets thrown up where the bow meets the rising sea, and spindrift torn off the crests in a gale. Puffs of
drops that fly, fall and drift with the wind, stepped on the CPU with the simulation's clock: the session's state,
which :mod:`~marinesim.render.layers.spray` draws and nothing writes back.

Bow spray. Ochi (1964) takes the sea rising against the bow faster than ``v_th = 0.093 sqrt(g L)`` (L the
waterline length; REFERENCES section 8) as the impact of a slam; a bottom slam also needs the forefoot out of the
water (the slamming criterion), a flare impact does not, and both throw spray. The rising speed is the time
derivative of the water's height over the stem's point on the calm waterline, linear as the export's relative
motion of a point: the incident sea along the stem's path (met at the encounter frequency) less the stem's heave
and pitch, taken while the water is at the bow (between the forefoot and the deck). From :data:`SPRAY_ONSET` of
the threshold on, a plunge sweeps up the flare and throws :data:`SLAM_PUFFS_PER_S`
``x ((v / v_th)^2 - SPRAY_ONSET^2)`` puffs a second up and out from it, on top of the stem's own velocity. The
flare meets the water as a wedge of deadrise ``beta`` 20-40 deg entering at ``v``: the spray root (where the water
piles up against it) runs along it at ``(pi / 2) v cot(beta)`` (small ``beta``: Wagner 1932, Z. Angew. Math. Mech.
12:193-215), and the jet leaves it at twice the root's speed relative to the body, ``pi v cot(beta)`` (Zhao &
Faltinsen 1993, J. Fluid Mech. 246:593-612; :func:`jet_speed`).

Spindrift. From Beaufort 8 (17.2 m/s at 10 m), when "edges of crests begin to break into spindrift" (WMO),
crests within :data:`SPINDRIFT_RADIUS_M` of the vessel shed puffs at a rate proportional to the whitecap
cover ``W = 3.84e-6 U^3.41`` (Monahan & O'Muircheartaigh 1980), faded in over Beaufort 8.

A puff is drops of one size, known by their terminal fall speed ``v_t`` (Gunn & Kinzer 1949: a sheet breaks into
drops of about 3 mm, 8.06 m/s; spindrift 0.4 mm, 1.62 m/s). Their Reynolds number is far from Stokes's (3 mm at
8 m/s: about 1600; 0.4 mm at 1.6 m/s: about 40), so the drag is taken as quadratic in the speed relative to the
air, ``dv/dt = -g z - g |v - w| (v - w) / v_t^2`` with ``w`` the wind at 10 m (E frame): it balances gravity at
``v_t`` (:func:`flown`). The puffs are stepped on the run's clock, :data:`STEP_S` at a time from their birth
(which is on it too), and a frame shows them flown on from the last step: the path does not depend on the
frame rate. A puff spreads as it flies and is gone when it falls half a metre below the still water level or
after :data:`LIFE_S`. The stream is seeded by the run's seed and the time: the same run gives the same spray.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.constants import G
from marinesim.criteria.quantities import ochi_threshold_velocity
from marinesim.hull import Hull
from marinesim.hull.waterplane import waterline_loops
from marinesim.scenario.model import wind_of
from marinesim.sea.ocean import Components
from marinesim.session.timeline import Leg, Simulation
from marinesim.vessel.response import Response

SPRAY_ONSET = 0.5
"""The bow throws spray from this fraction of the slamming threshold on: a plunge that sweeps up the flare."""
SLAM_PUFFS_PER_S = 1000.0
"""Puffs a second for each unit of ``(v / v_th)^2 - SPRAY_ONSET^2``: at the threshold, 750 a second."""
DROP_TERMINAL_M_S, SPINDRIFT_TERMINAL_M_S = 8.06, 1.62
"""Terminal fall speed (m/s) in still air of 3 mm drops (bow spray: a sheet breaks into large drops) and 0.4 mm
drops (spindrift) (Gunn & Kinzer 1949)."""
BEAUFORT_8_M_S, BEAUFORT_9_M_S = 17.2, 20.8
SPINDRIFT_RADIUS_M = 150.0
SPINDRIFT_PUFFS_PER_M2_S = 0.01
"""Puffs a second per square metre of whitecap (Monahan's W) once spindrift is fully on."""
CREST_SIGMA = 1.0
"""Spindrift leaves crests higher than this many standard deviations of the elevation."""
CREST_VARIANCE = 0.9
"""Share of the sea's variance in the components that place the crests spindrift leaves (the largest)."""
LIFE_S = 6.0
"""The longest a puff flies (s): its drops have spread too thin to see."""
MAX_PUFFS = 4096
"""Most puffs in flight (the sprite buffer's size): the oldest go first."""
STEP_S = 1.0 / 30.0
"""The puffs' clock: they are born at multiples of it and flown a step at a time (:func:`flown`)."""
WARM_UP_S = 4.0
"""A jump in time (a first frame, a seek) starts the spray this long before, so that a still shows it in flight."""
STEM_BLOCK = 32
"""Time steps of the sea at the stem summed at once (their phasor table: 32 x components x 16 bytes, 5 MB for the
S175's 10,465)."""
BOW_REACH = 0.05
"""Puffs leave the flare over this fraction of the waterline length aft of the stem."""


@dataclass
class Puffs:
    """The puffs in flight: E-frame position (n, 3) and velocity (n, 3) (m, m/s), age (s), terminal fall speed of
    their drops (m/s), kind (0 bow spray, 1 spindrift)."""

    position: np.ndarray
    velocity: np.ndarray
    age: np.ndarray
    terminal: np.ndarray
    kind: np.ndarray

    @classmethod
    def none(cls) -> Puffs:
        """No puffs."""
        return cls(np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0), np.zeros(0), np.zeros(0, np.int8))

    def __len__(self) -> int:
        return self.age.size

    def joined(self, other: Puffs) -> Puffs:
        """These puffs and ``other``'s, the oldest of these dropped beyond :data:`MAX_PUFFS`."""
        keep = max(MAX_PUFFS - len(other), 0)
        return Puffs(*(np.concatenate([a[-keep:] if keep else a[:0], b]) for a, b in
                       zip((self.position, self.velocity, self.age, self.terminal, self.kind),
                           (other.position, other.velocity, other.age, other.terminal, other.kind))))

    def where(self, keep: np.ndarray) -> Puffs:
        """The puffs where ``keep`` (n,) bool is true."""
        return Puffs(self.position[keep], self.velocity[keep], self.age[keep], self.terminal[keep], self.kind[keep])


def flown(position: np.ndarray, velocity: np.ndarray, terminal: np.ndarray, wind: np.ndarray, h: float
          ) -> tuple[np.ndarray, np.ndarray]:
    """Position and velocity (n, 3) (E frame, m, m/s) after ``h`` s of ``dv/dt = -g z - g |u| u / v_t^2``,
    ``u = v - wind``, for drops of terminal fall speed ``terminal`` (n,) (m/s) in a steady ``wind`` (3,) (m/s).

    In ``ceil(h / STEP_S)`` equal steps, each half of gravity's kick, the exact flow of the drag alone (``u`` keeps
    its direction, its size ``s0 / (1 + g s0 t / v_t^2)``, the drop going ``ln(1 + g s0 t / v_t^2) v_t^2 / g``
    along it while the wind carries it) and the other half: Strang splitting, second order and stable however
    strong the drag."""
    steps = math.ceil(h / STEP_S)
    if steps <= 0:
        return position, velocity
    k = h / steps
    kick = np.array([0.0, 0.0, 0.5 * G * k])
    drag = (G * k / terminal ** 2)[:, None]
    for _ in range(steps):
        u = velocity - kick - wind
        slowing = drag * np.linalg.norm(u, axis=1, keepdims=True)
        travel = np.ones_like(slowing)
        np.divide(np.log1p(slowing), slowing, out=travel, where=slowing > 0.0)
        position = position + (wind + u * travel) * k
        velocity = wind + u / (1.0 + slowing) - kick
    return position, velocity


def jet_speed(rising: float, deadrise: float | np.ndarray) -> float | np.ndarray:
    """Speed (m/s) relative to the body of the jet thrown by a wedge of ``deadrise`` (rad) entering the water at
    ``rising`` (m/s): twice the spray root's ``(pi / 2) rising cot(deadrise)`` (Wagner 1932; Zhao & Faltinsen
    1993)."""
    root = 0.5 * math.pi * rising / np.tan(deadrise)
    return 2.0 * root


def flying(puffs: Puffs, h: float, wind: np.ndarray) -> Puffs:
    """``puffs`` :func:`flown` ``h`` s on in ``wind`` (3,) (m/s), those that fell half a metre into the sea or lived
    :data:`LIFE_S` gone."""
    if not len(puffs) or h <= 0.0:
        return puffs
    position, velocity = flown(puffs.position, puffs.velocity, puffs.terminal, wind, h)
    p = Puffs(position, velocity, puffs.age + h, puffs.terminal, puffs.kind)
    return p.where((p.age < LIFE_S) & (p.position[:, 2] > -0.5))


def whitecap_fraction(u10: float) -> float:
    """Monahan & O'Muircheartaigh (1980): the sea's whitecap cover at a 10 m wind of ``u10`` m/s (fraction)."""
    return min(3.84e-6 * max(u10, 0.0) ** 3.41, 1.0)


@dataclass(frozen=True)
class Bow:
    """Where bow spray leaves the hull (body frame, m): the stem on the waterline, how far aft the flare throws
    it, the half-breadth there, the waterline length, the draft at the stem and the freeboard of the bow."""

    stem: np.ndarray
    reach_m: float
    half_breadth_m: float
    length_m: float
    draft_m: float
    freeboard_m: float

    @classmethod
    def of(cls, hull: Hull, drawn: np.ndarray) -> Bow | None:
        """The bow of ``hull`` (its waterline), its freeboard from the ``drawn`` mesh's vertices (n, 3), or None."""
        loops = waterline_loops(hull)
        if not loops:
            return None
        points = np.concatenate(loops)
        length = float(np.ptp(points[:, 0]))
        x_stem = float(points[:, 0].max())
        reach = BOW_REACH * length
        forward = points[points[:, 0] > x_stem - reach]
        near = np.asarray(drawn, float)
        near = near[near[:, 0] > x_stem - reach]
        hull_v = np.asarray(hull.vertices, float)
        below = hull_v[hull_v[:, 0] > x_stem - reach]
        return cls(np.array([x_stem, 0.0, 0.0]), reach, float(np.abs(forward[:, 1]).max()), length,
                   float(max(-below[:, 2].min(), 0.5)) if below.size else 0.5,
                   float(max(near[:, 2].max(), 0.5)) if near.size else 0.5)


class Spray:
    """The spray of ``sim`` (its vessel's ``bow``, or None for spindrift only): :attr:`puffs`, the puffs in flight at
    the simulation's time as of the last :meth:`update`."""

    def __init__(self, sim: Simulation, bow: Bow | None) -> None:
        self.sim, self.bow = sim, bow
        self.puffs = Puffs.none()
        self.time: float | None = None
        self._stepped, self._step = Puffs.none(), 0   # the puffs at the step ``_step STEP_S`` of the run's clock
        self._crest_set: tuple[Leg, Components, float] | None = None
        self._stem: tuple[Response, np.ndarray] | None = None

    def update(self, wind: np.ndarray | None = None) -> Puffs:
        """The puffs moved on to the simulation's time in ``wind`` (3,) (E frame, m/s at 10 m; by default the run's
        wind at its time, :func:`~marinesim.scenario.model.wind_of`); a jump (the first call, a seek, a step back)
        starts afresh :data:`WARM_UP_S` before. Puffs are born on the steps
        ``k STEP_S`` of the run's clock, each step's from its own seeded stream, and flown from step to step; the
        frame shows them flown on from the last step: the same run gives the same spray whatever the frame
        rate."""
        t = self.sim.time
        if wind is None:
            east, north, speed = wind_of(self.sim.environment, self.sim.sea)
            wind = np.array([east * speed, north * speed, 0.0])
        if self.time is None or t < self.time or t - self.time > WARM_UP_S:
            self._stepped, self._step = Puffs.none(), math.floor(max(t - WARM_UP_S, 0.0) / STEP_S)
        first, last = self._step + 1, math.floor(t / STEP_S)
        steps = np.arange(first, last + 1)
        stem = (self.at_stem(first * STEP_S, STEP_S, len(steps)) if len(steps) and self.bow is not None
                and self.sim.vessel is not None else None)
        for i, k in enumerate(steps):
            self._stepped = flying(self._stepped, STEP_S, wind)
            rng = np.random.default_rng([self.sim.scenario.run.seed, 7, int(k)])
            if stem is not None:
                self._bow_spray(k * STEP_S, stem[i], rng)
            self._spindrift(k * STEP_S, wind, rng)
        self._step = last
        self.puffs = flying(self._stepped, t - self._step * STEP_S, wind)
        self.time = t
        return self.puffs

    def _crests(self) -> tuple[Components, float]:
        """The newest leg's largest wave components, :data:`CREST_VARIANCE` of its variance (where the crests are),
        and the standard deviation of their elevation (m)."""
        leg = self.sim.legs[-1]
        if self._crest_set is None or self._crest_set[0] is not leg:
            c = self.sim.ocean.components(leg.start + leg.ramp_s, variance_fraction=CREST_VARIANCE)
            self._crest_set = leg, c, math.sqrt(c.variance)
        return self._crest_set[1], self._crest_set[2]

    def sea_at(self, x: np.ndarray, y: np.ndarray, t: float) -> np.ndarray:
        """Elevation (m) of the sea's largest components (:meth:`_crests`) at points (x, y) (n,) (m, E frame) at
        ``t`` (s)."""
        c, _ = self._crests()
        phase = c.omega * t - np.outer(np.ravel(x), c.kx) - np.outer(np.ravel(y), c.ky)
        return (np.exp(1j * phase) @ c.amplitude).real

    def at_stem(self, start: float, h: float, steps: int) -> np.ndarray:
        """At the stem at ``start + h * arange(steps)`` (s), (steps, 4): the height of the water over the stem's
        point on the calm waterline (m), how fast it rises against it (m/s), and the stem's own height (m) and
        vertical velocity (m/s); linear (heave less x pitch), from the newest sea's response on the track she is on
        (a sea change under way taken as done; in a turn, the tangent to it, taken each second:
        :meth:`Simulation.response_now`)."""
        response = self.sim.response_now()
        if self._stem is None or self._stem[0] is not response:
            motion = response.motion_coefficients()
            stem = motion[:, 2] - float(self.bow.stem[0]) * motion[:, 4]
            water = response.elevation_coefficients(self.bow.stem) - stem
            iw = 1j * response.omega_e
            self._stem = response, np.stack([water, iw * water, stem, iw * stem], axis=1)
        weights, omega_e = self._stem[1], response.omega_e
        out = np.empty((steps, 4))
        for lo in range(0, steps, STEM_BLOCK):  # (block, components) phasors at a time: memory stays bounded
            n = min(STEM_BLOCK, steps - lo)
            turns = np.ones((n, omega_e.size), complex)
            turns[1:] = np.exp(1j * omega_e * h)
            phasors = np.exp(1j * omega_e * (start + lo * h)) * np.cumprod(turns, axis=0)
            out[lo:lo + n] = (phasors @ weights).real
        return out

    def threshold_m_s(self) -> float:
        """Ochi's slamming threshold velocity (m/s) for this bow."""
        return ochi_threshold_velocity(self.bow.length_m)

    def _bow_spray(self, t: float, stem: np.ndarray, rng: np.random.Generator) -> None:
        """Puffs thrown in the step from ``t`` (s), ``stem`` being :meth:`at_stem`'s row for ``t``."""
        bow = self.bow
        height, rising, stem_z, stem_vz = stem
        v_th = self.threshold_m_s()
        if rising <= SPRAY_ONSET * v_th or not -bow.draft_m < height < bow.freeboard_m:
            return
        n = int(rng.poisson(SLAM_PUFFS_PER_S * min((rising / v_th) ** 2 - SPRAY_ONSET ** 2, 4.0) * STEP_S))
        if n == 0:
            return
        side = rng.choice((-1.0, 1.0), n)
        body = np.c_[-rng.uniform(0.0, bow.reach_m, n), side * bow.half_breadth_m * rng.uniform(0.3, 1.0, n),
                     np.full(n, max(height, 0.0))]          # from the stem
        elevation = np.radians(rng.uniform(45.0, 75.0, n))
        up_and_out = np.c_[np.full(n, 0.2), side * np.cos(elevation), np.sin(elevation)]
        speed = jet_speed(rising, np.radians(rng.uniform(20.0, 40.0, n)))
        launch = speed[:, None] * up_and_out / np.linalg.norm(up_and_out, axis=1, keepdims=True)
        pose = self.sim.pose(t)
        rotation = pose.matrix()[:3, :3]
        u = self.sim.velocity()
        at = pose.world(bow.stem[None, :])[0]
        at[2] = stem_z
        velocity = np.array([*u, stem_vz]) + launch @ rotation.T
        self._stepped = self._stepped.joined(Puffs(at + body @ rotation.T, velocity, np.zeros(n),
                                                   np.full(n, DROP_TERMINAL_M_S), np.zeros(n, np.int8)))

    def _spindrift(self, t: float, wind: np.ndarray, rng: np.random.Generator) -> None:
        """Puffs torn off the crests around the vessel in the step from ``t`` (s) in ``wind`` (3,) (m/s)."""
        u10 = float(np.hypot(wind[0], wind[1]))
        on = np.clip((u10 - BEAUFORT_8_M_S) / (BEAUFORT_9_M_S - BEAUFORT_8_M_S), 0.0, 1.0)
        if on <= 0.0:
            return
        area = math.pi * SPINDRIFT_RADIUS_M ** 2
        expected = SPINDRIFT_PUFFS_PER_M2_S * whitecap_fraction(u10) * on * area * STEP_S
        above = 0.5 * math.erfc(CREST_SIGMA / math.sqrt(2.0))  # share of the sea above the crest level
        tries = min(int(rng.poisson(expected / above)), 512)
        if tries == 0:
            return
        pose = self.sim.pose(t)
        centre = (pose.x, pose.y)
        r = SPINDRIFT_RADIUS_M * np.sqrt(rng.uniform(0.0, 1.0, tries))
        a = rng.uniform(0.0, 2.0 * math.pi, tries)
        x, y = centre[0] + r * np.cos(a), centre[1] + r * np.sin(a)
        eta = self.sea_at(x, y, t)
        crest = eta > CREST_SIGMA * self._crests()[1]
        n = int(crest.sum())
        if n == 0:
            return
        position = np.c_[x[crest], y[crest], eta[crest] + 0.3]
        velocity = np.outer(rng.uniform(0.3, 0.8, n), wind) + np.c_[np.zeros((n, 2)), rng.uniform(0.5, 2.0, n)]
        self._stepped = self._stepped.joined(Puffs(position, velocity, np.zeros(n),
                                                   np.full(n, SPINDRIFT_TERMINAL_M_S), np.ones(n, np.int8)))
