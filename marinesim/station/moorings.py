"""Mooring lines and hawsers holding a vessel on station: each line's fairlead tension from MoorPy's catenary.

Axes as :mod:`marinesim.manoeuvring.state`: the vessel's low-frequency position ``north``, ``east`` (m, from the
set point) and heading ``psi`` (rad, clockwise from north); body axes x forward, y to starboard. A line runs from
its far end, given in the earth frame as (north m, east m) from the set point, to its fairlead on the vessel, given in
the body frame as (x m forward, y m to starboard, z m up from the waterline). The far end is an anchor on the seabed, or
for a hawser a fixed point above the water (an FPSO's stern chock: the FPSO's own motions, drawn where a scenario has
her as a body, do not move it). The fairleads stay at their depth or height: the vessel's wave-frequency motion (heave,
roll, pitch) is not felt by the lines. An anchored line's wet weight acts over its whole length (a fairlead above the
waterline: its few metres in air counted wet); a hawser hangs in air and weighs its mass (a slack hawser dipping into
the sea is still weighed in air).

Line physics is MoorPy's (``moorpy.Catenary.catenary``: an elastic catenary with seabed contact, no seabed
friction; a hawser's hung from its fixed point, ``CB`` < 0) and its line-property library
(``moorpy.helpers.getLineProps``: mass, wet weight, axial stiffness EA and minimum breaking load from the material's
name and nominal diameter). A catenary solve per line and per Runge-Kutta stage would be far too slow for the
simulator, so :class:`Moorings` tabulates each line's horizontal and vertical fairlead tension ``H``, ``V`` against
the horizontal anchor-fairlead span once, on a grid of :data:`GRID_INTERVALS` or more intervals (0.5 m or finer)
over the set point's span +- :data:`REACH_FRACTION` of it or +- :data:`REACH_MAX_M`, whichever is smaller (taut
side: cut where the tension passes :data:`TAUT_LIMIT` times the breaking load), and interpolates it with a cubic
spline. Beyond the grid, ``H`` and ``V`` carry on linearly at the grid end's slope (the taut side's elastic
stiffness; on the slack side down to zero): the vessel has then left the range the mooring was laid for.

A hawser's table runs from well slack (:data:`SLACK_FRACTION` of the span at which it is straight and unstretched)
to past :data:`TAUT_LIMIT` times its breaking load, whatever its set point: the vessel may close on the fixed point
or weathervane about it. Slack, it hangs between its ends under its weight alone (MoorPy's suspended catenary, a
few kN for a nylon hawser); closer than the table's slack end its ``H`` and ``V`` are held at the end's values.
Its ``V`` (the line's pull down on the fairlead) turns negative when it pulls the fairlead up.

MoorPy (which imports matplotlib) is imported on first use, not with this module.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline

from marinesim.constants import RHO_SEAWATER, G
from marinesim.compiled import compiled, read_only
from marinesim.errors import ParameterError, require_finite, require_positive

REACH_FRACTION = 0.15
REACH_MAX_M = 60.0
"""The span grid covers the set point's horizontal anchor-fairlead span +- the smaller of this fraction of it and
this distance (m): a moored vessel's offset and her fairleads' swing in yaw stay well inside it."""
GRID_INTERVALS = 240
"""The fewest grid intervals over the span range; the step is 0.5 m or a power-of-two fraction of it, so that lines
alike share one table (cubic interpolation error at 0.5 m: some 4e-5 of the tension, for 100 mm chain)."""
TAUT_LIMIT = 3.0
"""The taut side of the grid ends where the fairlead tension passes this many times the line's breaking load."""
DIAMETER_RANGE_M = (0.01, 0.35)
"""Nominal diameters accepted (m): MoorPy's chain fits hold to about 0.36 m."""
ANCHOR_DEPTH_TOLERANCE_M = 0.1
"""An anchor depth stated within this of the water depth is on the seabed (m)."""
MIN_SPAN_M = 1.0
"""The least horizontal anchor-fairlead span at the set point (m): a catenary line runs out from the vessel."""
SLACK_FRACTION = 0.8
"""A hawser's table starts at this fraction of the horizontal span at which it is straight and unstretched."""


