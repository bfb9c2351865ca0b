"""What the after-action report shows, gathered from an exercise run (live, replayed or assessed).

:func:`debrief` turns an :class:`~marinesim.session.exercise.Exercise` that has run into the
:class:`Debrief` :mod:`marinesim.report.html` lays out: the briefing and a verdict per objective, each
criterion's running value at every evaluation, the events, alarms with their acknowledgements, the
messages and actions, motion sickness (MSI, MSDV) at the vessel's points, the ship's track and handling
(heading, speed, rudder, propeller), and the conditions; from a session log, whether the log is verified
(:class:`~marinesim.session.log.Verification`), for the report's header to say; of a run stopped before its
planned duration, how much of it ran, and which objectives it could not judge.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields

import numpy as np

from marinesim import __version__
from marinesim.angles import wave_compass_from_beta
from marinesim.criteria.monitor import Criterion, Level
from marinesim.criteria.sickness import MAX_WF_DT_S
from marinesim.scenario import Scenario
from marinesim.sea.seastate import SeaState
from marinesim.session.decisions import judge
from marinesim.session.exercise import EVERYONE, AlarmResult, CriterionResult, EventResult, Exercise, ran_words
from marinesim.session.log import SessionLog
from marinesim.session.sidecar import sha256
from marinesim.session.station import line_columns, station_record, thruster_columns

VERDICTS = {Level.OK: "met", Level.CAUTION: "met with caution", Level.EXCEEDED: "not met", Level.SETTLING: "no value"}
"""An objective's verdict from the worst level of the criteria that judge it, in a run that went through its
planned duration; in one stopped early an objective is "not met" if one of its criteria went above its limit,
else "not judged" (:meth:`~marinesim.session.exercise.Exercise.assessment`)."""


@dataclass(frozen=True)
class Series:
    """A criterion's running value (its unit; None while settling) at each evaluation time (s)."""

    time_s: list[float]
    value: list[float | None]


@dataclass(frozen=True, kw_only=True)
class CriterionTrace(CriterionResult):
    """A criterion's result over the run with its running value at every evaluation."""

    series: Series

    @classmethod
    def of(cls, result: CriterionResult, series: Series) -> CriterionTrace:
        return cls(**{f.name: getattr(result, f.name) for f in fields(CriterionResult)}, series=series)


@dataclass(frozen=True)
class Objective:
    """An objective of the briefing, the names of the criteria that judge it (or its decision is about), its verdict
    (:data:`VERDICTS`, or "not judged") and, for a decision (:mod:`~marinesim.session.decisions`), why."""

    text: str
    criteria: list[str]
    verdict: str
    why: str = ""


@dataclass(frozen=True)
class Briefing:
    """The briefing's text and its objectives."""

    text: str
    objectives: list[Objective]


@dataclass(frozen=True)
class LogCheck:
    """Whether the session log is verified, and the problems found in words where it is not."""

    verified: bool
    problems: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class Message:
    """A message at ``time_s`` (s) from its ``source``: "event" or "instructor"."""

    time_s: float
    text: str
    source: str


@dataclass(frozen=True)
class Action:
    """A live action at ``time_s`` (s), in words."""

    time_s: float
    what: str


@dataclass(frozen=True)
class Sickness:
    """Motion sickness at ``point`` over the run: MSI (%) and MSDV (m/s^1.5); None where not computed."""

    point: str
    msi_percent: float | None = None
    msdv_m_s1_5: float | None = None


@dataclass(frozen=True)
class SeaSystem:
    """One wave system of the sea at the start: Hs (m), Tp (s), where from (compass deg), JONSWAP gamma and
    spreading s where it has them."""

    hs_m: float
    tp_s: float
    from_deg: float
    gamma: float | None
    spreading_s: float | None


@dataclass(frozen=True)
class VesselConditions:
    """The vessel's RAO file and its sha256, her speed (kn) and heading (compass deg), and her points (name ->
    body-frame offset, m)."""

    rao: str
    rao_sha256: str | None
    speed_kn: float | None
    heading_deg: float | None
    points_m: dict[str, list[float]]


@dataclass(frozen=True, kw_only=True)
class Conditions:
    """What the run was made of: the scenario and log files with their sha256, the seed, the time run and planned
    (s), the time step (s), marinesim's version, the sea at the start and the vessel (None where not known)."""

    scenario: str | None = None
    scenario_sha256: str | None = None
    seed: int | None = None
    duration_s: float | None = None
    planned_s: float | None = None
    dt_s: float | None = None
    log: str | None = None
    log_sha256: str | None = None
    marinesim: str | None = None
    sea: list[SeaSystem] = field(default_factory=list)
    vessel: VesselConditions | None = None


