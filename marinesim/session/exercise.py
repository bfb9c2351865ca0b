"""A scenario run as an exercise: its timeline with the scripted events, the motion record on the
run's time grid, and the criteria evaluated over it as it grows.

The viewer moves it on frame by frame (:meth:`Exercise.advance`); ``marinesim assess``, the export
and the headless run take its record block by block (:meth:`Exercise.blocks`), each through
:func:`run_exercise` (built, run, closed). Both compute the rows at the grid times ``t_k = k dt`` and
evaluate the criteria at the same rows (every :data:`~marinesim.criteria.monitor.EVALUATE_S`), with
the clock stopped at each evaluation, so what the viewer shows at ``t`` is what ``assess`` reports
at ``t``. What it reports is an :class:`Assessment` (:meth:`Exercise.assessment`).

Events happen in time: one with ``at_s`` is asked of the timeline ahead of time and starts at
``at_s``; one with ``when`` is checked at every evaluation and happens the first time its condition
holds, its change starting then (a sea change :data:`~marinesim.session.timeline.PREPARE_S` later, while
its amplitudes are prepared; orders to the ship at once). Sea changes and orders never wait for each other.

A criterion whose running value goes above its limit raises an :class:`Alarm`, which stays until it is
acknowledged; it clears when the value is back within the limit. Live actions (an instructor's change
of sea, the trainee's helm, telegraph and autopilot orders, an event triggered early, a message, an
acknowledgement) go through
:meth:`Exercise.act`; everything that happens is kept in :attr:`Exercise.journal` with its simulation
time, the session log (:mod:`marinesim.session.log`) that a replay runs again.

A run stopped before its planned duration (:meth:`Exercise.complete` false: the session closed early) is
judged only as far as it went: a criterion that went above its limit did so, and stays exceeded, but one
still within it may yet have gone above later, so it is not judged; the verdict of such a run with nothing
exceeded is ``incomplete``, never ``within limits``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from marinesim.criteria.expectation import Expected
from marinesim.criteria.monitor import Criterion, Level, Monitor, Tally, value_and_limit, watched
from marinesim.errors import ParameterError
from marinesim.progress import task
from marinesim.scenario import Scenario
from marinesim.scenario.model import WEATHER
from marinesim.scenario.schema import Event
from marinesim.session.assembly import Assembly
from marinesim.session.expectation import Expectations
from marinesim.session.timeline import PREPARE_S, Simulation

BLOCK = 512
"""The fewest rows :meth:`Exercise.blocks` yields at once (the last block excepted)."""
AHEAD = 8192
"""Rows of the record computed at once by ``assess``, the export, the headless run and a seek (the viewer
computes only the rows up to its clock, a few a frame)."""
AHEAD_ON_CONDITION_S = 60.0
"""While an event that changes the run waits on its condition, the record is computed at most this far ahead (s):
what lies beyond the moment it holds is computed again."""


@dataclass(frozen=True)
class Happened:
    """Event ``index`` of the scenario happened at ``time_s`` (s)."""

    index: int
    time_s: float
    event: Event
    early: bool = False
    """Triggered by the instructor before its time or condition."""

    def line(self) -> str:
        """One log line: the time, the event, its message."""
        early = " (triggered early by the instructor)" if self.early else ""
        return f"t {self.time_s:7.1f} s  event {self.index}{early}: {self.event.describe()}"


@dataclass
class Alarm:
    """Criterion ``criterion`` (index of the scenario's), named ``name``, went above its ``limit`` at
    ``raised_s`` (s) with ``value``; acknowledged and back within the limit at the times given (s)."""

    criterion: int
    name: str
    raised_s: float
    value: float
    limit: float
    acknowledged_s: float | None = None
    cleared_s: float | None = None

    def line(self) -> str:
        value, limit = value_and_limit(self.value, self.limit)
        return f"t {self.raised_s:7.1f} s  ALARM {self.name}: {value} above the limit {limit}"


@dataclass(frozen=True)
class CriterionResult:
    """One criterion over the run so far: its worst ``value`` (in ``unit``; None while settling) at ``value_at_s``
    (s) against ``limit`` (caution at ``caution`` x limit) over ``window_s`` (s; None for a dose), the time spent
    above the limit and when it first went above (s), its ``level`` from the worst value, and whether it is
    ``judged`` (:meth:`Exercise.assessment`). What the sea the vessel met made of it
    (:mod:`~marinesim.session.expectation`; None where its quantity has no spectral estimate): the worst value
    ``expected`` (the median over seeds), the ``percentile`` of the worst value in that distribution, and the
    ``chance_exceeded`` (0 to 1) that the worst goes above the limit."""

    name: str
    point: str | None
    quantity: str
    unit: str | None
    window_s: float | None
    value: float | None
    value_at_s: float | None
    limit: float | None
    caution: float
    exceeded: bool
    time_exceeded_s: float
    first_exceeded_s: float | None
    level: Level
    judged: bool
    expected: float | None = None
    percentile: float | None = None
    chance_exceeded: float | None = None

    @property
    def reading(self) -> Level | None:
        """Its level where it is judged; None where the run stopped before it could be."""
        return self.level if self.judged else None

    def as_dict(self) -> dict:
        """As the JSON outputs write it: these fields in this order, the level as its word."""
        values = {field.name: getattr(self, field.name) for field in fields(CriterionResult)}
        return values | {"level": self.level.value}


@dataclass(frozen=True)
class EventResult:
    """Scripted event ``index``: its ``trigger`` in words (``at 480 s``, ``when roll > 8``), when it happened (s; None:
    it did not), what it changes and its message."""

    index: int
    trigger: str
    happened_s: float | None
    what: str
    message: str | None

    def as_dict(self) -> dict:
        return {field.name: getattr(self, field.name) for field in fields(self)}


@dataclass(frozen=True)
class AlarmResult:
    """An alarm of the criterion named ``criterion``: raised at ``raised_s`` (s) with ``value`` above ``limit`` (the
    criterion's unit), acknowledged and back within the limit at the times given (s; None: not by the end)."""

    criterion: str
    raised_s: float
    value: float
    limit: float
    acknowledged_s: float | None = None
    cleared_s: float | None = None

    def as_dict(self) -> dict:
        return {field.name: getattr(self, field.name) for field in fields(self)}


@dataclass(frozen=True)
class Assessment:
    """The criteria, events and alarms of a run of ``scenario`` (its path) with ``seed`` at ``dt_s`` (s), as
    ``marinesim assess`` reports them: ``duration_s`` the time run (s), ``planned_s`` the planned duration (s),
    ``complete`` whether it ran through it, and the ``verdict`` (:meth:`Exercise.assessment`)."""

    scenario: str
    seed: int
    duration_s: float
    planned_s: float
    complete: bool
    dt_s: float
    criteria: list[CriterionResult]
    events: list[EventResult]
    alarms: list[AlarmResult]
    verdict: str

    def as_dict(self) -> dict:
        """The assessment as ``assess --json`` and the headless run's ``assessment.json`` write it (plain values,
        the fields in this order, levels as their words)."""
        values = {field.name: getattr(self, field.name) for field in fields(self)}
        return values | {"criteria": [c.as_dict() for c in self.criteria], "events": [e.as_dict() for e in self.events],
                         "alarms": [a.as_dict() for a in self.alarms]}


CHANGE_KEYS = frozenset({"hs_factor", "tp_factor", "turn_waves_deg", "speed_kn", "heading_deg", "ramp_s"})
"""What a live change may give (:meth:`Simulation.change`'s keywords, the sea as factors of the present one; speed
and heading are orders to the engine and the autopilot)."""
ORDER_KEYS = frozenset({"rudder_deg", "engine", "speed_kn", "autopilot", "course_deg", "set_north_m", "set_east_m",
                        "fault", "hoist_m_s", "slew_deg_s", "helicopter", "vessel"})
"""What a live order may give (:meth:`Simulation.order`'s keywords)."""
WEATHER_KEYS = frozenset({*WEATHER, "hours", "ramp_s"})
"""What a live weather change may give (:meth:`Simulation.change_weather`'s keywords): new values, the clock moved,
the time the new values blend in over (s)."""
ACTIONS = {"change": CHANGE_KEYS, "order": ORDER_KEYS, "weather": WEATHER_KEYS, "trigger": frozenset({"index"}),
           "message": frozenset({"text", "to"}), "acknowledge": frozenset(), "report": frozenset({"text", "station"})}
"""Live actions and their fields: what :meth:`Exercise.act` applies and a replay applies again. A ``message`` is the
instructor's, to every station or the one named ``to``; a ``report`` is a trainee's at ``station`` to the
instructor."""
MAX_MESSAGE = 200
"""The longest message an instructor or a trainee may send (characters)."""
MAX_STATION = 40
"""The longest name of a station (characters): ``bridge``, ``crane``, ``helideck``..."""
EVERYONE = "all"
"""A message to every station."""


def _words(text: object) -> str:
    """A message's text on one line; refused empty or longer than :data:`MAX_MESSAGE`."""
    text = " ".join(str(text).split())
    if not text or len(text) > MAX_MESSAGE:
        raise ParameterError(f"a message needs 1 to {MAX_MESSAGE} characters, got {len(text)}")
    return text


def _station(name: object) -> str:
    """A station's name as given (:data:`EVERYONE` for all); refused if not a short name."""
    if not (isinstance(name, str) and len(name) <= MAX_STATION and name.isprintable()):
        raise ParameterError(f"a station's name needs at most {MAX_STATION} printable characters, got {name!r}")
    return name


def quiet(line: str) -> None:
    """Log nothing."""


def last_row(t: float, dt: float) -> int:
    """The last row of the run's time grid ``k dt`` at or before ``t`` (s)."""
    return math.floor(t / dt + 1e-9)


def ran_words(ran_s: float, planned_s: float) -> str:
    """How much of a run of ``planned_s`` (s) ran, ``ran_s`` (s), in words: '386 s of 1,800 s (21 %)' (the time and
    the share rounded down, so a run short of its end never reads as all of it)."""
    share = math.floor(100.0 * min(ran_s / planned_s, 1.0) + 1e-9) if planned_s > 0 else 100
    return f"{math.floor(ran_s + 1e-9):,d} s of {planned_s:,g} s ({share} %)"


def share_words(p: float) -> str:
    """A probability (0 to 1) in percent, the ends told apart from certainty: '<1 %', '43 %', '>99 %'."""
    percent = 100.0 * p
    return "<1 %" if percent < 0.5 else ">99 %" if percent > 99.5 else f"{percent:.0f} %"


class Exercise:
    """``simulation``'s scenario as an exercise over ``duration_s`` (default: the run's); each event
    that happens is passed to ``log`` as one line. ``watch``: more criteria to evaluate (:meth:`tally`),
    without alarms (the debrief's motion sickness at each point)."""

    def __init__(self, simulation: Simulation, duration_s: float | None = None,
                 log: Callable[[str], None] = quiet, watch: Sequence[Criterion] = ()) -> None:
        self.sim = simulation
        scenario: Scenario = simulation.scenario
        self.scenario = scenario
        self.dt = scenario.run.dt_s
        self.duration_s = scenario.run.duration_s if duration_s is None else duration_s
        self.log = log
        self.events = scenario.events
        for event in self.events:
            if event.sea is not None:
                simulation.ocean.check(event.sea)  # refused before anything runs
        vessel = scenario.vessel
        criteria = list(scenario.criteria)
        self._watching: dict[int, int] = {}
        """Conditional event -> the monitor's criterion its condition reads."""
        for i, event in enumerate(self.events):
            if event.condition is not None:
                criterion = watched(event.condition, criteria, vessel.points)
                if criterion not in criteria:
                    criteria.append(criterion)
                self._watching[i] = criteria.index(criterion)
        criteria += [criterion for criterion in watch if criterion not in criteria]
        self.criteria: tuple[Criterion, ...] = scenario.criteria
        """The scenario's criteria: the monitor's first; the others it holds are watched for conditions."""
        self.monitor = Monitor(criteria, vessel.points, self.dt, self.duration_s) if vessel and criteria else None
        self.happened: list[Happened] = []
        self.alarms: list[Alarm] = []
        self.said: list[tuple[float, str, str]] = []
        """The instructor's messages: (time s, text, to: a station's name or :data:`EVERYONE`)."""
        self.reports: list[tuple[float, str, str]] = []
        """The trainees' reports to the instructor: (time s, station, text)."""
        self.journal: list[dict[str, Any]] = []
        """Everything that happened, in time order: ``{"t": s, "kind": ..., ...}`` (the session log's entries)."""
        self.evaluated_s: list[float] = []
        self.values: list[list[float | None]] = []
        """The scenario's criteria at each evaluation (None while settling), at :attr:`evaluated_s`."""
        self._active: dict[int, Alarm] = {}
        self._timed = [i for i, event in enumerate(self.events) if event.at_s is not None]
        self._asked = 0      # timed events asked of the timeline
        self._announced = 0  # timed events that have happened
        self._conditional = list(self._watching)
        self._changing = {i for i, event in enumerate(self.events) if event.changes or event.weather}
        """The events that change the timeline (its sea, orders or weather)."""
        self.row = 0
        """The next grid row to record."""
        self._ahead: tuple[int, int, int, frozenset[str] | None, dict[str, np.ndarray]] | None = None
        """(first row, the timeline's version then, rows, the columns wanted, the columns) computed ahead."""
        self.expectations = Expectations(simulation, self.criteria) if self.monitor is not None else None
        """What the sea the vessel meets makes of each criterion (computed when asked)."""
        self._expected_now: dict[int, tuple[float, Expected | None]] = {}

    # -- moving on ----------------------------------------------------------------------------

    def advance(self, dt: float) -> None:
        """Move the clock on by ``dt`` (s), stopping at each evaluation on the way (the viewer's frame)."""
        self.advance_to(self.sim.time + dt)

    def advance_to(self, t: float) -> None:
        """Move the clock on to exactly ``t`` (s), as :meth:`advance`."""
        for _ in self._steps(t, rows=False, wanted=self._watched_columns()):
            pass

    def seek(self, t: float) -> None:
        """Jump forward to ``t`` (s), recording and evaluating on the way (the record computed ahead, as ``assess``
        computes it: an event that changes the run drops what lies beyond it); the solver restarts there."""
        for _ in self._steps(t, rows=False, step_solver=False, ahead=True, wanted=self._watched_columns()):
            pass
        self.sim.seek(t)

    def run(self, until: float | None = None) -> None:
        """Go on to ``until`` (s; default the run's end), as ``assess`` does: events happen, criteria are evaluated."""
        until = self.duration_s if until is None else until
        with task("exercise", max(self._last_row(until) + 1 - self.row, 0)) as bar:
            for block in self._steps(until, rows=True, wanted=self._watched_columns()):
                bar.update(block["time_s"].size)

    def blocks(self) -> Iterator[dict[str, np.ndarray]]:
        """Go through the whole run, yielding its record (every column) in blocks of rows."""
        return self._steps(self.duration_s, rows=True)

    def _watched_columns(self) -> frozenset[str]:
        """The record's columns the monitor reads (none without one): of the columns beyond the motions' and the
        ship's, all that a run keeping no record computes (:meth:`Simulation.frame_steps`)."""
        return self.monitor.columns if self.monitor is not None else frozenset()

    def _steps(self, target: float, rows: bool, step_solver: bool = True, ahead: bool = False,
               wanted: frozenset[str] | None = None) -> Iterator[dict[str, np.ndarray]]:
        """Move the clock to ``target`` (s): record the rows up to it if the monitor needs them (and
        yield them, :data:`BLOCK` rows or more at a time, if ``rows``), stopping the clock at each
        evaluation to evaluate and let events happen (without a monitor, at each timed event's first row: a weather
        change acts from the clock's time). With ``rows`` or ``ahead`` the record is computed up to
        :data:`AHEAD` rows at a time (the response's fast path; fewer before a scripted change); a change of
        the timeline drops what was computed ahead. ``wanted``: the columns computed beyond the motions' and the
        ship's (None: all)."""
        last = self._last_row(target)
        recording = rows or self.monitor is not None
        out: list[dict[str, np.ndarray]] = []
        while recording and self.row <= last:
            stop_row = min(last, self.row + AHEAD - 1)  # memory bounded whatever the run's length
            if self.monitor is not None:
                stride = self.monitor.stride
                stop_row = min(stop_row, -(-self.row // stride) * stride)  # the next evaluation
            elif self._announced < len(self._timed):
                at_s = self.events[self._timed[self._announced]].at_s
                stop_row = min(stop_row, max(self.row, math.ceil(at_s / self.dt - 1e-9)))  # the next timed event
            stop = min(stop_row * self.dt, target)  # the last row's time may round past the target
            self._ask_timed(stop)
            self._move_clock(stop, step_solver)
            block = self._record(self.row, stop_row, last if rows or ahead else stop_row, wanted)
            if self.monitor is not None:
                self.monitor.append(block)
            self.row = stop_row + 1
            self._announce_timed(stop)
            if self.monitor is not None and self.monitor.due(stop_row):
                values = self.monitor.evaluate()[:len(self.criteria)]
                self.evaluated_s.append(stop)
                self.values.append(values)
                self._check_alarms(stop, values)
                self._check_conditions(stop)
            if rows:
                out.append(block)
                if sum(b["time_s"].size for b in out) >= BLOCK or self.row > last:
                    yield {name: np.concatenate([b[name] for b in out]) for name in out[0]}
                    out = []
        self._ask_timed(target)
        self._move_clock(target, step_solver)
        self._announce_timed(target)

    def _record(self, first: int, last: int, ahead_to: int, wanted: frozenset[str] | None
                ) -> dict[str, np.ndarray]:
        """Rows ``first..last`` of the record (``wanted``: as :meth:`Simulation.frame_steps`): from what was computed
        ahead while the timeline has not changed since (with those columns), else computed now with up to
        :data:`AHEAD` rows (not beyond ``ahead_to``, nor into the next scripted change) ahead."""
        ahead = self._ahead
        if (ahead is None or ahead[1] != self.sim.version or not ahead[0] <= first <= last < ahead[0] + ahead[2]
                or not _holds(ahead[3], wanted)):
            count = max(last, min(ahead_to, first + AHEAD - 1, self._before_next_change(first))) - first + 1
            self._ahead = ahead = (first, self.sim.version, count, wanted,
                                   self.sim.frame_steps(first * self.dt, self.dt, count, wanted))
        lo, hi = first - ahead[0], last + 1 - ahead[0]
        return {name: column[lo:hi] for name, column in ahead[4].items()}

    def _before_next_change(self, first: int) -> int | float:
        """The last row from ``first`` the record may be computed ahead to: before the next timed event that changes
        the timeline (its sea, orders or weather), and no more than :data:`AHEAD_ON_CONDITION_S` on while such an
        event waits on its condition (infinity: no limit). A change drops the record beyond it, and a vessel
        keeping station is stepped again from there."""
        waiting = self._changing.intersection(self._conditional)
        limit = first + round(AHEAD_ON_CONDITION_S / self.dt) - 1 if waiting else math.inf
        for index in self._timed[self._announced:]:
            if index in self._changing:
                return min(limit, math.ceil(self.events[index].at_s / self.dt - 1e-9) - 1)
        return limit

    def _last_row(self, t: float) -> int:
        return last_row(t, self.dt) if self.sim.vessel is not None else -1

    def _move_clock(self, t: float, step_solver: bool) -> None:
        if t > self.sim.time:
            self.sim.advance_to(t, step_solver=step_solver)

    # -- events -------------------------------------------------------------------------------

    def _ask_timed(self, t: float) -> None:
        """Ask the timeline for the timed changes that start by ``t`` or are due for preparing."""
        while self._asked < len(self._timed) and self.events[self._timed[self._asked]].at_s - PREPARE_S <= t:
            event = self.events[self._timed[self._asked]]
            if event.changes:
                self._change(event, event.at_s)
            self._asked += 1

    def _announce_timed(self, t: float) -> None:
        while self._announced < len(self._timed) and self.events[self._timed[self._announced]].at_s <= t + 1e-9:
            index = self._timed[self._announced]
            self._happen(index, self.events[index].at_s)
            self._announced += 1

    def _check_conditions(self, t: float) -> None:
        for index in list(self._conditional):
            event = self.events[index]
            if event.condition.holds(self.monitor.tallies[self._watching[index]].value):
                self._conditional.remove(index)
                if event.changes:
                    self._change(event, t + (PREPARE_S if event.sea is not None else 0.0))
                self._happen(index, t)

    def _check_alarms(self, t: float, values: list[float | None]) -> None:
        """Raise an alarm for each criterion gone above its limit; clear those back within it."""
        for i, (criterion, value) in enumerate(zip(self.criteria, values)):
            above = value is not None and criterion.limit is not None and value > criterion.limit
            if above and i not in self._active:
                alarm = self._active[i] = Alarm(i, criterion.label, t, value, criterion.limit)
                self.alarms.append(alarm)
                self.note("alarm", criterion=alarm.name, value=value, limit=criterion.limit)
                self.log(alarm.line())
            elif not above and i in self._active:
                alarm = self._active.pop(i)
                alarm.cleared_s = t
                self.note("cleared", criterion=alarm.name, value=value)

    def _change(self, event: Event, at: float) -> None:
        """Event ``event``'s sea change from ``at`` (s) and its orders, given at ``at``."""
        if event.sea is not None:
            self.sim.change(sea=event.sea, ramp_s=event.ramp_s, at=at)
        if event.orders:
            self.sim.order(at=at, **event.orders)

    def _happen(self, index: int, t: float, early: bool = False) -> None:
        happened = Happened(index, t, self.events[index], early)
        if happened.event.weather:
            self.sim.change_weather(ramp_s=happened.event.ramp_s, **happened.event.weather)
        self.happened.append(happened)
        self.note("event", index=index, what=happened.event.describe(), **({"early": True} if early else {}))
        self.log(happened.line())

    # -- live actions -------------------------------------------------------------------------

    def act(self, action: str, **fields: Any) -> None:
        """Apply the live ``action`` (one of :data:`ACTIONS`, with its fields) now and journal it; a
        change the timeline refuses raises :class:`~marinesim.errors.MarinesimError` and is not journaled."""
        known = ACTIONS.get(action)
        if known is None or not fields.keys() <= known:
            raise ParameterError(f"unknown action {action!r} with {sorted(fields)}")
        if action == "change":
            self.sim.change(**fields)
        elif action == "order":
            self.sim.order(**fields)
        elif action == "weather":
            self.sim.change_weather(**fields)
        elif action == "trigger":
            self._trigger(fields["index"])
        elif action == "message":
            self._say(fields["text"], fields.get("to", EVERYONE))
        elif action == "report":
            self._report(fields["text"], fields.get("station", ""))
        self.note("action", action=action, **fields)
        if action == "acknowledge":
            self._acknowledge()

    def note(self, kind: str, **fields: Any) -> None:
        """Journal ``kind`` with ``fields`` at the present time."""
        self.journal.append({"t": self.sim.time, "kind": kind, **fields})

    def pending_events(self) -> list[int]:
        """The scripted events the instructor may still trigger early (not happened, not about to)."""
        timed = self._timed[self._asked:]
        return sorted(timed + self._conditional)

    def _trigger(self, index: int) -> None:
        if index not in self.pending_events():
            raise ParameterError(f"event {index} has happened or is about to: it cannot be triggered")
        if index in self._conditional:
            self._conditional.remove(index)
        else:
            self._timed.remove(index)
        event, now = self.events[index], self.sim.time
        if event.changes:
            self._change(event, now + (PREPARE_S if event.sea is not None else 0.0))
        self._happen(index, now, early=True)

    def _say(self, text: str, to: str) -> None:
        text = _words(text)
        self.said.append((self.sim.time, text, _station(to)))
        self.log(f"t {self.sim.time:7.1f} s  instructor{'' if to == EVERYONE else ' to ' + to}: {text}")

    def _report(self, text: str, station: str) -> None:
        text = _words(text)
        self.reports.append((self.sim.time, _station(station), text))
        self.log(f"t {self.sim.time:7.1f} s  report from {station or 'the trainee'}: {text}")

    def _acknowledge(self) -> None:
        waiting = [alarm for alarm in self.alarms if alarm.acknowledged_s is None]
        for alarm in waiting:
            alarm.acknowledged_s = self.sim.time
        if waiting:
            self.note("acknowledged", criteria=[a.name for a in waiting],
                      delays_s=[self.sim.time - a.raised_s for a in waiting])

    def unacknowledged(self) -> list[Alarm]:
        """The alarms waiting for an acknowledgement, oldest first."""
        return [alarm for alarm in self.alarms if alarm.acknowledged_s is None]

    # -- what it shows ------------------------------------------------------------------------

    def messages(self, t: float | None = None, span_s: float = 30.0, station: str | None = None) -> list[str]:
        """The messages of the events that happened within ``span_s`` before ``t`` (default now), newest last: the
        instructor's to everyone and, at a named ``station``, to it (None: all of them)."""
        t = self.sim.time if t is None else t
        said = [(h.time_s, h.event.message) for h in self.happened if h.event.message]
        said += [(time_s, f"instructor: {text}") for time_s, text, to in self.said
                 if station is None or to in (EVERYONE, station)]
        return [f"t {time_s:6.0f} s  {text}" for time_s, text in sorted(said, key=lambda m: m[0])
                if t - span_s <= time_s <= t]

    def tally(self, criterion: Criterion) -> Tally:
        """The tally of a criterion the exercise evaluates (the scenario's, a condition's, or watched)."""
        return self.monitor.tallies[self.monitor.criteria.index(criterion)]

    def readings(self) -> list[tuple[Criterion, float | None, Level]]:
        """(criterion, latest value or None while settling, level) of the scenario's criteria."""
        if self.monitor is None:
            return []
        return [(c, tally.value, c.level(tally.value))
                for c, tally in zip(self.criteria, self.monitor.tallies)]

    def expected_now(self, index: int) -> Expected | None:
        """The distribution of criterion ``index``'s value over its window ending at the last evaluation (the panel's
        value), in the sea she met (None: no spectral estimate for its quantity); kept until the next evaluation."""
        if self.expectations is None:
            return None
        at = self.evaluated_s[-1] if self.evaluated_s else 0.0  # the panel's value is the last evaluation's
        if self._expected_now.get(index, (None,))[0] != at:
            self._expected_now[index] = (at, self.expectations.window(index, at))
        return self._expected_now[index][1]

    def complete(self) -> bool:
        """Whether the run has gone through its planned duration: recorded the last row of its time grid."""
        return last_row(self.sim.time, self.dt) >= last_row(self.duration_s, self.dt)

    def assessment(self) -> Assessment:
        """The criteria and events of the run so far, as ``marinesim assess`` reports them: ``duration_s`` the time
        run (s), ``planned_s`` the run's planned duration (s), ``complete`` whether it ran through it. A criterion
        is ``judged`` if the run is complete or it went above its limit (an exceedance is a fact however early the
        run stopped; a value within the limit so far is not a pass). The verdict is ``exceeded`` if a criterion
        went above its limit, else ``incomplete`` for a run stopped early, else ``caution``, ``within limits``, or
        ``no value`` while every criterion is settling."""
        complete = self.complete()
        criteria = []
        tallies = self.monitor.tallies if self.monitor is not None else []
        for i, (criterion, tally) in enumerate(zip(self.criteria, tallies)):
            level = criterion.level(tally.worst)
            expected = self.expectations.run(i, self.sim.time)
            criteria.append(CriterionResult(
                name=criterion.label, point=criterion.point, quantity=criterion.quantity,
                unit=criterion.measure.unit, window_s=criterion.window, value=tally.worst, value_at_s=tally.worst_s,
                limit=criterion.limit, caution=criterion.caution, exceeded=tally.first_exceeded_s is not None,
                time_exceeded_s=tally.time_exceeded_s, first_exceeded_s=tally.first_exceeded_s, level=level,
                judged=complete or level is Level.EXCEEDED,
                expected=None if expected is None else expected.median,
                percentile=None if expected is None or tally.worst is None else expected.percentile(tally.worst),
                chance_exceeded=None if expected is None or criterion.limit is None
                else 1.0 - expected.cdf(criterion.limit)))
        happened = {h.index: h.time_s for h in self.happened}
        events = [EventResult(i, f"at {e.at_s:g} s" if e.at_s is not None else f"when {e.condition}", happened.get(i),
                              e.describe().partition(": ")[2], e.message)
                  for i, e in enumerate(self.events)]
        alarms = [AlarmResult(a.name, a.raised_s, a.value, a.limit, a.acknowledged_s, a.cleared_s) for a in self.alarms]
        levels = {c.level for c in criteria}
        verdict = ("exceeded" if Level.EXCEEDED in levels else "incomplete" if not complete
                   else "caution" if Level.CAUTION in levels else "no value" if levels == {Level.SETTLING}
                   else "within limits")
        return Assessment(str(self.scenario.path), self.scenario.run.seed, self.sim.time, self.duration_s, complete,
                          self.dt, criteria, events, alarms, verdict)


def _holds(computed: frozenset[str] | None, wanted: frozenset[str] | None) -> bool:
    """Whether a record computed with the columns ``computed`` holds those ``wanted`` (None: every column)."""
    return computed is None or (wanted is not None and wanted <= computed)


def run_exercise(scenario: Scenario, *, duration_s: float | None = None, log: Callable[[str], None] = quiet,
                 watch: Sequence[Criterion] = (), assembly: Assembly | None = None,
                 drive: Callable[[Exercise], object] | None = None) -> Exercise:
    """``scenario``'s exercise (as :class:`Exercise`: over ``duration_s``, events to ``log``, ``watch``) on a
    simulation without the wake (of ``assembly``, default a new one), driven by ``drive(exercise)`` (default
    :meth:`Exercise.run` to its end) and closed after, whatever happens; returns the exercise run."""
    with Simulation(scenario, wake=False, assembly=assembly) as simulation:
        exercise = Exercise(simulation, duration_s, log, watch)
        if drive is None:
            exercise.run()
        else:
            drive(exercise)
    return exercise