@dataclass(frozen=True)
class LineType:
    """A line's properties per unit length from MoorPy's library: ``mass_kg_m`` (kg/m), ``weight_n_m`` (wet
    weight in sea water, N/m), ``ea_n`` (axial stiffness, N), ``mbl_n`` (minimum breaking load, N)."""

    material: str
    diameter_m: float
    mass_kg_m: float
    weight_n_m: float
    ea_n: float
    mbl_n: float


@functools.lru_cache(maxsize=1)
def _library() -> dict:
    from moorpy.helpers import loadLineProps

    return loadLineProps(None)


def materials() -> tuple[str, ...]:
    """The line materials of MoorPy's default library (``chain``, ``chain_studlink``, ``wire``, ``polyester``...)."""
    return tuple(_library())


@functools.lru_cache(maxsize=64)
def line_type(material: str, diameter_m: float) -> LineType:
    """``material`` of nominal diameter ``diameter_m`` (m) from MoorPy's library, wet weight in sea water of
    :data:`~marinesim.constants.RHO_SEAWATER` under :data:`~marinesim.constants.G`; unknown materials are
    refused."""
    from moorpy.helpers import getLineProps

    if material not in _library():
        raise ParameterError(f"line type {material!r} is not in MoorPy's library (known: {', '.join(materials())})")
    low, high = DIAMETER_RANGE_M
    if not low <= diameter_m <= high:
        raise ParameterError(f"line type {material!r}: diameter must be in {low:g}..{high:g} m, got {diameter_m!r}")
    props = getLineProps(diameter_m * 1000.0, material, lineProps=_library(), rho=RHO_SEAWATER, g=G)
    return LineType(material, diameter_m, float(props["m"]), float(props["w"]), float(props["EA"]),
                    float(props["MBL"]))


@dataclass(frozen=True)
class Line:
    """One mooring line: ``anchor`` (north m, east m) in the earth frame from the set point, on the seabed (or at
    ``anchor_depth_m`` below the surface, which must then be the water depth); ``fairlead`` (x m forward, y m to
    starboard, z m up from the waterline) in the body frame from the vessel's origin; unstretched ``length_m``;
    MoorPy's ``material`` of nominal ``diameter_m`` (m).

    A hawser: ``anchor_height_m`` (m up from the waterline, >= 0) puts the far end at a fixed point in the air
    above ``anchor`` instead of on the seabed; its fairlead must be above the waterline too."""

    name: str
    anchor: tuple[float, float]
    fairlead: tuple[float, float, float]
    length_m: float
    material: str = "chain"
    diameter_m: float = 0.1
    anchor_depth_m: float | None = None
    anchor_height_m: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.strip():
            raise ParameterError(f"a mooring line's name must be a non-empty string, got {self.name!r}")
        where = f"line {self.name}"
        if np.shape(self.anchor) != (2,):
            raise ParameterError(f"{where}: anchor must be (north m, east m), got {self.anchor!r}")
        if np.shape(self.fairlead) != (3,):
            raise ParameterError(f"{where}: fairlead must be (x m forward, y m to starboard, z m up), "
                                 f"got {self.fairlead!r}")
        object.__setattr__(self, "anchor", tuple(require_finite(f"{where}: anchor", v) for v in self.anchor))
        object.__setattr__(self, "fairlead", tuple(require_finite(f"{where}: fairlead", v) for v in self.fairlead))
        if require_finite(f"{where}: length_m", self.length_m) <= 0.0:
            raise ParameterError(f"{where}: length_m must be > 0, got {self.length_m!r}")
        if self.anchor_depth_m is not None:
            require_finite(f"{where}: anchor_depth_m", self.anchor_depth_m)
        if self.anchor_height_m is not None:
            height = require_finite(f"{where}: anchor_height_m", self.anchor_height_m)
            if self.anchor_depth_m is not None:
                raise ParameterError(f"{where}: give anchor_depth_m (an anchor on the seabed) or anchor_height_m (a "
                                     f"hawser's fixed point above the water), not both")
            if height < 0.0:
                raise ParameterError(f"{where}: fixed point {-height:.1f} m below the waterline: a hawser's far end is "
                                     f"a point above the water")
            if self.fairlead[2] < 0.0:
                raise ParameterError(f"{where}: fairlead {-self.fairlead[2]:.1f} m below the waterline: a hawser runs "
                                     f"in air")
        require_finite(f"{where}: diameter_m", self.diameter_m)
        try:
            kind = line_type(self.material, float(self.diameter_m))
        except ParameterError as error:
            raise ParameterError(f"{where}: {error}") from None
        if not self.hawser and kind.weight_n_m <= 0.0:
            raise ParameterError(f"{where}: {self.material} of {self.diameter_m:g} m floats (wet weight "
                                 f"{kind.weight_n_m:.0f} N/m): a catenary line must sink")

    @property
    def type(self) -> LineType:
        """Its properties from MoorPy's library."""
        return line_type(self.material, float(self.diameter_m))

    @property
    def hawser(self) -> bool:
        """Whether its far end is a fixed point above the water (``anchor_height_m`` given)."""
        return self.anchor_height_m is not None

    @property
    def weight_n_m(self) -> float:
        """The weight it hangs under (N/m): in air for a hawser, wet in sea water for an anchored line."""
        kind = self.type
        return kind.mass_kg_m * G if self.hawser else kind.weight_n_m


