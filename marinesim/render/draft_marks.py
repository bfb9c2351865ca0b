"""Draft marks: metric numerals on both sides of the hull at the stem, amidships and the stern, painted by
``shaders/vessel.frag`` on the plating of whatever mesh is drawn (the hull's own or a visual mesh).

As ships carry them: numerals :data:`NUMERAL_M` high every :data:`STEP_M` of draft, the lower edge of each at
the draft it reads; whole metres read ``<n>M`` (``12M``), the others their decimetre (``2``, ``4``, ``6``,
``8``). The draft is measured from the keel (the hull's lowest point), so the calm waterline reads the hull's
draft. The numerals read left to right seen from outside: towards the bow on the starboard side, towards the
stern on the port side.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from marinesim.hull import Hull
from marinesim.hull.waterplane import waterline_loops

NUMERAL_M = 0.1
STEP_M = 0.2
GLYPH_WIDTH_M, ADVANCE_M, STROKE_M = 0.07, 0.09, 0.018
"""A numeral's width, the distance from one numeral to the next in ``12M``, and the stroke (m)."""
END_STATION = 0.015
"""The forward and aft marks stand this fraction of the waterline length in from its ends."""
DEEPEST = 1.5
"""The marks go up to this many times the still-water draft (the deepest a ship loads to is well within it)."""


def reading(draft_m: float) -> str:
    """What the numeral whose lower edge is at ``draft_m`` (a multiple of :data:`STEP_M`) reads."""
    tenths = round(draft_m * 10.0)
    return f"{tenths // 10}M" if tenths % 10 == 0 else str(tenths % 10)


@dataclass(frozen=True)
class DraftMarks:
    """Where the marks are (body frame, m), at the forward, midship and aft stations: their x, the keel line's z
    there (drafts are read from it: a trimmed hull reads its trim), the highest mark's z and the waterline's
    half-breadth (marks go only on plating at least half as far out)."""

    stations_x: tuple[float, float, float]
    keel_z: tuple[float, float, float]
    top_z: tuple[float, float, float]
    half_breadth_m: tuple[float, float, float]

    def uniforms(self) -> dict[str, object]:
        """The uniforms of ``shaders/vessel.frag``."""
        return {"u_marks_x": self.stations_x, "u_marks_keel": self.keel_z, "u_marks_top": self.top_z,
                "u_marks_half": self.half_breadth_m}


NO_MARKS = {"u_marks_x": (0.0,) * 3, "u_marks_keel": (0.0,) * 3, "u_marks_top": (-1.0,) * 3,
            "u_marks_half": (0.0,) * 3}
"""The uniforms for a vessel without marks (every top below its keel)."""

GLYPH = {"NUMERAL": NUMERAL_M, "STEP": STEP_M, "GLYPH_W": GLYPH_WIDTH_M, "ADVANCE": ADVANCE_M, "STROKE": STROKE_M}
"""The numerals' sizes (m) as ``shaders/vessel.frag``'s defines."""


def keel_line(hull: Hull) -> np.poly1d:
    """The keel's z (m) against x along the middle half of the hull: a straight line through the lowest point of
    each of 16 slices (the flat of the bottom; level unless the hull was loaded trimmed)."""
    v = np.asarray(hull.vertices, float)
    lo, hi = v[:, 0].min(), v[:, 0].max()
    edges = np.linspace(lo + 0.25 * (hi - lo), hi - 0.25 * (hi - lo), 17)
    slices = np.digitize(v[:, 0], edges)
    points = [(v[slices == i, 0].mean(), v[slices == i, 2].min()) for i in range(1, 17) if np.any(slices == i)]
    if len(points) < 2:
        return np.poly1d([float(v[:, 2].min())])
    x, z = np.array(points).T
    return np.poly1d(np.polyfit(x, z, 1))


def draft_marks(hull: Hull, drawn: np.ndarray) -> DraftMarks | None:
    """The marks of ``hull`` (its waterline's ends, its keel line) up to :data:`DEEPEST` times the draft, or to the
    top of the side plating of the ``drawn`` mesh's vertices (n, 3) at the station if lower; None for a hull
    without a waterline. A station with no drawn side above the water gets no marks (its top at its keel)."""
    loops = waterline_loops(hull)
    if not loops:
        return None
    waterline = np.concatenate(loops)
    inset = END_STATION * float(np.ptp(waterline[:, 0]))
    forward, aft = float(waterline[:, 0].max()) - inset, float(waterline[:, 0].min()) + inset
    stations = (forward, 0.5 * (forward + aft), aft)
    keel = keel_line(hull)
    drawn = np.asarray(drawn, float)
    keels, tops, halves = [], [], []
    for station in stations:
        keels.append(float(keel(station)))
        near = np.abs(waterline[:, 0] - station) < 2.0
        halves.append(float(np.abs(waterline[near, 1]).max()) if near.any() else 0.0)
        above = drawn[(np.abs(drawn[:, 0] - station) < 2.0) & (drawn[:, 2] > 0.0)]
        if not len(above):
            tops.append(keels[-1])
            continue
        side = above[np.abs(above[:, 1]) >= 0.9 * np.abs(above[:, 1]).max()]   # the plating at the ship's side
        tops.append(min(float(side[:, 2].max()), keels[-1] * (1.0 - DEEPEST)))
    return DraftMarks(stations, tuple(keels), tuple(tops), tuple(halves))
