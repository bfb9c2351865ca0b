"""Mean second-order wave drift coefficients: the horizontal force and yaw moment per wave amplitude squared.

A :class:`DriftTable` holds ``D(omega, beta)`` for surge X, sway Y and yaw N in the manoeuvring axes of
:mod:`marinesim.manoeuvring.state` (x forward, y to starboard, z down; N positive turning the bow to starboard),
so that a regular wave ``a cos(omega t)`` of relative propagation heading ``beta`` (docs/CONVENTIONS.md: 0
following sea, pi head sea, +pi/2 travelling towards port) pushes the vessel with the mean force ``|a|^2 D``.
Readers convert their program's axes once (:mod:`~marinesim.vessel.wamit_drift`, :mod:`~marinesim.vessel.aqwa_drift`,
:mod:`~marinesim.vessel.nemoh_drift`); :func:`make_drift_table` sorts, completes half-range tables by the
port/starboard mirror and checks the headings cover the circle. What the readers share is here too:
:class:`DriftLoads` (a reader's table before the heading checks), :func:`turned_round` (one heading made into the
whole circle for a body symmetric about the vertical axis) and :func:`drift_table` (the :class:`DriftTable`, with
``make_drift_table``'s refusals as :class:`FileFormatError`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from marinesim.compiled import compiled
from marinesim.errors import FileFormatError, ParameterError
from marinesim.vessel.rao import MAX_HEADING_GAP

DRIFT_DOFS = ("X", "Y", "N")
"""The three drift loads, manoeuvring axes: surge (N/m^2), sway to starboard (N/m^2), yaw to starboard (N m/m^2)."""
DRIFT_MIRROR_SIGN = np.array([1.0, -1.0, -1.0])
"""Sign of each load at heading ``-beta`` against ``beta`` (port/starboard symmetry): X even, Y and N odd."""
LONG_WAVE_POWER = 4
"""Below the table's lowest frequency the coefficients fall as ``(omega / omega_0)^4`` (the drift force of
long waves vanishes like the square of the body's wave-scattering, ~ (k L)^2 ~ omega^4)."""


@dataclass(frozen=True, eq=False)
class DriftTable:
    """Mean drift coefficients ``D(omega, beta)``, manoeuvring axes (module docstring).

    ``omega`` (n_w,) rad/s, strictly increasing, > 0; ``beta`` (n_b,) rad, relative propagation heading,
    strictly increasing in [-pi, pi), covering the circle (no gap over ``MAX_HEADING_GAP``);
    ``coefficients`` (n_w, n_b, 3): X and Y in N/m^2, N in N m/m^2 (per wave amplitude squared).
    Build it with :func:`make_drift_table`, which checks all this.
    """

    omega: np.ndarray
    beta: np.ndarray
    coefficients: np.ndarray
    source: str = ""
    notes: tuple[str, ...] = ()

    def __call__(self, omega: np.ndarray | float, beta: np.ndarray | float) -> np.ndarray:
        """``D`` at wave frequencies ``omega`` (rad/s) and relative headings ``beta`` (rad), broadcast together:
        shape ``broadcast(omega, beta).shape + (3,)``, i.e. (n, 3) for (n,) inputs.

        Bilinear in frequency and in heading (periodic over 2 pi): :meth:`at_frequencies`, then
        :meth:`at_headings`. Above the highest frequency the last row is kept (constant); below the lowest the first
        row falls as ``(omega / omega_0)^4`` (:data:`LONG_WAVE_POWER`), and ``omega <= 0`` gives zero.
        """
        w, b = np.broadcast_arrays(np.asarray(omega, dtype=float), np.asarray(beta, dtype=float))
        return self.at_headings(self.at_frequencies(w.ravel()), b.ravel()).reshape(w.shape + (3,))

    def at_frequencies(self, omega: np.ndarray) -> np.ndarray:
        """The frequency half of the lookup: ``D`` (N/m^2, N/m^2, N m/m^2) at each of ``omega`` (n,) rad/s on
        every table heading, (n, n_b, 3), linear between the table's frequencies (the long-wave factor below
        them)."""
        w = np.asarray(omega, dtype=float).ravel()
        n_w = self.omega.size
        wc = np.clip(w, self.omega[0], self.omega[-1])
        i = np.clip(np.searchsorted(self.omega, wc, side="right") - 1, 0, max(n_w - 2, 0))
        i1 = np.minimum(i + 1, n_w - 1)
        span = self.omega[i1] - self.omega[i]
        tw = np.divide(wc - self.omega[i], span, out=np.zeros_like(wc), where=span > 0)[:, None, None]
        factor = np.where(w >= self.omega[0], 1.0, np.clip(w / self.omega[0], 0.0, None) ** LONG_WAVE_POWER)
        return ((1.0 - tw) * self.coefficients[i] + tw * self.coefficients[i1]) * factor[:, None, None]

    def at_headings(self, by_frequency: np.ndarray, beta: np.ndarray, rows: np.ndarray | None = None) -> np.ndarray:
        """The heading half: ``D`` (n, 3) at relative headings ``beta`` (n,) rad, linear between the table's
        headings round the circle, from :meth:`at_frequencies`' (m, n_b, 3): heading ``i`` on its row ``rows[i]``
        (default: row ``i``)."""
        b = np.asarray(beta, dtype=float).ravel()
        rows = np.arange(b.size) if rows is None else np.asarray(rows).ravel()
        if by_frequency.ndim != 3 or by_frequency.shape[1:] != (self.beta.size, 3):
            raise ParameterError(f"at_headings: the frequencies' coefficients must be (m, {self.beta.size}, 3), got "
                                 f"{by_frequency.shape}")
        if rows.dtype.kind not in "iu" or rows.size != b.size or (
                rows.size and (rows.min() < 0 or rows.max() >= by_frequency.shape[0])):
            raise ParameterError(f"at_headings: {b.size} headings need as many rows of the {by_frequency.shape[0]} "
                                 f"frequencies' coefficients, got {rows.size}")
        out = np.empty((b.size, 3))
        _between_headings(np.ascontiguousarray(by_frequency, dtype=float).reshape(-1, 3),
                          np.append(self.beta, self.beta[0] + 2.0 * math.pi), b, np.asarray(rows, dtype=np.int64), out)
        return out