class Moorings:
    """``lines`` in water ``depth`` (m; ``math.inf``, deep water: hawsers only) holding a vessel whose set point is
    (0, 0) heading ``heading`` (rad, clockwise from north), the lines named in ``failed`` parted. Immutable:
    :meth:`with_failed` gives a copy.

    Refused (:class:`ParameterError`, one line naming the line and the numbers): no lines, two lines of one name,
    an anchor off the seabed or in deep water, a fairlead under the seabed, an anchor (or a hawser's fixed point)
    under its fairlead, a line too short to reach its fairlead without breaking, and one whose tension at the set
    point is above its breaking load."""

    def __init__(self, lines: Sequence[Line], depth: float, heading: float = 0.0,
                 failed: Iterable[str] = ()) -> None:
        depth = require_positive("depth_m", depth, allow_infinite=True)
        self.depth, self.heading = depth, require_finite("heading", heading)
        self.lines = tuple(lines)
        if not self.lines:
            raise ParameterError("moorings need at least one line")
        names = [line.name for line in self.lines]
        twice = sorted({name for name in names if names.count(name) > 1})
        if twice:
            raise ParameterError(f"line {twice[0]}: two lines of that name (line names must be unique)")
        self.names = tuple(names)
        self._ends_at, = read_only(np.array([(line.anchor[0], line.anchor[1], line.fairlead[0], line.fairlead[1])
                                             for line in self.lines], dtype=float))
        """Each line's far end (north m, east m) and fairlead (x m, y m), (n_lines, 4)."""
        self.mbl = np.array([line.type.mbl_n for line in self.lines])
        """Each line's minimum breaking load (N), (n_lines,)."""
        self.mbl.flags.writeable = False
        spans = _spans(0.0, 0.0, self.heading, self._ends_at)[:, 2].tolist()
        tables = [(self._check_hawser if line.hawser else self._check_and_tabulate)(line, span)
                  for line, span in zip(self.lines, spans)]
        self._tabulate(tables, [line.hawser for line in self.lines])
        self.failed: frozenset[str] = frozenset()
        self._intact, = read_only(np.ones(len(self.lines)))
        self._variants: dict[frozenset[str], Moorings] = {}
        if failed:
            self._fail(frozenset(failed))
        self.pretensions = self._pretensions()
        """Each line's fairlead tension at the set point (N), (n_lines,); 0 for a parted line."""

    # -- construction -------------------------------------------------------------------------------------------

    def _check_and_tabulate(self, line: Line, span: float) -> tuple[np.ndarray, np.ndarray]:
        where, depth = f"line {line.name}", self.depth
        if math.isinf(depth):
            raise ParameterError(f"{where}: an anchor on the seabed needs a water depth, got deep water (only a "
                                 f"hawser to a fixed point moors a vessel there)")
        if line.anchor_depth_m is not None and abs(line.anchor_depth_m - depth) > ANCHOR_DEPTH_TOLERANCE_M:
            off = depth - line.anchor_depth_m
            raise ParameterError(f"{where}: anchor {abs(off):.1f} m {'above' if off > 0 else 'below'} the seabed "
                                 f"(depth {depth:g} m)")
        height = depth + line.fairlead[2]
        if height <= 0.0:
            raise ParameterError(f"{where}: fairlead {-line.fairlead[2]:.1f} m below the waterline, under the seabed "
                                 f"(depth {depth:g} m)")
        if span < MIN_SPAN_M:
            raise ParameterError(f"{where}: anchor {span:.2f} m from under its fairlead at the set point: a catenary "
                                 f"line runs out from the vessel (at least {MIN_SPAN_M:g} m)")
        kind = line.type
        reach_length = line.length_m * (1.0 + kind.mbl_n / kind.ea_n)
        straight = math.hypot(span, height)
        if reach_length <= straight:
            raise ParameterError(f"{where}: {line.length_m:.1f} m long, too short to reach its fairlead {straight:.1f} "
                                 f"m from the anchor (stretched to its breaking load: {reach_length:.1f} m)")
        from moorpy.helpers import CatenaryError

        try:
            hv = _catenary(line.length_m, kind.ea_n, kind.weight_n_m, height, 0.0, depth, span)[:2]
            pretension = math.hypot(*hv)
        except CatenaryError:
            raise ParameterError(f"{where}: MoorPy's catenary fails at the set point ({line.length_m:g} m of line, "
                                 f"{height:g} m high over {span:.1f} m)") from None
        if pretension >= kind.mbl_n:
            raise ParameterError(f"{where}: tension {pretension / 1e6:.2f} MN at the set point is above its breaking "
                                 f"load {kind.mbl_n / 1e6:.2f} MN: the line is too short for an anchor {span:.1f} m "
                                 f"out")
        reach = min(REACH_FRACTION * span, REACH_MAX_M)
        step = 0.5 / 2.0 ** max(0, math.ceil(math.log2(GRID_INTERVALS * 0.5 / (2.0 * reach))))
        first, last = math.floor((span - reach) / step), math.ceil((span + reach) / step)
        try:
            return _table(line.length_m, kind.ea_n, kind.weight_n_m, height, 0.0, depth, first * step, step,
                          last - first + 1, TAUT_LIMIT * kind.mbl_n)
        except ParameterError as error:
            raise ParameterError(f"{where}: {error}") from None

    def _check_hawser(self, line: Line, span: float) -> tuple[np.ndarray, np.ndarray]:
        """Check a hawser at horizontal ``span`` (m) from its fixed point at the set point and tabulate it from well
        slack to past :data:`TAUT_LIMIT` times its breaking load."""
        where, kind, length = f"line {line.name}", line.type, line.length_m
        rise = line.fairlead[2] - line.anchor_height_m  # fairlead above the fixed point (m)
        seabed = min(self.depth, 2.0 * length)  # the water depth, or deeper than the hawser can hang (same tensions)
        below = seabed + line.anchor_height_m  # seabed below the fixed point (m)
        if span < MIN_SPAN_M:
            raise ParameterError(f"{where}: fixed point {span:.2f} m from over its fairlead at the set point: a hawser "
                                 f"runs out from the vessel (at least {MIN_SPAN_M:g} m)")
        reach_length = length * (1.0 + kind.mbl_n / kind.ea_n)
        straight = math.hypot(span, rise)
        if reach_length <= straight:
            raise ParameterError(f"{where}: {length:.1f} m long, too short to reach its fairlead {straight:.1f} m "
                                 f"from the fixed point (stretched to its breaking load: {reach_length:.1f} m)")
        from moorpy.helpers import CatenaryError

        try:
            pretension = math.hypot(*_catenary(length, kind.ea_n, line.weight_n_m, rise, below, seabed, span)[:2])
        except CatenaryError:
            raise ParameterError(f"{where}: MoorPy's catenary fails at the set point ({length:g} m of hawser, "
                                 f"{rise:+g} m high over {span:.1f} m)") from None
        if pretension >= kind.mbl_n:
            raise ParameterError(f"{where}: tension {pretension / 1e6:.2f} MN at the set point is above its breaking "
                                 f"load {kind.mbl_n / 1e6:.2f} MN: the hawser is too short for a fixed point "
                                 f"{straight:.1f} m from its fairlead")
        reach = min(REACH_FRACTION * span, REACH_MAX_M)
        straight_span = math.sqrt(max(length * length - rise * rise, 0.0))  # just taut, unstretched (m)
        limit_span = math.sqrt(max((length * (1.0 + TAUT_LIMIT * kind.mbl_n / kind.ea_n)) ** 2 - rise * rise, 0.0))
        low = max(min(SLACK_FRACTION * straight_span, span - reach), 0.5 * MIN_SPAN_M)
        high = max(limit_span, span + reach) + 1.0
        step = 0.5 / 2.0 ** max(0, math.ceil(math.log2(GRID_INTERVALS * 0.5 / (high - low))))
        first, last = math.floor(low / step), math.ceil(high / step)
        try:
            spans, hv = _table(length, kind.ea_n, line.weight_n_m, rise, below, seabed, first * step, step,
                               last - first + 1, TAUT_LIMIT * kind.mbl_n)
        except ParameterError as error:
            raise ParameterError(f"{where}: {error}") from None
        if spans[0] >= span:
            raise ParameterError(f"{where}: MoorPy's catenary fails for the slack hawser out to {spans[0]:.1f} m, "
                                 f"beyond the set point's {span:.1f} m")
        return spans, hv

    def _tabulate(self, tables: list[tuple[np.ndarray, np.ndarray]], hold_slack: Sequence[bool]) -> None:
        """Each line's cubic pieces of (H, V) against span, as :func:`_hv` reads them: ``_table`` (n_lines, 13) its
        first span (m), last span (m), step (m), last piece, least V (N: 0, or none for a hawser) and the ends' (H,
        V, dH/ds, dV/ds) at the first and last span; ``_pieces`` (all pieces, 8) the pieces' coefficients (H3, V3,
        H2, V2, H1, V1, H0, V0), line ``i``'s from row ``_first[i]``. The lines of ``hold_slack`` (hawsers) are
        held at their slack end's values below their table."""
        rows, pieces, first = [], [], [0]
        for (spans, hv), hawser in zip(tables, hold_slack):
            spline = CubicSpline(spans, hv)
            slope = spline.derivative()
            pieces.append(spline.c.transpose(1, 0, 2).reshape(len(spans) - 1, 8))
            first.append(first[-1] + len(spans) - 1)
            low = (*spline(spans[0]), *slope(spans[0]))
            high = (*spline(spans[-1]), *slope(spans[-1]))
            ends = (*low[:2], *((0.0, 0.0) if hawser else low[2:]), *high)
            rows.append((spans[0], spans[-1], spans[1] - spans[0], len(spans) - 2, -math.inf if hawser else 0.0,
                         *ends))
        self._table, self._pieces, self._first = read_only(np.array(rows, dtype=float),
                                                           np.ascontiguousarray(np.concatenate(pieces)),
                                                           np.array(first[:-1], dtype=np.int64))

    @property
    def packed(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """What :func:`moorings_force` reads after the position (read-only): the lines' ends (n_lines, 4), their
        tables (:meth:`_tabulate`) and which are intact (1.0) or parted (0.0), (n_lines,)."""
        return self._ends_at, self._table, self._pieces, self._first, self._intact

    @property
    def span_range(self) -> np.ndarray:
        """Each line's tabulated horizontal span (m), (n_lines, 2): beyond it the tension is extrapolated."""
        return self._table[:, :2].copy()

    # -- failures -----------------------------------------------------------------------------------------------

    def with_failed(self, *names: str) -> Moorings:
        """These moorings with the lines ``names`` parted as well (an instructor's fault); cheap, the tables
        shared. An unknown name is refused."""
        failed = self.failed | frozenset(names)
        if failed == self.failed:
            return self
        if failed not in self._variants:
            if len(self._variants) >= 64:
                self._variants.pop(next(iter(self._variants)))
            variant = object.__new__(Moorings)
            variant.__dict__.update(self.__dict__)
            variant._variants = {}
            variant._fail(failed)
            variant.pretensions = variant._pretensions()
            self._variants[failed] = variant
        return self._variants[failed]

    def _fail(self, failed: frozenset[str]) -> None:
        unknown = sorted(failed - set(self.names))
        if unknown:
            raise ParameterError(f"line {unknown[0]}: no such mooring line (lines: {', '.join(self.names)})")
        self.failed = failed
        self._intact, = read_only(np.array([0.0 if name in failed else 1.0 for name in self.names]))

    def _pretensions(self) -> np.ndarray:
        tensions = self.tensions(0.0, 0.0, self.heading)
        tensions.flags.writeable = False
        return tensions

    # -- loads --------------------------------------------------------------------------------------------------

    def force(self, north: float, east: float, psi: float) -> np.ndarray:
        """The intact lines' pull on the vessel at (``north``, ``east``, ``psi``): (X N forward, Y N to starboard,
        N N m bow to starboard) in body axes about her origin, (3,)."""
        return np.array(moorings_force(north, east, psi, *self.packed))

    def tensions(self, north: float, east: float, psi: float) -> np.ndarray:
        """Each line's tension at its fairlead, ``hypot(H, V)`` (N), (n_lines,); 0 for a parted line."""
        return _tensions(north, east, psi, *self.packed)

    def stiffness(self, north: float = 0.0, east: float = 0.0, psi: float | None = None) -> np.ndarray:
        """The restoring stiffness ``K = -d(X, Y, N) / d(x, y, psi)`` (3, 3; N/m, N/rad, N m/m, N m/rad) at
        (``north``, ``east``, ``psi``; ``psi`` None: the set point's heading) for small displacements x forward, y
        to starboard (body axes) and in yaw, by central differences of :meth:`force`."""
        psi = self.heading if psi is None else psi
        c, s = math.cos(psi), math.sin(psi)
        steps = (0.01, 0.01, 1e-5)
        moves = (np.array([c, s, 0.0]), np.array([-s, c, 0.0]), np.array([0.0, 0.0, 1.0]))
        k = np.empty((3, 3))
        for j, (h, move) in enumerate(zip(steps, moves)):
            plus = self.force(*(np.array([north, east, psi]) + h * move))
            minus = self.force(*(np.array([north, east, psi]) - h * move))
            k[:, j] = -(plus - minus) / (2.0 * h)
        return k


# The lines' loads at a position, compiled: the simulation asks at each stage of each step.

@compiled
def _spans(north: float, east: float, psi: float, ends_at: np.ndarray) -> np.ndarray:
    """From each fairlead to its far end, the vessel at (``north``, ``east``, ``psi``): north and east (m) and the
    horizontal span (m), (n_lines, 3); ``ends_at`` (n_lines, 4) as :attr:`Moorings.packed`."""
    c, s = math.cos(psi), math.sin(psi)
    out = np.empty((ends_at.shape[0], 3))
    for i in range(ends_at.shape[0]):
        anchor_north, anchor_east, x, y = ends_at[i, 0], ends_at[i, 1], ends_at[i, 2], ends_at[i, 3]
        d_north = anchor_north - (north + x * c - y * s)
        d_east = anchor_east - (east + x * s + y * c)
        out[i, 0], out[i, 1], out[i, 2] = d_north, d_east, math.hypot(d_north, d_east)
    return out


@compiled
def _hv(i: int, span: float, table: np.ndarray, pieces: np.ndarray, first: np.ndarray, intact: np.ndarray
        ) -> tuple[float, float]:
    """Line ``i``'s horizontal tension and vertical pull down (N) at its fairlead at horizontal ``span`` (m):
    ``H`` >= 0, ``V`` >= 0 but for a hawser; both 0 for a parted line. The cubic piece of its table, or a straight
    line on from its ends."""
    if math.isnan(span):
        return math.nan, math.nan
    lo, hi, step, last, least = table[i, 0], table[i, 1], table[i, 2], int(table[i, 3]), table[i, 4]
    if span < lo:
        h, v = table[i, 5] + table[i, 7] * (span - lo), table[i, 6] + table[i, 8] * (span - lo)
    elif span > hi:
        h, v = table[i, 9] + table[i, 11] * (span - hi), table[i, 10] + table[i, 12] * (span - hi)
    else:
        k = min(max(math.floor((span - lo) / step), 0), last)
        t = span - (lo + k * step)
        c = pieces[first[i] + k]  # H3, V3, H2, V2, H1, V1, H0, V0
        h, v = ((c[0] * t + c[2]) * t + c[4]) * t + c[6], ((c[1] * t + c[3]) * t + c[5]) * t + c[7]
    return max(h, 0.0) * intact[i], max(v, least) * intact[i]


@compiled
def moorings_force(north: float, east: float, psi: float, ends_at: np.ndarray, table: np.ndarray,
                   pieces: np.ndarray, first: np.ndarray, intact: np.ndarray) -> tuple[float, float, float]:
    """:meth:`Moorings.force` (X N, Y N, N N m) with the lines packed (:attr:`Moorings.packed`)."""
    c, s = math.cos(psi), math.sin(psi)
    spans = _spans(north, east, psi, ends_at)
    x_sum = y_sum = moment = 0.0
    for i in range(ends_at.shape[0]):
        d_north, d_east, span = spans[i, 0], spans[i, 1], spans[i, 2]
        h = _hv(i, span, table, pieces, first, intact)[0] / max(span, 1e-9)
        f_north, f_east = h * d_north, h * d_east
        x_force, y_force = f_north * c + f_east * s, -f_north * s + f_east * c
        x, y = ends_at[i, 2], ends_at[i, 3]
        x_sum, y_sum, moment = x_sum + x_force, y_sum + y_force, moment + (x * y_force - y * x_force)
    return x_sum, y_sum, moment


@compiled
def _tensions(north: float, east: float, psi: float, ends_at: np.ndarray, table: np.ndarray, pieces: np.ndarray,
              first: np.ndarray, intact: np.ndarray) -> np.ndarray:
    """:meth:`Moorings.tensions` (N, (n_lines,)) with the lines packed (:attr:`Moorings.packed`)."""
    spans = _spans(north, east, psi, ends_at)
    out = np.empty(ends_at.shape[0])
    for i in range(ends_at.shape[0]):
        h, v = _hv(i, spans[i, 2], table, pieces, first, intact)
        out[i] = math.hypot(h, v)
    return out


def _catenary(length: float, ea: float, weight: float, height: float, below: float, depth: float, span: float,
              guess: tuple[float, float] = (0.0, 0.0)) -> tuple[float, float, tuple[float, float]]:
    """MoorPy's catenary from the far end to a fairlead ``height`` (m, < 0: below it) above it and ``span`` (m)
    away, the far end an anchor on the seabed (``below`` 0) or a fixed point ``below`` m above the seabed (the line
    clear of it), in water ``depth`` (m): the fairlead's horizontal tension and vertical pull down (N), and MoorPy's
    solved (HF, VF) to start the next solve from (its own line's end B, which it may have swapped)."""
    from moorpy.Catenary import catenary

    *_, fx_b, fz_b, info = catenary(span, height, length, ea, weight, CB=-below, HF0=guess[0], VF0=guess[1],
                                    depth=depth)
    return -float(fx_b), -float(fz_b), (float(info["HF"]), float(info["VF"]))


@functools.lru_cache(maxsize=256)
def _table(length: float, ea: float, weight: float, height: float, below: float, depth: float, start: float,
           step: float, count: int, limit: float) -> tuple[np.ndarray, np.ndarray]:
    """Spans ``start + i step`` (m, i < ``count``) and the fairlead's (H, V) there (N), (m,) and (m, 2), the line as
    :func:`_catenary`'s; cut after the first span whose tension passes ``limit`` (N) or where the catenary fails on
    the taut side. A hawser's (``below`` > 0) spans where the catenary fails while the line is slack, before any
    it solves, are left out (the table then starts later)."""
    from moorpy.helpers import CatenaryError

    spans = start + step * np.arange(count)
    rows, guess, skipped = [], (0.0, 0.0), 0
    for span in spans:
        try:
            h, v, guess = _catenary(length, ea, weight, height, below, depth, float(span), guess)
        except CatenaryError:
            if not rows and below > 0.0 and math.hypot(span, height) < length:
                skipped += 1
                continue
            if len(rows) < 4:
                raise ParameterError(f"MoorPy's catenary fails for a {length:g} m line {height:g} m high over "
                                     f"{span:g} m") from None
            break
        rows.append((h, v))
        if math.hypot(h, v) > limit and len(rows) >= 4:
            break
    hv = np.array(rows)
    hv.flags.writeable = False
    spans = spans[skipped: skipped + len(rows)].copy()
    spans.flags.writeable = False
    return spans, hv
