"""6-DOF response of a vessel to the ocean's wave components, on a straight track or along a manoeuvre.

REFERENCES section 4: ``x_j(t) = Re sum_i H_j(w_i, beta_i - psi(t), U(t)) a_i exp(i(w_i t - k_i . r(t)))``
with ``r(t)`` the reference point in the Earth frame: each component's phase accumulates its encounter
frequency ``w - k . dr/dt`` as the ship goes, so a turn or a change of speed never makes a motion jump.
On a straight track (:class:`Response`), ``r(t) = r0 + U t (cos psi, sin psi)``, the phase is linear in t,
``w_e t - k . r0`` with the encounter frequency ``w_e = w - U k cos(beta_rel)``, so velocities and
accelerations are exact (``i w_e``, ``-w_e^2`` per component) and a block of time steps is one real
matrix product: ``[cos(w_e t) | sin(w_e t)] @ [Re C; -Im C]`` (float64: exported positions differentiate
twice to the exported accelerations). Along a manoeuvre, :mod:`marinesim.vessel.along`.

Points on board (body frame, m) move as ``xi + R p`` with ``R = Rz(yaw) Ry(pitch) Rx(roll)``
(CONVENTIONS), their velocity and acceleration from the exact derivatives of R. Positions are
given in the steady vessel frame (x forward, y port, z up, origin at the reference point's mean
position). The wave elevation is the incident wave at the reference point's and each point's
mean position; ``<point>_relative_m`` is the point's vertical motion minus that elevation.

What the viewer shows and what ``marinesim export`` writes both come from :meth:`Response.frame`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator

import numpy as np

from marinesim.errors import ParameterError, require_finite, require_positive
from marinesim.pose import RotationKinematics
from marinesim.recent import Newest
from marinesim.sea.ocean import Components
from marinesim.sea.phasors import phasor_table
from marinesim.vessel.rao import DOFS, RaoTable

OUTSIDE_HEADINGS_SHARE = 0.01
"""Largest share of the sea's variance a partial RAO table may meet outside its headings (those components
take the nearest covered heading's RAO); more is refused."""
BLOCK = 512
"""Time steps per matrix product."""
CHUNK = 1024
"""Components per matrix product: their phasor table (BLOCK x 2 CHUNK x 8 bytes = 8 MiB) stays in cache. A run of
fewer steps than BLOCK takes as many more components as its table has fewer rows, up to WIDEST times CHUNK."""
WIDEST = 32
BLOCKS_PER_PASS = 16
"""Blocks computed per pass over the component chunks (the rows held in memory at once)."""
FRAME_STEPS = 16
"""A call of at most this many steps (a viewer frame's one to three, a headless session's second of ten) keeps its
phasor table for the next frames ..."""
FRAME_TABLES_KEPT = 3
"""... the newest this many, by time step and steps: at most 48 rows of every component, 38 MB at 50,000."""
SHARED_ROWS = 32
"""Rows of a phasor table shared by responses at rest (:class:`Response`'s ``tables``): a call of at most
:data:`BLOCK` steps is summed in blocks of this many, so that the short runs of a vessel keeping station on a
wandering heading (a few seconds on each) all read one table, 9 MB at 17,844 components; a longer call makes its
own table of :data:`BLOCK` rows, which its many blocks repay."""

PhasorTables = Newest[tuple[float, int], list[np.ndarray]]
"""Phasor tables by (time step, rows), each a list over the component chunks (:meth:`Response.linear_steps`)."""


@dataclass(frozen=True)
class Track:
    """Straight course at constant speed: heading ``psi`` (math angle of the bow, rad, E frame),
    ``speed`` (m/s), start of the reference point ``(x0, y0)`` (m, E frame) at t = 0."""

    heading: float
    speed: float = 0.0
    x0: float = 0.0
    y0: float = 0.0


def _check_headings(rao: RaoTable, beta_rel: np.ndarray, power: np.ndarray) -> None:
    """Refuse waves that a partial RAO table does not cover (more than :data:`OUTSIDE_HEADINGS_SHARE` of the
    variance ``power`` at relative headings ``beta_rel``, rad), naming what it covers and where they come from."""
    if rao.covered is None or power.sum() <= 0.0:
        return
    outside = ~rao.covers(beta_rel)
    share = float(power[outside].sum() / power.sum())
    if share > OUTSIDE_HEADINGS_SHARE:
        mean = math.degrees(np.angle(np.sum(power[outside] * np.exp(1j * beta_rel[outside])))) % 360.0
        name = f" {Path(rao.source).name}" if rao.source else ""
        raise ParameterError(
            f"the RAO table{name} covers relative wave headings {rao.covered_text()} only: "
            f"{100 * share:.0f} % of this sea's variance meets the vessel at other headings (around {mean:.0f} deg; "
            "0 following, 90 from starboard, 180 head seas). Choose a course or a long-crested sea inside them, "
            "or an RAO file with more headings")