@compiled
def _between_headings(flat: np.ndarray, ring: np.ndarray, beta: np.ndarray, rows: np.ndarray, out: np.ndarray) -> None:
    """:meth:`DriftTable.at_headings`' interpolation into ``out`` (n, 3): heading ``beta[i]`` (rad) wrapped onto the
    table's circle ``ring`` (its n_b headings, then the first plus 2 pi), linear between the two table headings
    around it, on frequency row ``rows[i]`` of ``flat`` (m n_b, 3: row r's heading k at r n_b + k)."""
    n_b, turn = ring.size - 1, 2.0 * math.pi
    per_radian = n_b / (ring[n_b] - ring[0])
    for i in range(beta.size):
        v = beta[i] - ring[0]
        if 0.0 <= v < turn:            # Python's % where it needs no division, to the bit
            q = ring[0] + v
        elif -turn < v < 0.0:
            q = ring[0] + (v + turn)
        else:
            q = ring[0] + v % turn
        if q != q:
            j = n_b - 1
        else:                          # the last table heading at or before q (from a guess on even spacing)
            j = min(max(int((q - ring[0]) * per_radian), 0), n_b)
            while j > 0 and ring[j] > q:
                j -= 1
            while j < n_b and ring[j + 1] <= q:
                j += 1
            j = min(j, n_b - 1)
        t = (q - ring[j]) / (ring[j + 1] - ring[j])
        first = rows[i] * n_b
        lo, hi = first + j, first + (0 if j + 1 == n_b else j + 1)
        for load in range(3):
            out[i, load] = (1.0 - t) * flat[lo, load] + t * flat[hi, load]


