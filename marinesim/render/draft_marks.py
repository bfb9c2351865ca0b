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


def reading(draft_m: float) -> str:
    """What the numeral whose lower edge is at ``draft_m`` (a multiple of :data:`STEP_M`) reads."""
    tenths = round(draft_m * 10.0)
    return f"{tenths // 10}M" if tenths % 10 == 0 else str(tenths % 10)


@dataclass(frozen=True)
class DraftMarks:
    """Where the marks are (body frame, m): the x of the forward, midship and aft marks, the keel's z (drafts
    are read from it) and the highest mark's z (the lowest deck edge at the three)."""

    stations_x: tuple[float, float, float]
    keel_z: float
    top_z: float

    def uniforms(self) -> dict[str, object]:
        """The uniforms of ``shaders/vessel.frag``."""
        return {"u_marks_x": self.stations_x, "u_marks_z": (self.keel_z, self.top_z)}


NO_MARKS = {"u_marks_x": (0.0, 0.0, 0.0), "u_marks_z": (0.0, -1.0)}
"""The uniforms for a vessel without marks (the highest mark below the keel)."""


def draft_marks(hull: Hull, drawn: np.ndarray) -> DraftMarks | None:
    """The marks of ``hull`` (its waterline's ends and its keel) up to the deck edge of the ``drawn`` mesh's
    vertices (n, 3) at the three stations; None for a hull without a waterline."""
    loops = waterline_loops(hull)
    if not loops:
        return None
    x = np.concatenate(loops)[:, 0]
    inset = END_STATION * float(np.ptp(x))
    forward, aft = float(x.max()) - inset, float(x.min()) + inset
    stations = (forward, 0.5 * (forward + aft), aft)
    drawn = np.asarray(drawn, float)
    tops = []
    for station in stations:
        near = drawn[np.abs(drawn[:, 0] - station) < 2.0]
        if not len(near):
            return None
        side = near[np.abs(near[:, 1]) >= 0.9 * np.abs(near[:, 1]).max()]   # the plating at the ship's side
        tops.append(float(side[:, 2].max()))
    return DraftMarks(stations, float(np.asarray(hull.vertices)[:, 2].min()), min(tops))