@dataclass(frozen=True, kw_only=True)
class Debrief:
    """What the after-action report shows (:func:`debrief`); a part left out (None, empty) is left out of the page.
    ``alarms`` None: not known (an empty list: none raised). ``ship``: the ship's track and handling, columns of
    the record by name (:func:`_ship`)."""

    title: str | None = None
    source: str | None = None
    log_check: LogCheck | None = None
    briefing: Briefing | None = None
    verdict: str | None = None
    stopped_early: str | None = None
    """How much of a run stopped before its planned duration ran, in words (:func:`ran_words`)."""
    conditions: Conditions | None = None
    criteria: list[CriterionTrace] = field(default_factory=list)
    events: list[EventResult] = field(default_factory=list)
    alarms: list[AlarmResult] | None = None
    messages: list[Message] = field(default_factory=list)
    actions: list[Action] = field(default_factory=list)
    sickness: list[Sickness] = field(default_factory=list)
    ship: dict | None = None


def sickness_criteria(scenario: Scenario) -> list[Criterion]:
    """The motion-sickness criteria the debrief watches at each point: MSI, and MSDV where dt allows W_f."""
    vessel = scenario.vessel
    if vessel is None:
        return []
    quantities = ["msi_pct"] + (["msdv_m_s1_5"] if scenario.run.dt_s <= MAX_WF_DT_S else [])
    return [Criterion(q, point=point) for point in vessel.points for q in quantities]


def debrief(exercise: Exercise, log: SessionLog | None = None) -> Debrief:
    """The report's data from ``exercise`` (run with ``watch=sickness_criteria(...)``), its session ``log`` if any."""
    scenario = exercise.scenario
    result = exercise.assessment()
    criteria = [CriterionTrace.of(c, Series(exercise.evaluated_s, [values[i] for values in exercise.values]))
                for i, c in enumerate(result.criteria)]
    levels = {c.name: c.level for c in criteria}
    briefing = None
    if scenario.briefing is not None:
        objectives = []
        for objective in scenario.briefing.objectives:
            if objective.decision is not None:
                judged = judge(exercise, objective)
                objectives.append(Objective(objective.text, list(objective.criteria), judged.verdict, judged.why))
                continue
            worst = max((levels[name] for name in objective.criteria), default=Level.SETTLING)
            verdict = VERDICTS[worst] if result.complete or worst is Level.EXCEEDED else "not judged"
            objectives.append(Objective(objective.text, list(objective.criteria), verdict))
        briefing = Briefing(scenario.briefing.text, objectives)
    messages = [Message(h.time_s, h.event.message, "event") for h in exercise.happened if h.event.message]
    messages += [Message(t, text, "instructor" if to == EVERYONE else f"instructor to {to}")
                 for t, text, to in exercise.said]
    messages += [Message(t, text, f"report from {station or 'the trainee'}") for t, station, text in exercise.reports]
    actions = [Action(e["t"], _action(e)) for e in exercise.journal if e["kind"] == "action"]
    sickness = []
    if exercise.monitor is not None:
        by_point: dict[str, dict[str, float | None]] = {}
        for criterion in sickness_criteria(scenario):
            value = exercise.tally(criterion).value
            key = "msi_percent" if criterion.quantity == "msi_pct" else "msdv_m_s1_5"
            by_point.setdefault(criterion.point, {})[key] = value
        sickness = [Sickness(point, **values) for point, values in by_point.items()]
    return Debrief(
        title=scenario.name.replace("_", " "),
        source=str(log.path) if log is not None else str(scenario.path),
        log_check=None if log is None else LogCheck(log.verification.verified,
                                                    [words for _, words in log.verification.problems]),
        briefing=briefing,
        verdict=result.verdict,
        stopped_early=None if result.complete else ran_words(result.duration_s, result.planned_s),
        conditions=_conditions(exercise, log),
        criteria=criteria,
        events=result.events,
        alarms=result.alarms,
        messages=sorted(messages, key=lambda m: m.time_s),
        actions=actions,
        sickness=sickness,
        ship=_ship(exercise),
    )


SHIP_SAMPLES = 2000
"""The most samples of the ship's track and handling the report draws (one a second in shorter runs)."""