def make_drift_table(omega: np.ndarray, beta: np.ndarray, coefficients: np.ndarray, *, source: str = "",
                     notes: tuple[str, ...] = ()) -> DriftTable:
    """A :class:`DriftTable` from ``omega`` (n_w,) rad/s, ``beta`` (n_b,) rad and ``coefficients`` (n_w, n_b, 3)
    in the manoeuvring axes, in any order. Headings spanning exactly 0..pi (or -pi..0) are completed by the
    port/starboard mirror (:data:`DRIFT_MIRROR_SIGN`); any other set must leave no gap wider than
    ``MAX_HEADING_GAP`` round the circle. :class:`ParameterError` names what is wrong."""
    omega = np.asarray(omega, dtype=float)
    beta = np.asarray(beta, dtype=float)
    values = np.asarray(coefficients, dtype=float)
    if omega.ndim != 1 or beta.ndim != 1 or values.shape != (omega.size, beta.size, 3):
        raise ParameterError(f"drift coefficients must be (frequencies, headings, 3) = ({omega.size}, {beta.size}, 3),"
                             f" got {values.shape}")
    if omega.size == 0 or beta.size == 0:
        raise ParameterError("a drift table needs at least one frequency and one heading")
    if not (np.all(np.isfinite(omega)) and np.all(np.isfinite(beta)) and np.all(np.isfinite(values))):
        raise ParameterError("drift table frequencies, headings and coefficients must be finite")
    if np.any(omega <= 0.0):
        raise ParameterError(f"drift table frequencies must be > 0 rad/s, got {omega.min():g}")
    order = np.argsort(omega, kind="stable")
    omega, values = omega[order], values[order]
    if np.any(np.diff(omega) == 0.0):
        raise ParameterError(f"drift table frequency {omega[np.flatnonzero(np.diff(omega) == 0.0)[0]]:g} rad/s "
                             "is given twice")
    eps = 1e-9
    wrapped = np.mod(beta + math.pi, 2.0 * math.pi) - math.pi  # [-pi, pi)
    if beta.size > 1 and np.all(beta > -eps) and np.all(beta < math.pi + eps) \
            and beta.min() < eps and beta.max() > math.pi - eps:
        wrapped = np.where(beta > math.pi - eps, -math.pi, beta)
        inner = (beta > eps) & (beta < math.pi - eps)
        wrapped = np.concatenate([wrapped, -beta[inner]])
        values = np.concatenate([values, values[:, inner] * DRIFT_MIRROR_SIGN], axis=1)
        notes = notes + ("headings 0..180 deg completed by the port/starboard mirror",)
    elif beta.size > 1 and np.all(beta < eps) and np.all(beta > -math.pi - eps) \
            and beta.max() > -eps and beta.min() < -math.pi + eps:
        wrapped = np.where(beta < -math.pi + eps, -math.pi, np.where(beta > -eps, 0.0, beta))
        inner = (beta < -eps) & (beta > -math.pi + eps)
        wrapped = np.concatenate([wrapped, -beta[inner]])
        values = np.concatenate([values, values[:, inner] * DRIFT_MIRROR_SIGN], axis=1)
        notes = notes + ("headings -180..0 deg completed by the port/starboard mirror",)
    order = np.argsort(wrapped, kind="stable")
    wrapped, values = wrapped[order], values[:, order]
    same = np.flatnonzero(np.diff(wrapped) < eps)
    # one heading twice (-180 and 180, 0 and 360, as runs over the whole circle write it): kept once if it agrees
    scale = max(float(np.abs(values).max()), 1e-300)
    for k in same:
        if not np.allclose(values[:, k], values[:, k + 1], rtol=1e-4, atol=1e-6 * scale):
            raise ParameterError(f"drift table heading {math.degrees(wrapped[k]):g} deg is given twice, with "
                                 "different values")
    if same.size:
        keep = np.setdiff1d(np.arange(wrapped.size), same + 1)
        wrapped, values = wrapped[keep], values[:, keep]
    gaps = np.diff(np.append(wrapped, wrapped[0] + 2.0 * math.pi))
    if np.any(gaps > MAX_HEADING_GAP + eps):
        k = int(np.argmax(gaps))
        raise ParameterError(f"drift table headings leave a gap of {math.degrees(gaps[k]):g} deg after "
                             f"{math.degrees(wrapped[k]):g} deg (at most {math.degrees(MAX_HEADING_GAP):g}): give "
                             "headings round the circle, or 0..180 deg for a port/starboard symmetric vessel")
    for array in (omega, wrapped, values):
        array.setflags(write=False)
    return DriftTable(omega, wrapped, values, str(source), tuple(notes))


TURN_STEP_DEG = 5.0
"""Heading step of the table :func:`turned_round` makes (linear interpolation of the turning force vector
between steps of 5 deg is within 0.1 % of its magnitude)."""


@dataclass(frozen=True)
class DriftLoads:
    """Mean drift loads as a reader found them, before the heading checks of :func:`make_drift_table`:
    ``omega`` (n_w,) rad/s increasing, ``headings_deg`` (n_b,) relative propagation heading in [-180, 180]
    increasing (one of -180 and 180), ``values`` (n_w, n_b, 3) in the manoeuvring axes (X, Y in N/m^2, N in
    N m/m^2) and ``notes``."""

    omega: np.ndarray
    headings_deg: np.ndarray
    values: np.ndarray
    notes: tuple[str, ...]


