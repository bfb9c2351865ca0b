"""The RAO model: six complex transfer functions over frequency, relative heading and speed.

Conventions (docs/CONVENTIONS.md, "Transfer functions"): ``H_j(w, beta_rel, U)`` gives the
response ``x_j(t) = Re{H_j a exp(i w t)}`` to the wave ``a exp(i w t)`` at the body-frame origin
(the RAO reference point); positive phase = response leads. Translations in m/m, rotations in
rad/m. ``w`` is the wave (not encounter) frequency; ``beta_rel`` the direction the waves travel
towards relative to the bow (0 following, pi/2 towards port, pi head sea).

Interpolation is linear on Re/Im in frequency, heading (wrapping around the circle) and speed.
Outside the tabulated frequencies:

* below the lowest, ``H = L(w) + (H(w0) - L(w0)) (w / w0)^2``: the free-floating long-wave
  limit ``L`` (:func:`long_wave_limit`, in the table's water depth) plus the table's deviation
  from it, fading as w^2;
* above the highest, the last value tapered by ``cos^2`` to zero at 1.5 times that frequency.

A table of one frequency (a regular-wave result) is extended the same way from that frequency.

Speeds outside a multi-speed table are clamped to its ends (scenarios refuse them up front). A table of one
speed serves every speed with the encounter frequency shifted but its own values unchanged; far from its speed
that misses the forward-speed effects on the RAO itself, and :func:`one_speed_note` says so.
"""

from __future__ import annotations

import math
import dataclasses
from dataclasses import dataclass, field

import numpy as np

from marinesim.compiled import compiled
from marinesim.constants import G, KNOT
from marinesim.errors import HeadingError, ParameterError, require_positive
from marinesim.sea.dispersion import k_from_omega

DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
ROTATIONS = (3, 4, 5)
MIRROR_SIGN = np.array([1.0, -1.0, 1.0, -1.0, 1.0, -1.0])
"""Sign of each DOF under the port/starboard mirror beta -> -beta: sway, roll, yaw flip."""
TAPER_END = 1.5
"""Above the table, RAOs taper to zero at this multiple of the highest frequency."""
MAX_HEADING_GAP = math.pi / 2
"""Largest gap between tabulated headings (after mirroring) that interpolation may bridge; a wider gap makes
the table partial (it covers arcs of headings, :attr:`RaoTable.covered`)."""
HEADING_MARGIN = math.radians(15.0)
"""A partial table stands for headings up to this beyond the ends of each arc it covers (its end values
held): one step of the usual 15 deg table, so a table at 180 deg only serves head seas 165..195 deg."""
MAX_TRANSLATION_M_M = 50.0
"""Largest |RAO| of surge, sway, heave (m/m): resonant heave peaks of floating bodies stay under 10."""
MAX_ROTATION_RAD_M = 1.0
"""Largest |RAO| of roll, pitch, yaw (rad/m) at full scale: 57 deg per metre of wave amplitude, beyond any
ship's resonant roll; a model-scale table may reach :data:`MAX_ROTATION_SLOPES` times the wave slope k."""
SURGE_SPEED_FACTOR = 1.5
"""A surge RAO at forward speed above this multiple of the same table's largest surge at zero speed is noted
as implausible (no restoring force, no resonance to amplify it: strip-theory surge at speed, as VERES gives
it, is the usual cause)."""
MAX_ORBIT_FACTOR = 3.0
"""A surge or sway RAO above this multiple of the wave orbit's horizontal amplitude (``1 / tanh(kh)`` m/m) is
noted as implausible (couplings near a resonance reach about twice it: the HAMS cylinder's 2.1)."""
MAX_ROTATION_SLOPES = 50.0
"""Largest rotation |RAO| as a multiple of the wave slope per amplitude, k = w^2 / g (rad/m)."""
RESONANCE_DAMPING = 0.1
"""Largest damping (fraction of critical) of a peak that may be a real resonance beyond the limits above (a moored
spar's surge, a flap's roll): such a peak is described and left to the reader's caller to refuse or accept."""
SPEED_JUMP_FACTOR = 3.0
"""A rotation |RAO| at a speed between two others of the table above this multiple of both neighbouring speeds'
(same frequency and heading) is noted as non-physical: the S175's VERES roll at 15 kn, 150 deg, 1.047 rad/s is
7.38 deg/m against 0.892 and 1.25 at 10 and 20 kn (5.9 times), while no other speed of that table jumps above
2.3 times both neighbours where it exceeds :data:`SPEED_JUMP_FLOOR`."""
SPEED_JUMP_FLOOR = 0.25
"""A jump over :data:`SPEED_JUMP_FACTOR` is noted only where the rotation exceeds this fraction of the wave slope
k (rad/m): under it, the rotation stays under 3 deg even in waves as steep as ka = 0.2, and the S175's jumps in the
noise of its shortest waves (10 kn, 2.51 rad/s: 0.04 of the slope) are left alone."""
NEAR_RESONANCE = 1.5
"""A speed whose encounter frequency is within this factor (either side) of the DOF's resonance may truly peak
against its neighbouring speeds (speed sweeps the encounter frequency through the resonance): not a jump."""
BEYOND_RESONANCE = 3.0
"""At encounter frequencies beyond this multiple of a rotation's resonance the rotation is inertia-controlled: driven
by the long-wave excitation (the one that gives |H| = k in long waves), an oscillator answers ``1 / (3^2 - 1)`` =
1/8 of the wave slope k there, so :data:`BEYOND_RESONANCE_SLOPES` times the slope is noted as non-physical. Closer
in, real tables exceed it: at 1.5 times the zero-speed roll resonance the S175's VERES roll at 10 kn reaches 3.1
times the slope (its roll peak moves with speed). Beyond three times, the tables of rao/ and tests/data stay under
0.44 times the slope (the semisubmersible's roll), but for the S175's roll at 15 and 20 kn (up to 1.4 and 3.5)."""
BEYOND_RESONANCE_SLOPES = 1.0
"""The rotation |RAO|, as a multiple of the wave slope k (rad/m), noted beyond :data:`BEYOND_RESONANCE`."""
WARNING_WORDS = ("implausible", "non-physical")
"""How the notes that warn of data no floating body gives begin (:attr:`RaoTable.warnings`)."""
ONE_SPEED_FROUDE = 0.1
"""A table of one speed used at a Froude number ``U / sqrt(g L)`` more than this from its own is noted (not
refused): at 15 kn (Fn 0.19) the S175's zero-speed table misses the head-sea pitch peak by tens of percent
(``tests/test_vessel_one_speed.py``), while below Fn 0.1 forward speed changes a ship's RAOs little."""
ONE_SPEED_KN = 5.0
"""With no length known, a table of one speed used more than this many knots from its own speed is noted
instead: Fn 0.1 for a 67 m ship, so a longer ship is noted no later than on her Froude number."""


