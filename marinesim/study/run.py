"""An operability study from a scenario and a scatter diagram: the frequency-domain figures for every
(Tp, heading, criterion), the operability they give, and optionally their time-domain check.

The scenario gives the vessel (RAO table, points, speed), the criteria and their limits, and the shape of
the sea: its first ``[[sea]]`` spectrum's type and gamma, its spreading and the water depth. Each scatter
cell becomes that spectrum with the cell's Hs and Tp (a Tz table is turned into Tp with the shape's Tz/Tp).
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from marinesim import __version__
from marinesim.criteria import spectral
from marinesim.criteria.quantities import CRANE_QUANTITIES, STATION_QUANTITIES
from marinesim.errors import ParameterError, ScenarioError
from marinesim.scenario import Scenario
from marinesim.sea.kinds import BREAKING_DEPTH_RATIO, BREAKING_STEEPNESS
from marinesim.sea.seastate import SeaState, WaveSystem
from marinesim.sea.spreading import LongCrested
from marinesim.session.sidecar import sha256
from marinesim.study import results
from marinesim.study.alpha import AlphaTable
from marinesim.study.operability import Operability, operability
from marinesim.study.scatter import Scatter, read_scatter, steepness
from marinesim.vessel.response import OUTSIDE_HEADINGS_SHARE

MAX_TASKS = 1_000_000
"""The most time-domain tasks one study may ask for."""
FINE_STEP = ("msdv_m_s1_5", "msi_pct", "slamming_probability")
"""Quantities whose time-domain check records at 0.1 s, not 0.5 s: W_f filters up to 0.63 Hz, and the slamming
velocity is a difference of the record (14 % low at 0.5 s in head seas at speed, 0.3 % at 0.1 s)."""


@dataclass(frozen=True)
class Study:
    """What a study evaluates: the scenario's vessel and ``criteria`` (all with limits), the sea's ``system``
    shape over ``depth_m``, the ``scatter`` with each cell's peak period ``cell_tp`` (cells,) s, the study's
    peak periods ``tp`` (T,) s and relative wave ``headings_deg`` (H,), and the exposure ``duration_s``
    (most probable maxima and doses)."""

    scenario: Scenario
    scatter: Scatter
    system: WaveSystem
    depth_m: float
    cell_tp: np.ndarray
    tp: np.ndarray
    headings_deg: np.ndarray
    duration_s: float

    @property
    def criteria(self):
        """The scenario's criteria on the wave-frequency motions: a station-keeping footprint is the simulation's
        (her low-frequency excursions), not the spectra's, and a crane's load's the lift's."""
        return motion_criteria(self.scenario)

    @property
    def names(self) -> list[str]:
        return [c.label for c in self.criteria]

    def sea(self, hs: float, tp: float, heading_deg: float) -> SeaState:
        """The study's sea of (``hs`` m, ``tp`` s) travelling at ``heading_deg`` relative to the bow."""
        spectrum = replace(self.system.spectrum, hs=hs, tp=tp)
        return SeaState((WaveSystem(spectrum, math.radians(heading_deg), self.system.spreading),), self.depth_m)


def motion_criteria(scenario: Scenario) -> tuple:
    """``scenario``'s criteria less a station-keeping vessel's (:data:`STATION_QUANTITIES`) and a crane's load's
    (:data:`CRANE_QUANTITIES`: the lift's, which depend on the crane operator, not on the vessel's response alone)."""
    return tuple(c for c in scenario.criteria if c.quantity not in STATION_QUANTITIES + CRANE_QUANTITIES)


def prepare(scenario: Scenario, scatter_path: Path, headings_deg: np.ndarray, duration_h: float) -> Study:
    """The study of ``scenario`` over the scatter file at ``scatter_path``; refuses a scenario without a
    vessel, a criterion without a limit, or a sea without a spectrum."""
    if scenario.vessel is None:
        raise ScenarioError(f"{scenario.path}: an operability study needs a [vessel]")
    if not motion_criteria(scenario):
        raise ScenarioError(f"{scenario.path}: no [[criteria]]: nothing limits the operation")
    unlimited = [c.label for c in motion_criteria(scenario) if c.limit is None]
    if unlimited:
        raise ScenarioError(f"{scenario.path}: criteria without a limit: {', '.join(unlimited)}")
    systems = scenario.sea.spectral_systems
    if not systems:
        raise ScenarioError(f"{scenario.path}: the first [[sea]] must be a spectrum (it gives the study's sea shape)")
    headings = np.asarray(headings_deg, float)
    if headings.ndim != 1 or headings.size == 0 or headings.size > 360 or np.unique(headings).size != headings.size:
        raise ParameterError("--headings must give 1 to 360 different headings")
    duration = 3600.0 * duration_h
    if not 60.0 <= duration <= 30 * 24 * 3600.0:
        raise ParameterError(f"--duration-h must be between 1/60 and 720 h, got {duration_h!r}")
    scatter = read_scatter(scatter_path)
    system = systems[0]
    cell_tp = scatter.period if scatter.period_kind == "tp" else scatter.period / tz_over_tp(system, scenario.sea.depth)
    _check_steepness(scatter, cell_tp)
    deepest_sea = float(scatter.hs.max())
    if deepest_sea > BREAKING_DEPTH_RATIO * scenario.sea.depth:  # refused now, not in the middle of the study
        raise ParameterError(f"{scatter_path}: Hs {deepest_sea:g} m breaks in the scenario's {scenario.sea.depth:g} m "
                             f"of water (H > {BREAKING_DEPTH_RATIO:g} x depth): leave out the cells above "
                             f"{BREAKING_DEPTH_RATIO * scenario.sea.depth:.3g} m")
    tp = np.unique(cell_tp)
    _check_covered(scenario, system, np.sort(headings), float(np.median(tp)))
    return Study(scenario, scatter, system, scenario.sea.depth, cell_tp, tp, np.sort(headings), duration)