def turned_round(headings_deg: np.ndarray, values: np.ndarray, step_deg: float = TURN_STEP_DEG) -> tuple[
        np.ndarray, np.ndarray, str]:
    """Headings (rad, every ``step_deg`` on [-180, 180)) and loads (n_w, n_step, 3) of a body symmetric about the
    vertical axis through its moment reference point, from its loads ``values`` (n_w, n_b, 3; manoeuvring axes)
    at the distinct ``headings_deg`` (n_b,), and a note.

    For such a body the horizontal drift force turns with the waves and the yaw moment does not change: the
    loads at heading ``b`` turned back to heading 0 are ``X0 = X cos b - Y sin b``, ``Y0 = X sin b + Y cos b``
    (waves turned towards port turn the force towards port, which is ``-Y``), ``N0 = N``. The headings given
    are turned back to 0 and averaged (one heading is taken as it is), then turned round the circle; the note
    gives how far the headings given differ from their average, as a share of the largest force.
    """
    headings = np.radians(np.asarray(headings_deg, dtype=float))
    values = np.asarray(values, dtype=float)
    c, s = np.cos(headings), np.sin(headings)
    x, y, n = values[..., 0], values[..., 1], values[..., 2]
    back = np.stack([x * c - y * s, x * s + y * c, n], axis=-1)  # (n_w, n_b, 3) at heading 0
    mean = back.mean(axis=1)
    force = max(float(np.abs(mean[:, :2]).max()), 1e-300)
    spread = float(np.abs(back[..., :2] - mean[:, None, :2]).max()) / force
    grid = np.radians(np.arange(-180.0, 180.0, float(step_deg)))
    cg, sg = np.cos(grid), np.sin(grid)
    x0, y0, n0 = mean[:, 0:1], mean[:, 1:2], mean[:, 2:3]
    turned = np.stack([x0 * cg + y0 * sg, -x0 * sg + y0 * cg, np.broadcast_to(n0, (mean.shape[0], grid.size))],
                      axis=-1)
    given = ", ".join(f"{h:g}" for h in np.asarray(headings_deg, dtype=float))
    note = (f"axisymmetric body: the loads at heading(s) {given} deg turned to 0 deg"
            + (f" and averaged (they differ from the average by up to {spread:.3g} of the largest force)"
               if headings.size > 1 else "")
            + f", then turned round the circle every {step_deg:g} deg; yaw moment kept as given")
    return grid, turned, note


def drift_table(path: Path, loads: DriftLoads, *, axisymmetric: bool = False) -> DriftTable:
    """The :class:`DriftTable` of ``loads`` read from ``path``: turned round the circle for an ``axisymmetric``
    body, else as given (a half range is mirrored by :func:`make_drift_table`); its refusal (headings that
    leave a gap) becomes a :class:`FileFormatError` naming the headings the file covers."""
    beta, values, notes = np.radians(loads.headings_deg), loads.values, loads.notes
    if axisymmetric:
        beta, values, note = turned_round(loads.headings_deg, loads.values)
        notes = notes + (note,)
    try:
        return make_drift_table(loads.omega, beta, values, source=str(path), notes=notes)
    except ParameterError as error:
        covered = ", ".join(f"{h:g}" for h in loads.headings_deg)
        hint = "" if axisymmetric else "; for a body symmetric about the vertical axis pass axisymmetric=True"
        raise FileFormatError(path, None, f"{error} (the file covers heading(s) {covered} deg{hint})") from None


def wrapped_heading(direction_deg: float, shown: dict[float, float]) -> float:
    """``direction_deg`` (-360..360) as a heading in [-180, 180], the same number for the same heading: the first
    of -180 and 180 met is kept for both (``shown`` remembers it), so a half range 0..180 or -180..0 stays one
    for :func:`make_drift_table`'s mirror and a full circle printing both ends keeps one."""
    key = round((direction_deg + 180.0) % 360.0 - 180.0, 9)  # [-180, 180), 1e-9 deg: 0.1 stays 0.1
    return shown.setdefault(key, 180.0 if key == -180.0 and direction_deg > 0.0 else key)