@dataclass(frozen=True)
class Resonance:
    """A lightly damped resonance peak of one DOF beyond a plausibility limit: ``text`` says what was found (the
    peak, its period, its damping); ``refused``: beyond :data:`MAX_TRANSLATION_M_M` or :data:`MAX_ROTATION_RAD_M`
    (refused unless accepted), else beyond :data:`MAX_ORBIT_FACTOR` (noted); ``dof`` its index in :data:`DOFS`."""

    text: str
    refused: bool
    dof: int


def long_wave_limit(omega: np.ndarray, beta: np.ndarray, g: float = G, depth: float = math.inf) -> np.ndarray:
    """Long-wave RAO of a free-floating body in water of ``depth`` (m; inf = deep), shape (n, 6).

    The body follows the wave orbit and slope at the surface: surge ``-i cos beta / tanh(kh)``,
    sway ``-i sin beta / tanh(kh)`` (the horizontal orbit is ``1 / tanh(kh)`` times the vertical
    one), heave 1, roll ``-i k sin beta``, pitch ``i k cos beta`` (pitch bow down = minus the
    slope along x), yaw 0, with ``k`` from ``w^2 = g k tanh(kh)`` (deep water: ``k = w^2 / g``,
    ``tanh = 1``).
    """
    omega = np.asarray(omega, dtype=float)
    beta = np.asarray(beta, dtype=float)
    k = k_from_omega(omega, depth, g)
    orbit = 1.0 if math.isinf(depth) else 1.0 / np.tanh(k * depth)
    c, s = np.cos(beta), np.sin(beta)
    zero = np.zeros(np.broadcast(omega, beta).shape)
    return np.stack([-1j * c * orbit + zero, -1j * s * orbit + zero, 1.0 + zero, -1j * k * s, 1j * k * c,
                     zero + 0j], axis=-1)


