"""Operability over a scatter diagram: in which sea states, at which headings, can the vessel do the job?

For a criterion whose value is linear in Hs (an RMS, a most probable maximum, a significant amplitude: all
proportional to the response's standard deviation), the limiting Hs of a (Tp, heading) is
``limit / value(Hs = 1 m)`` (others are solved for it); the operation's limiting Hs is the smallest over its criteria, and the
criterion that sets it *governs*. A sea state (Hs, Tp) is workable at a heading when Hs <= that limit.
Operability at a heading is the probability of the workable sea states; the overall figure takes, in each
sea state, the best heading (the vessel is free to choose it). With an alpha factor (DNV-ST-N001 4.3: a
forecast-based operation's limit is ``alpha x`` its design limit) the limiting Hs are multiplied by it
first (:func:`marinesim.study.run.evaluate`; an alpha table gives it per limiting Hs,
:mod:`marinesim.study.alpha`).

The limiting Hs per criterion comes from :class:`~marinesim.criteria.spectral.SpectralCriteria`; the rest
is array arithmetic over (heading, Tp, criterion).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from marinesim.errors import ParameterError
from marinesim.study.scatter import Scatter


@dataclass(frozen=True)
class Operability:
    """A study's figures. ``tp`` (T,) s are the scatter's peak periods, ``headings_deg`` (H,) the relative
    wave directions; ``limiting_hs`` (H, T, C) m per criterion and ``limiting_hs_all`` (H, T) m the smallest,
    ``governing`` (H, T) the index of the criterion that sets it; ``workable`` (cells, H) bool and
    ``operability_pct`` (H,) the probability (%) of the workable cells; ``overall_pct`` with the best heading
    in each sea state."""

    tp: np.ndarray
    headings_deg: np.ndarray
    limiting_hs: np.ndarray
    limiting_hs_all: np.ndarray
    governing: np.ndarray
    workable: np.ndarray
    operability_pct: np.ndarray
    overall_pct: float

    @property
    def best_heading_deg(self) -> float:
        """The heading with the highest operability (the first of equals)."""
        return float(self.headings_deg[int(np.argmax(self.operability_pct))])


def operability(limiting_hs: np.ndarray, tp: np.ndarray, headings_deg: np.ndarray, scatter: Scatter,
                cell_tp: np.ndarray) -> Operability:
    """The figures of a study from each criterion's limiting Hs, ``limiting_hs`` (T, H, C) m (inf where it
    never limits), at the peak periods ``tp`` (T,) s and headings (H,) deg; the cells of ``scatter`` with their
    peak periods ``cell_tp`` (cells,), each one of ``tp``."""
    limiting = np.asarray(limiting_hs, float)
    if limiting.ndim != 3 or limiting.shape[:2] != (tp.size, headings_deg.size):
        raise ParameterError(f"limiting_hs must be (Tp, heading, criterion) with {tp.size} Tp and "
                             f"{headings_deg.size} headings, got {limiting.shape}")
    limiting = np.moveaxis(limiting, 1, 0)                                                           # (H, T, C)
    limiting_all = limiting.min(axis=2)
    governing = limiting.argmin(axis=2)
    column = np.searchsorted(tp, cell_tp)
    if np.any(column >= tp.size) or np.any(tp[np.minimum(column, tp.size - 1)] != cell_tp):
        raise ParameterError("every cell's peak period must be one of the study's periods")
    workable = scatter.hs[:, None] <= limiting_all[:, column].T                                      # (cells, H)
    pct = 100.0 * scatter.probability @ workable
    overall = 100.0 * float(scatter.probability @ workable.any(axis=1))
    return Operability(tp, headings_deg, limiting, limiting_all, governing, workable, pct, overall)
