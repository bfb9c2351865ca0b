"""The time-domain check of an operability study: each task synthesises one sea state at one heading with
one seed, the vessel's response to it, and the criteria over that record, exactly as a live exercise
evaluates them (:class:`~marinesim.criteria.monitor.Monitor`).

A task's summary, per criterion, is the median of the criterion's values over the record's consecutive
non-overlapping windows (its own window, e.g. 600 s; a dose: its value over the whole record). For an RMS
quantity that estimates the sea state's RMS; for a largest value, the median of the window maxima, which
the spectral most probable maximum in the window approaches (Rayleigh). Tasks return these few numbers,
never a time series.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from marinesim.criteria.monitor import Criterion, Monitor
from marinesim.errors import ParameterError
from marinesim.sea.ocean import Ocean
from marinesim.sea.seastate import SeaState, WaveSystem
from marinesim.session.assembly import VARIANCE_FRACTION
from marinesim.vessel.rao import RaoTable
from marinesim.vessel.response import Response, Track

TILES, RESOLUTION = 3, 128
"""The ocean each task synthesises: three cascades of 128^2 cells (99.9 % of a JONSWAP sea's variance), of
which the vessel responds to the largest components carrying :data:`VARIANCE_FRACTION` of it, as in a live
run (about 3000). At 64^2 too few distinct frequencies remain (cells on one |k| ring share one):
a 3 h record's RMS scatters by 10 % from seed to seed, against 4 % here."""
MAX_ROWS = 2_000_000
"""The longest record a task may synthesise (rows of dt)."""


@dataclass(frozen=True)
class TimeDomainStudy:
    """Every task of a study: sea states (``hs`` m, ``tp`` s; (cells,)) shaped as ``system`` (its spectrum's
    gamma and its spreading), met at ``headings_deg`` (relative wave directions of the RAO convention, (H,)),
    each with ``seeds``; the vessel (``rao``, ``points`` body frame m, ``speed_m_s``), the ``criteria``, and
    records of ``duration_s`` sampled every ``dt_s``. Task ``i`` is (cell, heading, seed) in C order."""

    rao: RaoTable
    points: dict[str, tuple[float, float, float]]
    speed_m_s: float
    criteria: tuple[Criterion, ...]
    system: WaveSystem
    depth_m: float
    hs: np.ndarray
    tp: np.ndarray
    headings_deg: np.ndarray
    seeds: tuple[int, ...]
    duration_s: float
    dt_s: float = 0.5

    def __post_init__(self) -> None:
        rows = self.duration_s / self.dt_s
        if not 1 <= rows <= MAX_ROWS:
            raise ParameterError(f"a time-domain record of {self.duration_s:g} s at dt {self.dt_s:g} s is "
                                 f"{rows:.0f} rows; at most {MAX_ROWS}")
        for criterion in self.criteria:
            if criterion.window is not None and criterion.window > self.duration_s:
                raise ParameterError(f"criterion {criterion.label!r}: its {criterion.window:g} s window is longer "
                                     f"than the {self.duration_s:g} s record")

    @property
    def shape(self) -> tuple[int, int, int]:
        """(cells, headings, seeds)."""
        return len(self.hs), len(self.headings_deg), len(self.seeds)

    @property
    def tasks(self) -> int:
        return int(np.prod(self.shape))

    def sea(self, cell: int, heading: int) -> SeaState:
        """The sea state of ``cell`` travelling at ``headings_deg[heading]`` to a vessel whose bow points
        along +x (so that the math direction of travel is the relative heading)."""
        spectrum = replace(self.system.spectrum, hs=float(self.hs[cell]), tp=float(self.tp[cell]))
        beta = math.radians(float(self.headings_deg[heading]))
        return SeaState((WaveSystem(spectrum, beta, self.system.spreading),), depth=self.depth_m)


def run_task(study: TimeDomainStudy, index: int) -> np.ndarray:
    """The summary (len(criteria),) of task ``index``: see the module docstring. Deterministic: the same
    task gives the same bits in any process (one thread)."""
    cell, heading, seed = np.unravel_index(index, study.shape)
    ocean = Ocean(study.sea(int(cell), int(heading)), tile_count=TILES, resolution=RESOLUTION,
                  seed=study.seeds[int(seed)], threads=1)
    components = ocean.components(variance_fraction=VARIANCE_FRACTION)
    response = Response(study.rao, components, Track(heading=0.0, speed=study.speed_m_s), study.points)
    criteria = list(study.criteria)
    monitor = Monitor(criteria, study.points, study.dt_s, study.duration_s)
    steps = int(round(study.duration_s / study.dt_s))
    window_rows = {i: monitor.window_rows(c) for i, c in enumerate(criteria) if c.window is not None}
    ends = sorted({k * n for n in window_rows.values() for k in range(1, steps // n + 1)} | {steps})
    samples: dict[int, list[float]] = {i: [] for i in window_rows}
    for frame in response.frames(0.0, study.dt_s, steps):
        lo, size = 0, frame["time_s"].size
        while lo < size:
            stop = min(size, next(e for e in ends if e > monitor.rows) - monitor.rows + lo)
            monitor.append({name: column[lo:stop] for name, column in frame.items()})
            lo = stop
            for i, n in window_rows.items():
                if monitor.rows % n == 0:
                    value = monitor.windowed(criteria[i])
                    if value is not None:
                        samples[i].append(value)
    final = monitor.evaluate()
    out = np.full(len(criteria), math.nan)
    for i, value in enumerate(final):
        if i in samples:
            out[i] = np.median(samples[i]) if samples[i] else math.nan
        elif value is not None:
            out[i] = value
    return out


class Task:
    """:func:`run_task` of ``study`` as a picklable callable of the task index (what a Dask worker receives)."""

    def __init__(self, study: TimeDomainStudy) -> None:
        self.study = study

    def __call__(self, index: int) -> np.ndarray:
        return run_task(self.study, index)