@dataclass(frozen=True)
class RaoTable:
    """Tabulated RAOs in the internal convention.

    ``values[s, b, w, j]``: speed ``speed[s]`` (m/s), heading ``beta[b]`` (rad, increasing in
    [0, 2 pi)), frequency ``omega[w]`` (rad/s, increasing), DOF j in :data:`DOFS` order.
    ``depth`` (m, inf = deep water) is the water depth the table was computed for: the long-wave
    limits and the extension below the table use it. Build with :func:`make_table`, which
    completes half-range tables by symmetry. ``covered`` is None for a table of the whole circle,
    else the arcs ``(first, last)`` (rad, counter-clockwise from first to last) its headings cover
    with no gap over :data:`MAX_HEADING_GAP` (a partial table: a single heading, or headings on one
    side only), each good to :data:`HEADING_MARGIN` beyond its ends.
    """

    omega: np.ndarray
    beta: np.ndarray
    speed: np.ndarray
    values: np.ndarray
    reference_point: tuple[float, float, float]
    rho: float
    g: float
    source: str
    source_format: str
    notes: tuple[str, ...] = field(default=())
    mirrored: bool = False
    depth: float = math.inf
    covered: tuple[tuple[float, float], ...] | None = None
    resonances: tuple[Resonance, ...] = ()
    draft: float | None = None              # the vessel's draft (m) as her file gives it; None if it gives none
    length: float | None = None             # the ship's length (m) as her file states it (VERES: Lpp); else None

    def __call__(self, omega: np.ndarray, beta: np.ndarray, speed: float = 0.0) -> np.ndarray:
        """Interpolated RAOs, shape (n, 6), at wave frequencies ``omega`` (rad/s, > 0) and
        relative headings ``beta`` (rad, any range) for forward speed ``speed`` (m/s)."""
        omega, beta = np.broadcast_arrays(np.asarray(omega, dtype=float).ravel(), np.asarray(beta, dtype=float).ravel())
        beta = np.mod(beta, 2.0 * math.pi)
        table = self._at_speed(speed)
        w_lo, w_hi = self.omega[0], self.omega[-1]
        if self.covered is not None:
            beta = self._nearest_covered(beta)
        first = self.beta[0]
        beta = first + np.mod(beta - first, 2.0 * math.pi)  # from the first heading round: past the last, wrapped
        inside = _bilinear(self.omega, self._beta_wrapped, table, np.clip(omega, w_lo, w_hi), beta)
        below = omega < w_lo
        if np.any(below):
            fade = (omega[below] / w_lo) ** 2
            at_edge = inside[below]
            inside[below] = (long_wave_limit(omega[below], beta[below], self.g, self.depth)
                             + (at_edge - long_wave_limit(np.full(fade.size, w_lo), beta[below], self.g,
                                                          self.depth)) * fade[:, None])
        above = omega > w_hi
        if np.any(above):
            x = np.clip((omega[above] - w_hi) / ((TAPER_END - 1.0) * w_hi), 0.0, 1.0)
            inside[above] *= (np.cos(0.5 * math.pi * x) ** 2)[:, None]
        return inside

    def _nearest_covered(self, beta: np.ndarray) -> np.ndarray:
        """``beta`` (rad, in [0, 2 pi)) moved to the nearest heading of the covered arcs (its end values held
        beyond an arc's ends; interpolation never bridges a gap)."""
        best, moved = np.full(beta.shape, np.inf), beta.copy()
        for first, last in self.covered:
            length = np.mod(last - first, 2.0 * math.pi)
            offset = np.mod(beta - first, 2.0 * math.pi)
            after = offset - length                        # > 0: beyond the last heading
            before = 2.0 * math.pi - offset                # to the first heading, going back
            inside = offset <= length
            distance = np.where(inside, 0.0, np.minimum(after, before))
            target = np.where(inside, beta, np.where(after <= before, last, first))
            closer = distance < best
            best, moved = np.where(closer, distance, best), np.where(closer, target, moved)
        return np.mod(moved, 2.0 * math.pi)

    def covers(self, beta: np.ndarray) -> np.ndarray:
        """Whether each relative heading ``beta`` (rad, any range) is within the table's headings (a table of
        the whole circle covers every one; a partial table its arcs and :data:`HEADING_MARGIN` beyond them)."""
        beta = np.mod(np.asarray(beta, dtype=float), 2.0 * math.pi)
        if self.covered is None:
            return np.ones(beta.shape, dtype=bool)
        return np.abs(np.angle(np.exp(1j * (self._nearest_covered(beta) - beta)))) <= HEADING_MARGIN + 1e-9

    def covered_text(self) -> str:
        """The covered headings in words, e.g. ``"165..195 deg (tabulated 180)"``."""
        if self.covered is None:
            return "0..360 deg"
        margin = math.degrees(HEADING_MARGIN)
        arcs = []
        for first, last in self.covered:
            a, b = round(math.degrees(first), 6), round(math.degrees(last), 6)
            tabulated = f"{a:g}" if a == b else f"{a:g}..{b:g}"
            arcs.append(f"{(a - margin) % 360:g}..{(b + margin) % 360:g} deg (tabulated {tabulated})")
        return ", ".join(arcs)

    @property
    def _beta_wrapped(self) -> np.ndarray:
        return np.append(self.beta, self.beta[0] + 2.0 * math.pi)

    def _at_speed(self, speed: float) -> np.ndarray:
        """Table (nb + 1, nw, 6) at ``speed``, with the first heading repeated at the end."""
        if self.speed.size == 1:
            table = self.values[0]
        else:
            u = float(np.clip(speed, self.speed[0], self.speed[-1]))
            i = int(np.clip(np.searchsorted(self.speed, u, side="right") - 1, 0, self.speed.size - 2))
            f = (u - self.speed[i]) / (self.speed[i + 1] - self.speed[i])
            table = (1.0 - f) * self.values[i] + f * self.values[i + 1]
        return np.concatenate([table, table[:1]], axis=0)

    @property
    def warnings(self) -> tuple[str, ...]:
        """The notes that warn of data no floating body gives (implausible translations, non-physical rotations)."""
        return tuple(n for n in self.notes if n.startswith(WARNING_WORDS))

    def at_speeds(self, speeds: list[float]) -> RaoTable:
        """The table with only ``speeds`` (m/s, each one of its own to 0.01 kn), screened again (implausible
        translations, :func:`non_physical_rotations`): its other notes kept, those on the speeds left out gone."""
        keep = []
        for speed in speeds:
            match = np.flatnonzero(np.abs(self.speed - speed) <= 0.01 * KNOT)
            if match.size == 0:
                raise ParameterError(f"{speed / KNOT:g} kn is not one of the table's speeds "
                                     f"({', '.join(f'{v / KNOT:g}' for v in self.speed)} kn)")
            keep.append(int(match[0]))
        keep = sorted(set(keep))
        given = self.beta <= math.pi + 1e-9 if self.mirrored else np.ones(self.beta.size, bool)  # as read

        def screened(speed: np.ndarray, values: np.ndarray) -> tuple[str, ...]:
            dofs = {r.dof for r in self.resonances}
            return (_implausible(self.omega, self.beta, speed, values, self.g, self.depth, dofs)[0]
                    + non_physical_rotations(self.omega, self.beta[given], speed, values[:, given], self.g, self.depth))
        before = set(screened(self.speed, self.values))
        notes = tuple(n for n in self.notes if n not in before) + screened(self.speed[keep], self.values[keep])
        return dataclasses.replace(self, speed=self.speed[keep], values=self.values[keep], notes=notes)

    @property
    def speed_range(self) -> tuple[float, float]:
        return float(self.speed[0]), float(self.speed[-1])