def _check_steepness(scatter: Scatter, cell_tp: np.ndarray) -> None:
    """Refuse a scatter cell steeper than breaking (:data:`~marinesim.sea.kinds.BREAKING_STEEPNESS`) at its peak
    period ``cell_tp`` (s): no sea state is, and counting it would make the study's percentages meaningless."""
    steep = np.flatnonzero(steepness(scatter.hs, cell_tp) > BREAKING_STEEPNESS)
    if steep.size:
        i = int(steep[0])
        period = (f"Tp {cell_tp[i]:g} s" if scatter.period_kind == "tp"
                  else f"Tz {scatter.period[i]:g} s (Tp {cell_tp[i]:.3g} s in the scenario's spectrum)")
        raise ParameterError(f"{scatter.source}: the cell Hs {scatter.hs[i]:g} m, {period} is steeper than breaking: "
                             f"Hs / Lp = {steepness(scatter.hs[i], cell_tp[i]):.3g} > 1/7 (Lp = g Tp^2 / 2 pi, "
                             f"deep water); {steep.size} such cell(s)")


def _check_covered(scenario: Scenario, system: WaveSystem, headings_deg: np.ndarray, tp: float) -> None:
    """A partial RAO table answers only the headings it covers: refuse a study heading whose waves (the sea's
    spreading about it, at the peak frequency of the middle Tp) put more than the share a run allows outside."""
    rao = scenario.vessel.rao
    if rao.covered is None:
        return
    if isinstance(system.spreading, LongCrested):
        offsets, weights = np.zeros(1), np.ones(1)
    else:
        offsets = spectral.SPREAD
        weights = system.spreading.density(offsets, np.full(offsets.size, 2.0 * math.pi / tp))
    refused = [h for h in headings_deg
               if weights[~rao.covers(math.radians(h) + offsets)].sum() > OUTSIDE_HEADINGS_SHARE * weights.sum()]
    if refused:
        raise ParameterError(f"the RAO table covers relative wave headings {rao.covered_text()} only: the sea's "
                             f"waves at --headings {', '.join(f'{h:g}' for h in refused)} deg meet the vessel "
                             "outside them (give headings inside, or a long-crested sea)")


def tz_over_tp(system: WaveSystem, depth_m: float) -> float:
    """Tz / Tp of ``system``'s spectrum shape (the same at every Tp in deep water; at 10 s otherwise)."""
    sea = SeaState((WaveSystem(replace(system.spectrum, hs=1.0, tp=10.0), system.beta, system.spreading),), depth_m)
    return sea.tz / 10.0


def frequency_domain(study: Study) -> spectral.SpectralCriteria:
    """Each criterion at Hs = 1 m for every (Tp, heading), from the response spectra."""
    vessel = study.scenario.vessel
    return spectral.criteria_at_unit_hs(vessel.rao, vessel.points, vessel.speed_m_s, list(study.criteria),
                                        study.system, study.depth_m, study.tp, study.headings_deg,
                                        study.duration_s)


def evaluate(study: Study, alpha: float = 1.0, table: AlphaTable | None = None,
             planned_period_h: float | None = None) -> tuple[spectral.SpectralCriteria, Operability]:
    """The spectral criteria and the operability they give with forecast limits: every limiting Hs times
    ``alpha`` (in (0, 1]), or with ``table`` the alpha of the planned operation period ``planned_period_h``
    (T_POP, h) at that limiting Hs
    (DNV-ST-N001's alpha factor, :mod:`marinesim.study.alpha`)."""
    if not 0.0 < alpha <= 1.0:
        raise ParameterError(f"--alpha must be in (0, 1], got {alpha!r}")
    estimates = frequency_domain(study)
    limiting = alpha * estimates.limiting_hs(np.array([c.limit for c in study.criteria], float))
    if table is not None:
        limiting = table.forecast_limit(planned_period_h, limiting)
    return estimates, operability(limiting, study.tp, study.headings_deg, study.scatter, study.cell_tp)