def motion_columns(points: dict[str, tuple[float, float, float]]) -> list[str]:
    """Column names of a motion frame, in CONVENTIONS order (rotations in degrees)."""
    def unit(j: int, suffix: str) -> str:
        return (("deg" if j >= 3 else "m") + suffix)
    names = ["time_s"] + [f"{d}_{unit(j, '')}" for j, d in enumerate(DOFS)]
    names += [f"{d}_vel_{unit(j, '_s')}" for j, d in enumerate(DOFS)]
    names += [f"{d}_acc_{unit(j, '_s2')}" for j, d in enumerate(DOFS)]
    for name in points:
        names += [f"{name}_x_m", f"{name}_y_m", f"{name}_z_m", f"{name}_vz_m_s", f"{name}_az_m_s2",
                  f"{name}_relative_m"]
    return names + ["wave_elevation_m"]


class Response:
    """Motions of a vessel (RAO table, track, named points) in the given wave components. ``strict``: refuse a sea
    a partial RAO table does not cover (a scenario's start); else its nearest headings serve (a course the ship
    has been steered onto). ``tables``: phasor tables shared with the responses to the same components of a vessel
    at rest on other headings (their encounter frequencies are the waves' own; one store per component set), read
    by calls of at most :data:`BLOCK` steps in blocks of :data:`SHARED_ROWS`; None, or a longer call, its own."""

    def __init__(self, rao: RaoTable, components: Components, track: Track,
                 points: dict[str, tuple[float, float, float]] | None = None, strict: bool = True,
                 tables: PhasorTables | None = None) -> None:
        if tables is not None and track.speed != 0.0:
            raise ParameterError(f"phasor tables are shared at rest only, not at {track.speed:g} m/s")
        self.rao, self.components, self.track = rao, components, track
        self.points = {name: np.asarray(p, dtype=float) for name, p in (points or {}).items()}
        for name, p in self.points.items():
            if p.shape != (3,) or not np.all(np.isfinite(p)):
                raise ParameterError(f"point {name!r} must be three finite numbers (m, body frame), got {p.tolist()}")
        c, psi = components, track.heading
        beta_rel = c.direction - psi
        if strict:
            _check_headings(rao, beta_rel, np.abs(c.amplitude) ** 2)
        along = c.kx * math.cos(psi) + c.ky * math.sin(psi)
        self.omega_e = c.omega - track.speed * along
        self.transfer = rao(c.omega, beta_rel, track.speed)              # (n, 6)
        self._at_origin = at_origin = c.amplitude * np.exp(-1j * (c.kx * track.x0 + c.ky * track.y0))
        motion = self.motion_coefficients()
        iw = 1j * self.omega_e[:, None]
        columns = [motion, iw * motion, iw ** 2 * motion, at_origin[:, None]]
        columns += [self.elevation_coefficients(p)[:, None] for p in self.points.values()]
        coefficients = np.concatenate(columns, axis=1)                     # (n, 19 + points)
        self._real, self._imag = np.ascontiguousarray(coefficients.real), np.ascontiguousarray(coefficients.imag)
        self._shared_tables = tables
        self._frame_tables: PhasorTables = Newest(FRAME_TABLES_KEPT)

    def elevation_coefficients(self, p: np.ndarray) -> np.ndarray:
        """The incident waves at the mean position of body point ``p`` (3,) (m): complex (n,), the elevation being
        ``Re sum c exp(i w_e t)`` (m) along the track."""
        c, psi = self.components, self.track.heading
        cos_psi, sin_psi = math.cos(psi), math.sin(psi)
        shift = c.kx * (cos_psi * p[0] - sin_psi * p[1]) + c.ky * (sin_psi * p[0] + cos_psi * p[1])
        return self._at_origin * np.exp(-1j * shift)

    def motion_coefficients(self) -> np.ndarray:
        """The six motions' complex amplitudes (n, 6) (m, rad), each ``Re sum c exp(i w_e t)`` along the track."""
        return self.transfer * self._at_origin[:, None]

    @property
    def columns(self) -> list[str]:
        return motion_columns(self.points)

    def variance_outside_table(self) -> dict[str, dict[str, float | None]]:
        """Share of each DOF's displacement variance at the reference point that comes from wave
        components below and above the RAO table's frequencies (where :class:`RaoTable` extends it
        by the long-wave model and by a taper): ``{"below": {dof: share}, "above": {dof: share}}``,
        shares in [0, 1] of ``sum |H_j a|^2 / 2`` over the components (the variance of random
        phases), None for a DOF with no variance."""
        power = np.abs(self.transfer * self.components.amplitude[:, None]) ** 2 / 2.0   # (n, 6)
        total = power.sum(axis=0)
        omega = self.components.omega
        out: dict[str, dict[str, float | None]] = {}
        for side, outside in (("below", omega < self.rao.omega[0]), ("above", omega > self.rao.omega[-1])):
            part = power[outside].sum(axis=0)
            out[side] = {dof: float(part[j] / total[j]) if total[j] > 0.0 else None for j, dof in enumerate(DOFS)}
        return out

    def linear(self, times: np.ndarray) -> np.ndarray:
        """Real linear outputs at arbitrary ``times`` (s): (T, 19 + points) = 6 DOF displacement,
        velocity, acceleration (m, rad), elevation at the reference point and at each point."""
        times = np.asarray(times, dtype=float).ravel()
        out = np.empty((times.size, self._real.shape[1]))
        for lo in range(0, times.size, BLOCK):
            phase = np.outer(times[lo:lo + BLOCK], self.omega_e)
            out[lo:lo + BLOCK] = np.cos(phase) @ self._real - np.sin(phase) @ self._imag
        return out

    def linear_steps(self, start: float, dt: float, steps: int) -> Iterator[tuple[np.ndarray, np.ndarray]]:
        """``(times, linear outputs)`` in blocks for ``start + dt * arange(steps)``.

        One phasor table ``exp(i w_e j dt)`` (j below the block's length: :data:`BLOCK` or the run's steps; or
        :data:`SHARED_ROWS`, the shared table of a response at rest, for a run of at most :data:`BLOCK` steps;
        :func:`~marinesim.sea.phasors.phasor_table`), its real and imaginary parts side by side, serves every block:
        the block's start time is folded into the coefficients, or into the table's rows where a block has fewer
        rows than there are outputs (as the few steps of a viewer's frame do: those of at most :data:`FRAME_STEPS`
        keep their tables). The product is memory-bound, so components go in chunks whose table stays in cache while
        a run of blocks reuses it.
        """
        dt = require_positive("time step", dt)
        start = require_finite("start time", start)
        steps = int(steps)
        shared = self._shared_tables is not None and steps <= BLOCK
        block = SHARED_ROWS if shared else min(BLOCK, max(steps, 1))
        if steps <= 0:
            return
        size = CHUNK * min(BLOCK // block, WIDEST)  # a short run's table, as few rows, takes more components
        chunks = [slice(lo, lo + size) for lo in range(0, self.omega_e.size, size)]
        outputs = self._real.shape[1]

        def made() -> list[np.ndarray]:
            tables = []
            for chunk in chunks:
                phasors = phasor_table(self.omega_e[chunk], dt, block)
                tables.append(np.concatenate([phasors.real, phasors.imag], axis=1))  # (block, 2 chunk)
            return tables
        if shared:
            tables = self._shared_tables.get((dt, block), made)
        else:
            tables = self._frame_tables.get((dt, block), made) if block <= FRAME_STEPS else made()
        span = block * BLOCKS_PER_PASS
        for first in range(0, steps, span):
            count = min(span, steps - first)
            out = np.zeros((count, outputs))
            for chunk, table in zip(chunks, tables):
                real, imag, omega_e = self._real[chunk], self._imag[chunk], self.omega_e[chunk]
                width = omega_e.size
                for lo in range(0, count, block):
                    n = min(block, count - lo)
                    turn = np.exp(1j * omega_e * (start + (first + lo) * dt))
                    if n < outputs:  # turn the table's rows
                        tc, ts = table[:n, :width], table[:n, width:]
                        c = tc * turn.real - ts * turn.imag
                        s = tc * turn.imag + ts * turn.real
                        out[lo:lo + n] += c @ real - s @ imag
                    else:            # turn the coefficients
                        c, s = turn.real[:, None], turn.imag[:, None]
                        out[lo:lo + n] += table[:n] @ np.concatenate([real * c - imag * s, -(real * s + imag * c)])
            for lo in range(0, count, block):
                n = min(block, count - lo)
                yield start + (first + lo + np.arange(n)) * dt, out[lo:lo + n]

    def frame(self, times: np.ndarray, linear: np.ndarray | None = None) -> dict[str, np.ndarray]:
        """Every output column (:func:`motion_columns`, CSV units) at ``times`` (s)."""
        times = np.asarray(times, dtype=float).ravel()
        if linear is None:
            linear = self.linear(times)
        disp, vel, acc = linear[:, 0:6], linear[:, 6:12], linear[:, 12:18]
        to_csv = np.array([1.0, 1.0, 1.0] + [180.0 / math.pi] * 3)
        values = [times[:, None], disp * to_csv, vel * to_csv, acc * to_csv]
        if self.points:
            offsets = np.array(list(self.points.values()))
            kinematics = RotationKinematics(disp[:, 3:6], vel[:, 3:6], acc[:, 3:6])
            position, velocity, acceleration = kinematics.points(offsets, disp[:, :3], vel[:, :3], acc[:, :3])
            relative = position[..., 2] - offsets[:, 2] - linear[:, 19:19 + len(offsets)]
            for i in range(len(offsets)):
                values.append(np.column_stack([position[:, i], velocity[:, i, 2], acceleration[:, i, 2],
                                               relative[:, i]]))
        values.append(linear[:, 18:19])
        return dict(zip(self.columns, np.concatenate(values, axis=1).T))

    def frames(self, start: float, dt: float, steps: int) -> Iterator[dict[str, np.ndarray]]:
        """:meth:`frame` for ``start + dt * arange(steps)``, block by block (streams long runs)."""
        for times, linear in self.linear_steps(start, dt, steps):
            yield self.frame(times, linear)