@dataclass(frozen=True)
class SolverRaos:
    """One body's zero-speed RAOs as a solver's output gives them (AQWA, NEMOH), already in the internal convention,
    before :func:`make_table`: ``omega`` (rad/s, increasing), ``headings_deg`` (wave travel direction from body x,
    deg, increasing), ``values`` (headings, frequencies, 6; m/m and rad/m, phase lead), ``reference_point`` (m),
    ``rho`` (kg/m^3), ``g`` (m/s^2), ``depth`` (m, inf = deep or not given), ``source`` (the file read, or
    "equation of motion" for RAOs solved from coefficients) and ``notes``."""

    omega: np.ndarray
    headings_deg: np.ndarray
    values: np.ndarray
    reference_point: tuple[float, float, float]
    rho: float
    g: float
    depth: float
    source: str
    notes: tuple[str, ...]


def one_speed_note(table: RaoTable, speed: float, length: float | None, length_from: str = "") -> str | None:
    """A line for the user where ``table`` has one speed and serves ``speed`` (m/s) far from it: Froude numbers
    ``U / sqrt(g L)`` on the ship's ``length`` (m; ``length_from`` says whose) more than :data:`ONE_SPEED_FROUDE`
    apart, or, ``length`` None, speeds more than :data:`ONE_SPEED_KN` apart; None otherwise, and for a table of
    several speeds (interpolated within them)."""
    if table.speed.size > 1:
        return None
    own = float(table.speed[0])
    if length is None:
        if abs(speed - own) <= ONE_SPEED_KN * KNOT + 1e-9:
            return None
        how = f"length unknown, so no Froude number: noted more than {ONE_SPEED_KN:g} kn from the table's speed"
    else:
        froude, own_froude = (u / math.sqrt(G * length) for u in (speed, own))
        if abs(froude - own_froude) <= ONE_SPEED_FROUDE:
            return None
        ship = f"L {length:.4g} m" + (f", {length_from}" if length_from else "")
        how = f"Fn {froude:.3f}" + (f", the table's {own_froude:.3f}" if own > 0.0 else "") + f"; {ship}"
    return (f"the RAO table has one speed ({own / KNOT:.3g} kn) and is used at {speed / KNOT:.3g} kn ({how}): "
            "the forward-speed effects are missing (the encounter frequency shift is applied, but the RAO's own "
            "dependence on speed is not)")


def _bilinear(omega_grid: np.ndarray, beta_grid: np.ndarray, table: np.ndarray,
              omega: np.ndarray, beta: np.ndarray) -> np.ndarray:
    """Linear on Re/Im in frequency and heading; ``table`` is (len(beta_grid), len(omega_grid), 6).
    A one-frequency table holds its value at every frequency."""
    iw, fw = _locate(omega_grid, omega)
    ib, fb = _locate(beta_grid, beta)
    flat = np.ascontiguousarray(table, dtype=np.complex128).view(np.float64).reshape(-1, 2 * table.shape[2])
    out = np.empty((omega.size, flat.shape[1]))
    _bilinear_pairs(flat, omega_grid.size, iw, fw, ib, fb, out)
    return out.view(np.complex128)