def attributes(study: Study, alpha: float, table: AlphaTable | None = None,
               planned_period_h: float | None = None) -> dict:
    """The inputs and settings a study's files name (paths, sha256, spectrum shape, alpha factor)."""
    vessel = study.scenario.vessel
    spectrum = study.system.spectrum
    return {"marinesim": __version__, "scenario": str(study.scenario.path),
            "scenario_sha256": sha256(study.scenario.path), "scatter": study.scatter.source,
            "scatter_sha256": sha256(Path(study.scatter.source)), "rao": str(vessel.rao_path),
            "rao_sha256": sha256(vessel.rao_path), "speed_kn": vessel.speed_kn,
            "spectrum": type(spectrum).__name__, "gamma": float(getattr(spectrum, "gamma", 1.0) or 1.0),
            "spreading": repr(study.system.spreading), "depth_m": str(study.depth_m),
            "duration_h": study.duration_s / 3600.0, "alpha": alpha,
            "scatter_period": study.scatter.period_kind,
            **({} if table is None else {"alpha_table": table.source, "alpha_table_sha256": sha256(Path(table.source)),
                                         "planned_period_h": planned_period_h})}


def fingerprint(study: Study, attrs: dict, seeds: int, cells: np.ndarray, record_s: float) -> str:
    """A name for a time-domain store: the inputs' hashes and every setting that changes a task's numbers."""
    text = repr((attrs, seeds, cells.tolist(), record_s, study.headings_deg.tolist(), study.tp.tolist()))
    return hashlib.sha256(text.encode()).hexdigest()


def write(study: Study, estimates: spectral.SpectralCriteria, result: Operability, out_dir: Path, attrs: dict,
          extra: dict | None = None) -> list[Path]:
    """The study's files in ``out_dir`` (see :mod:`marinesim.study.results`); ``extra`` adds variables."""
    units = [c.measure.unit for c in study.criteria]
    limits = np.array([c.limit for c in study.criteria], float)
    data = results.dataset(result, estimates.value1, study.names, units, limits, study.scatter, study.cell_tp, attrs)
    if extra:
        data = data.assign(extra)
    title = study.scenario.name
    return results.write_study(out_dir, data, results.summary_csv(result, study.names),
                               results.pictures(result, study.scatter, study.cell_tp, study.names, title))


def time_domain(study: Study, estimates: spectral.SpectralCriteria, seeds: int, cells: np.ndarray, store: Path,
                scheduler: str | None = None, workers: int | None = None, serial: bool = False) -> dict:
    """Check the spectral figures in the time domain: ``seeds`` records of the study's duration for each of
    ``cells`` (indices into the scatter) at every heading, through the same response synthesis and the same
    criteria as a live run, on Dask (see :mod:`marinesim.study.distributed`), kept in ``store``. Returns
    xarray variables over (check_cell, heading_deg, criterion): the time-domain mean over seeds, its
    standard error, and the spectral value of the cell's Hs for comparison."""
    from marinesim.study.distributed import run_tasks
    from marinesim.study.timedomain import Task, TimeDomainStudy

    if not 1 <= seeds <= 1000:
        raise ParameterError(f"--time-domain takes 1 to 1000 seeds, got {seeds}")
    cells = np.asarray(cells, int)
    if cells.size == 0 or cells.min() < 0 or cells.max() >= study.scatter.hs.size:
        raise ParameterError(f"--cells must be indices of the scatter's {study.scatter.hs.size} cells")
    vessel = study.scenario.vessel
    fine = any(c.quantity in FINE_STEP for c in study.criteria)
    dt = 0.1 if fine else 0.5
    base = study.scenario.run.seed
    td = TimeDomainStudy(vessel.rao, vessel.points, vessel.speed_m_s, tuple(study.criteria), study.system,
                         study.depth_m, study.scatter.hs[cells], study.cell_tp[cells], study.headings_deg,
                         tuple(base + k for k in range(seeds)), study.duration_s, dt)
    if td.tasks > MAX_TASKS:
        raise ParameterError(f"{td.tasks} time-domain tasks is more than {MAX_TASKS}: choose fewer --cells or seeds")
    attrs = attributes(study, 1.0)
    rows = run_tasks(Task(td), td.tasks, len(study.criteria), store,
                     fingerprint(study, attrs, seeds, cells, study.duration_s), scheduler, workers, serial)
    values = rows.reshape(td.shape + (len(study.criteria),))                   # (cells, H, seeds, C)
    mean = values.mean(axis=2)
    error = values.std(axis=2, ddof=1) / math.sqrt(seeds) if seeds > 1 else np.full_like(mean, np.nan)
    column = np.searchsorted(study.tp, study.cell_tp[cells])
    spectral_value = np.stack([estimates.value(np.full(estimates.value1.shape[:2], study.scatter.hs[cell]))[t]
                               for cell, t in zip(cells, column)])                                # (cells, H, C)
    dims = ("check_cell", "heading_deg", "criterion")
    return {"time_domain_mean": (dims, mean, {"long_name": "criterion over the records, mean over seeds"}),
            "time_domain_stderr": (dims, error, {"long_name": "standard error of that mean"}),
            "spectral_value": (dims, spectral_value, {"long_name": "the frequency-domain value at the cell's Hs"}),
            "check_cell_index": (("check_cell",), cells, {"long_name": "scatter cell of the time-domain check"})}