def _ship(exercise: Exercise) -> dict | None:
    """The ship's track and handling over the run (the record's ship columns), one sample a second or
    :data:`SHIP_SAMPLES` over the run if longer; None without a vessel."""
    sim = exercise.sim
    if sim.vessel is None:
        return None
    end = sim.time
    step = max(1.0, end / SHIP_SAMPLES)
    times = np.arange(0.0, end + 1e-9, step)
    record = sim.voyage.record(times, np.zeros(times.size))
    ship = sim.vessel.ship
    out = {"name": ship.name, "model": ship.describe(), "time_s": times.tolist()}
    for column in ("north_m", "east_m", "heading_deg", "speed_over_ground_kn", "rudder_deg", "rudder_order_deg",
                   "propeller_rpm", "rate_of_turn_deg_min"):
        out[column] = np.round(record[column], 6).tolist()
    out["course_deg"] = [None if not o.autopilot else round(math.degrees(o.course) % 360.0, 6)
                         for o in map(sim.voyage.orders_at, times)]
    if sim.station is not None:
        out["station"] = _station(sim, times)
    return out


def _station(sim, times: np.ndarray) -> dict:
    """A vessel keeping station at ``times`` (s): her midship from the set point (m), the wind, and each thruster's
    use (%) or mooring line's tension (kN), from the record's station columns."""
    ship = sim.voyage.ship
    record = station_record(ship, sim.voyage, times)
    out = {"footprint_m": sim.scenario.station.footprint_m,
           "north_from_set_point_m": np.round(record["north_of_set_point_m"], 4).tolist(),
           "east_from_set_point_m": np.round(record["east_of_set_point_m"], 4).tolist(),
           "wind_speed_m_s": np.round(record["wind_speed_m_s"], 3).tolist()}
    if ship.thrusters is not None:
        out["thrusters"] = {t.name: np.round(record[column], 2).tolist()
                            for t, column in zip(ship.thrusters.units, thruster_columns(ship))}
    if ship.moorings is not None:
        out["lines"] = {name: np.round(record[column], 1).tolist()
                        for name, column in zip(ship.line_names, line_columns(ship))}
    return out


def _action(entry: dict) -> str:
    """An action entry of the journal in words."""
    fields = {k: v for k, v in entry.items() if k not in ("t", "kind", "action")}
    if entry["action"] == "change":
        return "change: " + ", ".join(f"{k} {v:g}" for k, v in fields.items() if k != "ramp_s")
    if entry["action"] == "order":
        to = f" to {fields.pop('vessel')}" if "vessel" in fields else ""
        return f"order{to}: " + ", ".join(_order_words(k, v) for k, v in fields.items())
    if entry["action"] == "weather":
        return "weather: " + ", ".join(f"{k} {v:g}" for k, v in fields.items())
    if entry["action"] == "trigger":
        return f"event {fields['index']} triggered early"
    if entry["action"] == "message":
        to = fields.get("to", EVERYONE)
        return f"message{'' if to == EVERYONE else ' to ' + to}: {fields['text']}"
    if entry["action"] == "report":
        return f"report from {fields.get('station') or 'the trainee'}: {fields['text']}"
    return "alarms acknowledged"


def _order_words(key: str, value: object) -> str:
    """One order of the bridge in words, as a helmsman repeats it."""
    if key == "rudder_deg":
        return ("midships" if value == 0 else f"{'starboard' if value > 0 else 'port'} {abs(value):g}"
                + (" (hard over)" if abs(value) >= 35 else ""))
    if key == "course_deg":
        return f"steer {value:05.1f}"
    if key == "autopilot":
        return "autopilot " + ("on" if value else "off, hand steering")
    if key == "speed_kn":
        return f"engine for {value:g} kn"
    return str(value)


def _conditions(exercise: Exercise, log: SessionLog | None) -> Conditions:
    scenario = exercise.scenario
    vessel = scenario.vessel
    seas = []
    for system in scenario.sea.systems:
        alone = SeaState((system,), depth=scenario.sea.depth)
        seas.append(SeaSystem(alone.hs, alone.tp, wave_compass_from_beta(system.beta),
                              getattr(getattr(system, "spectrum", None), "gamma", None),
                              getattr(getattr(system, "spreading", None), "s", None)))
    return Conditions(
        scenario=str(scenario.path), scenario_sha256=sha256(scenario.path), seed=scenario.run.seed,
        duration_s=exercise.sim.time, planned_s=exercise.duration_s, dt_s=scenario.run.dt_s,
        log=str(log.path) if log is not None else None, log_sha256=log.verification.sha256 if log is not None else None,
        marinesim=__version__, sea=seas,
        vessel=None if vessel is None else VesselConditions(
            str(vessel.rao_path), sha256(vessel.rao_path), vessel.speed_kn, vessel.heading_deg,
            {name: list(p) for name, p in vessel.points.items()}))