@compiled
def _bilinear_pairs(flat: np.ndarray, n_w: int, iw: np.ndarray, fw: np.ndarray, ib: np.ndarray, fb: np.ndarray,
                    out: np.ndarray) -> None:
    """:func:`_bilinear` on the complex values as (re, im) pairs of floats: ``(1 - fb) ((1 - fw) a + fw b) + fb ((1 -
    fw) c + fw d)`` into ``out`` (n, 2 dofs), from ``flat`` (headings x frequencies, 2 dofs), each point's cells
    ``iw``, ``ib`` and fractions ``fw``, ``fb`` (n,)."""
    for k in range(out.shape[0]):
        i0 = iw[k]
        i1 = min(i0 + 1, n_w - 1)
        near, far = ib[k] * n_w, (ib[k] + 1) * n_w
        w, b = fw[k], fb[k]
        for c in range(out.shape[1]):
            side = flat[near + i0, c] * (1 - w) + flat[near + i1, c] * w
            other = flat[far + i0, c] * (1 - w) + flat[far + i1, c] * w
            out[k, c] = side * (1 - b) + other * b


def _locate(grid: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Cell index and fraction of each ``x`` in the increasing ``grid`` (x within its range)."""
    if grid.size == 1:
        return np.zeros(x.size, dtype=np.intp), np.zeros(x.size)
    i = np.clip(np.searchsorted(grid, x, side="right") - 1, 0, grid.size - 2)
    return i, (x - grid[i]) / (grid[i + 1] - grid[i])


def refer_phases(values: np.ndarray, omega: np.ndarray, headings_deg: np.ndarray, offset_m: tuple[float, float],
                 depth: float, g: float) -> np.ndarray:
    """RAOs ``values`` (headings, frequencies, ...) relative to the incident wave at one point -> relative to
    the wave at the point ``offset_m`` (dx, dy) from it: the wave there lags by ``k (dx cos b + dy sin b)``, so
    the RAOs gain that phase (``exp(+i w t)``, lead). ``omega`` rad/s, headings the travel direction."""
    dx, dy = offset_m
    if dx == 0.0 and dy == 0.0:
        return values
    k = k_from_omega(np.asarray(omega, float), depth if math.isfinite(depth) else math.inf, g)
    beta = np.radians(np.asarray(headings_deg, float))[:, None]
    factor = np.exp(1j * k[None, :] * (dx * np.cos(beta) + dy * np.sin(beta)))
    return values * factor.reshape(factor.shape + (1,) * (values.ndim - 2))


def make_table(omega: np.ndarray, beta: np.ndarray, speed: np.ndarray, values: np.ndarray, *,
               reference_point=(0.0, 0.0, 0.0), rho: float = 1025.0, g: float = G, source: str = "",
               source_format: str = "", notes: tuple[str, ...] = (), depth: float = math.inf,
               draft: float | None = None, length: float | None = None) -> RaoTable:
    """Validate and complete an RAO table already in the internal convention.

    ``values`` has shape (speeds, headings, frequencies, 6). Headings (rad) spanning exactly
    0..pi are completed by the port/starboard mirror (:data:`MIRROR_SIGN`); headings that leave a
    gap wider than :data:`MAX_HEADING_GAP` make a partial table (:attr:`RaoTable.covered`).
    ``depth``: water depth (m, > 0; inf = deep); ``draft`` and ``length``: the vessel's (m, > 0) if the file
    gives them. Raises :class:`HeadingError` on unusable headings, :class:`ParameterError` on anything else.
    """
    depth = require_positive("water depth", depth, allow_infinite=True)
    draft = None if draft is None else require_positive("draft", draft)
    length = None if length is None else require_positive("length", length)
    omega = np.asarray(omega, dtype=float)
    beta = np.asarray(beta, dtype=float)
    speed = np.atleast_1d(np.asarray(speed, dtype=float))
    values = np.asarray(values, dtype=complex)
    if values.shape != (speed.size, beta.size, omega.size, 6):
        raise ParameterError(f"RAO values have shape {values.shape}, expected "
                             f"(speeds, headings, frequencies, 6) = ({speed.size}, {beta.size}, {omega.size}, 6)")
    if not np.all(np.isfinite(values)):
        raise ParameterError("RAO values must be finite")
    _check_increasing("frequencies", omega, minimum=0.0)
    resonances = _check_amplitudes(omega, beta, speed, values, g)
    _check_increasing("speeds", speed, minimum=None)
    if beta.size == 0 or not np.all(np.isfinite(beta)):
        raise HeadingError("RAO headings must be finite and at least one")
    rotations = non_physical_rotations(omega, beta, speed, values, g, depth)
    order = np.argsort(beta, kind="stable")
    beta, values = beta[order], values[:, order]
    eps = 1e-9
    mirrored = bool(abs(beta[0]) < eps and abs(beta[-1] - math.pi) < eps)
    if mirrored:
        inner = (beta > eps) & (beta < math.pi - eps)
        beta = np.concatenate([beta, 2.0 * math.pi - beta[inner][::-1]])
        values = np.concatenate([values, values[:, inner][:, ::-1] * MIRROR_SIGN], axis=1)
    beta = np.mod(beta, 2.0 * math.pi)
    beta[beta > 2.0 * math.pi - eps] = 0.0
    order = np.argsort(beta, kind="stable")
    beta, values = beta[order], values[:, order]
    same = np.flatnonzero(np.diff(beta) < eps)
    if same.size:
        raise HeadingError(f"RAO heading {math.degrees(beta[same[0]]):g} deg is given twice "
                           "(after wrapping to 0..360)")
    gaps = np.diff(np.append(beta, beta[0] + 2.0 * math.pi))
    wide = gaps > MAX_HEADING_GAP + eps
    covered = None
    if wide.any():
        ends = np.flatnonzero(wide)                      # the gap after these headings is too wide to bridge
        starts = (ends + 1) % beta.size
        covered = tuple((float(beta[a]), float(beta[b])) for a, b in zip(starts, np.roll(ends, -1), strict=True))
    implausible, orbit_resonances = _implausible(omega, beta, speed, values, g, depth, {r.dof for r in resonances})
    return RaoTable(omega, beta, speed, values, tuple(float(v) for v in reference_point), float(rho),
                    float(g), str(source), source_format, tuple(notes) + implausible + rotations, mirrored, depth,
                    covered, resonances + orbit_resonances, draft, length)


def _where(omega: np.ndarray, beta: np.ndarray, speed: np.ndarray, index: tuple) -> str:
    """Speed, heading and period of ``index`` (speed, heading, frequency) in words."""
    s, b, w = index
    return f"{speed[s] / KNOT:.3g} kn, heading {math.degrees(beta[b]):g} deg, T {2 * math.pi / omega[w]:.3g} s"


def resonance_damping(omega: np.ndarray, amplitude: np.ndarray, peak: int) -> float | None:
    """Damping (fraction of critical) of the peak of ``amplitude`` (|H| at the frequencies ``omega``, rad/s) at
    index ``peak``, from its half-power bandwidth ``(w2 - w1) / (2 wn)`` (``|H| = peak / sqrt 2`` at w1 and w2,
    linear between the tabulated points; one side doubled where the table ends before the other); None unless
    ``peak`` is an interior maximum with a half-power point. An upper bound where the peak is narrower than the
    frequency step."""
    if not 0 < peak < omega.size - 1 or amplitude[peak] < max(amplitude[peak - 1], amplitude[peak + 1]):
        return None
    half = amplitude[peak] / math.sqrt(2.0)
    sides = []
    for step in (-1, 1):
        k = peak
        while 0 <= k + step < omega.size and amplitude[k + step] > half:
            k += step
        if not 0 <= k + step < omega.size:
            continue
        f = (amplitude[k] - half) / (amplitude[k] - amplitude[k + step])
        sides.append(abs(omega[k] + f * (omega[k + step] - omega[k]) - omega[peak]))
    if not sides:
        return None
    return float(sum(sides) * 2.0 / len(sides) / (2.0 * omega[peak]))


def _resonance_text(omega: np.ndarray, beta: np.ndarray, speed: np.ndarray, values: np.ndarray,
                    index: tuple, j: int) -> str | None:
    """The lightly damped resonance (:data:`RESONANCE_DAMPING`) of DOF ``j`` whose peak over frequency, at the
    speed and heading of ``index``, is at ``index``'s frequency, in words; None where there is none."""
    s, b, w = index
    amplitude = np.abs(values[s, b, :, j])
    while 0 < w < omega.size - 1 and max(amplitude[w - 1], amplitude[w + 1]) > amplitude[w]:
        w += 1 if amplitude[w + 1] > amplitude[w - 1] else -1  # up to the peak
    index = (s, b, w)
    zeta = resonance_damping(omega, amplitude, w)
    if zeta is None or zeta > RESONANCE_DAMPING:
        return None
    return (f"a resonance peak of {amplitude[w]:.3g} at T {2 * math.pi / omega[w]:.3g} s (heading "
            f"{math.degrees(beta[b]):g} deg, {speed[s] / KNOT:.3g} kn) with about {100 * zeta:.2g} % of critical "
            "damping or less (its half-power bandwidth between the tabulated frequencies)")


def _implausible(omega: np.ndarray, beta: np.ndarray, speed: np.ndarray, values: np.ndarray, g: float,
                 depth: float, resonant: set[int]) -> tuple[tuple[str, ...], tuple[Resonance, ...]]:
    """Notes on surge and sway RAOs a floating body does not have (:data:`SURGE_SPEED_FACTOR`,
    :data:`MAX_ORBIT_FACTOR`): each names where the largest is and what it was compared with; a surge or sway
    beyond the orbit factor at a lightly damped resonance peak is a :class:`Resonance` instead, unless its DOF is
    in ``resonant`` (already one beyond the amplitude limits)."""
    notes, resonances = [], []
    k = k_from_omega(omega, depth, g)
    orbit = np.ones_like(k) if math.isinf(depth) else 1.0 / np.tanh(k * depth)
    for j, dof in ((0, "surge"), (1, "sway")):
        ratio = np.abs(values[..., j]) / orbit
        peak = np.unravel_index(int(np.argmax(ratio)), ratio.shape)
        if ratio[peak] > MAX_ORBIT_FACTOR and j not in resonant:
            found = f"{dof} RAO {abs(values[peak + (j,)]):.3g} m/m, {ratio[peak]:.2g} times the wave orbit"
            resonance = _resonance_text(omega, beta, speed, values, peak, j)
            if resonance is not None:
                resonances.append(Resonance(f"{found}: {resonance}", refused=False, dof=j))
            else:
                notes.append(f"implausible {dof} RAO: {abs(values[peak + (j,)]):.3g} m/m at "
                             f"{_where(omega, beta, speed, peak)}, {ratio[peak]:.2g} times the wave orbit; check the "
                             "file's units and reference point")
    at_rest = np.flatnonzero(np.abs(speed) < 1e-9)
    if at_rest.size and speed.size > 1:
        surge = np.abs(values[..., 0])
        still = surge[at_rest].max()
        peak = np.unravel_index(int(np.argmax(surge)), surge.shape)
        if still > 0.0 and surge[peak] > SURGE_SPEED_FACTOR * still:
            notes.append(f"implausible surge RAO at speed: {surge[peak]:.3g} m/m at "
                         f"{_where(omega, beta, speed, peak)}, {surge[peak] / still:.2g} times the largest at 0 kn "
                         f"({still:.3g} m/m); surge has no "
                         "restoring force to resonate with, so this is the source's (strip-theory surge at "
                         "speed is unreliable): treat surge at this speed with caution")
    return tuple(notes), tuple(resonances)


def non_physical_rotations(omega: np.ndarray, beta: np.ndarray, speed: np.ndarray, values: np.ndarray, g: float,
                           depth: float) -> tuple[str, ...]:
    """Notes on roll, pitch and yaw |RAO| no floating body has, one per DOF and speed, naming the worst point.

    ``values`` (speeds, headings, frequencies, 6) at ``omega`` (rad/s), ``beta`` (rad, as tabulated: each once)
    and ``speed`` (m/s, increasing), wave slope ``k`` from ``w^2 = g k tanh(k depth)``. Two rules:

    * a jump: at a speed between two others, over :data:`SPEED_JUMP_FACTOR` times both neighbouring speeds' at
      the same frequency and heading and over :data:`SPEED_JUMP_FLOOR` times the wave slope, unless the encounter
      frequency is within :data:`NEAR_RESONANCE` of the DOF's resonance;
    * beyond the resonance: over :data:`BEYOND_RESONANCE_SLOPES` times the wave slope at an encounter frequency
      ``|w - k U cos beta|`` over :data:`BEYOND_RESONANCE` times the DOF's resonance.

    A DOF's resonance is the encounter frequency of its first peak over frequency at the table's first speed
    (:func:`_rotation_resonance`; roll's: the beam-sea roll peak; yaw, which has no restoring, its first response
    peak's).
    """
    k = k_from_omega(omega, depth, g)
    encounter = np.abs(omega - k * speed[:, None, None] * np.cos(beta)[None, :, None])
    notes = []
    for j in ROTATIONS:
        amp = np.abs(values[..., j])
        resonance = _rotation_resonance(omega, encounter[0], amp[0])
        slopes = amp / k
        jump = np.zeros(amp.shape, dtype=bool)
        if speed.size > 2:
            near = (encounter[1:-1] < NEAR_RESONANCE * resonance) & (encounter[1:-1] > resonance / NEAR_RESONANCE)
            jump[1:-1] = ((amp[1:-1] > SPEED_JUMP_FACTOR * np.maximum(amp[:-2], amp[2:]))
                          & (slopes[1:-1] > SPEED_JUMP_FLOOR) & ~near)
        beyond = (encounter > BEYOND_RESONANCE * resonance) & (slopes > BEYOND_RESONANCE_SLOPES)
        for s in np.flatnonzero((jump | beyond).any(axis=(1, 2))):
            notes.append(_rotation_note(omega, beta, speed, amp, k, encounter, resonance, jump, beyond, s, j))
    return tuple(notes)


def _rotation_resonance(omega: np.ndarray, encounter: np.ndarray, amp: np.ndarray) -> float:
    """A rotation's resonance (rad/s) from its |RAO| ``amp`` (headings, frequencies) at one speed: the encounter
    frequency (``encounter``, same shape) of the lowest-frequency peak over frequency of its largest over the
    headings, so that a spike in shorter waves does not pass for it; the largest where there is no interior peak
    (and the wave frequency where the encounter frequency there is zero)."""
    largest = amp.max(axis=0)
    peaks = np.flatnonzero((largest[1:-1] > largest[:-2]) & (largest[1:-1] >= largest[2:])) + 1
    w = int(peaks[0]) if peaks.size else int(np.argmax(largest))
    return float(encounter[int(np.argmax(amp[:, w])), w]) or float(omega[w])


def _rotation_note(omega: np.ndarray, beta: np.ndarray, speed: np.ndarray, amp: np.ndarray, k: np.ndarray,
                   encounter: np.ndarray, resonance: float, jump: np.ndarray, beyond: np.ndarray, s: int,
                   j: int) -> str:
    """The line of :func:`non_physical_rotations` for DOF ``j`` at speed index ``s``: its largest flagged |RAO|
    ``amp`` (speeds, headings, frequencies; rad/m) with what it was compared with, then how many points each rule
    flagged at this speed and where."""
    dof, kn = DOFS[j], [f"{u / KNOT:.3g}" for u in speed]
    flagged = jump[s] | beyond[s]
    b, w = np.unravel_index(int(np.argmax(np.where(flagged, amp[s], -1.0))), flagged.shape)
    heading = np.mod(np.degrees(beta), 360.0)
    text = (f"non-physical {dof} RAO at {kn[s]} kn, {round(heading[b], 6):g} deg, {omega[w]:.4g} rad/s: "
            f"{math.degrees(amp[s, b, w]):.3g} deg/m")
    if jump[s, b, w]:
        text += (f" against {math.degrees(amp[s - 1, b, w]):.3g} and {math.degrees(amp[s + 1, b, w]):.3g} at "
                 f"{kn[s - 1]} and {kn[s + 1]} kn")
    text += f" (wave slope {math.degrees(k[w]):.3g} deg/m"
    if beyond[s, b, w]:
        text += (f"; {amp[s, b, w] / k[w]:.3g}x it at an encounter frequency {encounter[s, b, w] / resonance:.2g}x "
                 "the resonance")
    counts = [f"{n} point{'s' * (n > 1)} {what}" for n, what in (
        (int(jump[s].sum()), f"over {SPEED_JUMP_FACTOR:g}x both neighbouring speeds"),
        (int(beyond[s].sum()), f"over {BEYOND_RESONANCE_SLOPES:g}x the wave slope beyond {BEYOND_RESONANCE:g}x the "
                               "resonance")) if n]
    rows, cols = np.nonzero(flagged)
    return (f"{text}); at {kn[s]} kn {', '.join(counts)}, at headings {round(heading[rows].min(), 6):g}.."
            f"{round(heading[rows].max(), 6):g} deg and {omega[cols].min():.3g}..{omega[cols].max():.3g} rad/s (the "
            f"{dof} resonance: {resonance:.3g} rad/s, T {2 * math.pi / resonance:.3g} s, its first peak at "
            f"{kn[0]} kn): the source's {dof} at this speed is suspect, not a floating body's")


def _check_amplitudes(omega: np.ndarray, beta: np.ndarray, speed: np.ndarray, values: np.ndarray,
                      g: float) -> tuple[Resonance, ...]:
    """Refuse an |RAO| no floating body has (:data:`MAX_TRANSLATION_M_M`, :data:`MAX_ROTATION_RAD_M`), unless the
    DOF's largest excess is a lightly damped resonance peak: that is returned, described, for the caller to refuse
    or accept."""
    limit = np.full((omega.size, 6), MAX_TRANSLATION_M_M)
    limit[:, list(ROTATIONS)] = np.maximum(MAX_ROTATION_RAD_M, MAX_ROTATION_SLOPES * omega**2 / g)[:, None]
    excess = np.abs(values) / limit
    resonances = []
    for j in np.flatnonzero((excess > 1.0).any(axis=(0, 1, 2))):
        s, b, w = np.unravel_index(int(np.argmax(excess[..., j])), excess.shape[:3])
        unit = "rad/m" if j in ROTATIONS else "m/m"
        found = (f"RAO {DOFS[j]} amplitude {abs(values[s, b, w, j]):.3g} {unit} at {omega[w]:.4g} rad/s, heading "
                 f"{math.degrees(beta[b]):g} deg is beyond any floating body's (<= {limit[w, j]:.3g} {unit})")
        resonance = _resonance_text(omega, beta, speed, values, (s, b, w), j)
        if resonance is None:
            raise ParameterError(f"{found}: check the units")
        resonances.append(Resonance(f"{found}: {resonance}", refused=True, dof=int(j)))
    return tuple(resonances)


def _check_increasing(name: str, grid: np.ndarray, minimum: float | None) -> None:
    if grid.ndim != 1 or grid.size == 0 or not np.all(np.isfinite(grid)):
        raise ParameterError(f"RAO {name} must be a non-empty list of finite numbers")
    if minimum is not None and grid[0] <= minimum:
        raise ParameterError(f"RAO {name} must be > {minimum:g}, got {grid[0]:g}")
    if np.any(np.diff(grid) <= 0):
        at = int(np.flatnonzero(np.diff(grid) <= 0)[0])
        raise ParameterError(f"RAO {name} must be strictly increasing: {grid[at]:g} then {grid[at + 1]:g}")
