"""Decisions an objective may ask of the trainee, judged from an exercise's journal
(:data:`~marinesim.scenario.model.DECISIONS`):

- ``acknowledge``: every alarm of the objective's criteria (all criteria if it names none) acknowledged within
  ``within_s`` of being raised;
- ``act_before``: a course or speed order (helm, telegraph, autopilot, a heading or speed change) that keeps the
  expectation of its criteria within their limits: the median of each criterion's window in the sea she met
  (:meth:`~marinesim.session.expectation.Expectations.window`), looked at every
  :data:`~marinesim.session.expectation.STEP_S` once the window has settled. Met if it never passes (with an order
  given, or none needed); not met if it passes, whatever was ordered before (an order that was too little, too
  late, or that brought the passing on). A criterion without an expectation (its quantity has none, a regular
  wave) leaves the decision not judged.
- ``give_way`` (COLREG Rules 15 and 16: the give-way vessel takes early and substantial action to keep well clear):
  her action is when her heading has turned :data:`SUBSTANTIAL_TURN_DEG` from her heading at the start, or her speed
  over the ground fallen by :data:`SUBSTANTIAL_SLOWING` of it (Rule 8: large enough to be readily apparent; orders
  that change neither, an autopilot engaged or a course nudged a degree, are no action), as the record shows it every
  :data:`PASSING_STEP_S`; met if it came while the time to the closest point of approach (TCPA) to ``vessel`` was
  still at least ``within_s`` and her distance to it was never less than ``passing_m``. Not met if she passed
  closer, whatever she did, or acted late; not judged if the run ended before she passed her. The encounter at the
  start, as :func:`~marinesim.offshore.traffic.encounter` classes it (Rules 13 to 15), is said with the verdict.

A run stopped early judges what it can: an alarm still waiting for less than ``within_s``, or an expectation that
has not passed its limit while no order was given, is "not judged".
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.constants import KNOT, NAUTICAL_MILE
from marinesim.criteria.monitor import SETTLE_FRACTION
from marinesim.offshore.traffic import Encounter, encounter
from marinesim.scenario.schema import Objective
from marinesim.session.exercise import Exercise
from marinesim.session.expectation import STEP_S

STEERING = frozenset({"rudder_deg", "engine", "speed_kn", "autopilot", "course_deg", "heading_deg"})
"""The fields of an order or a change that alter course or speed."""


@dataclass(frozen=True)
class Judged:
    """A decision's ``verdict`` ("met", "not met", "not judged") and ``why``, in words."""

    verdict: str
    why: str


PASSING_STEP_S = 1.0
"""The range to the vessel given way to is looked at this often (s): at 30 kn closing, 15 m between looks."""
SUBSTANTIAL_TURN_DEG = 10.0
"""A change of heading that is an action to give way (deg): readily apparent on another ship's radar (Rule 8 (b))."""
SUBSTANTIAL_SLOWING = 0.25
"""A fall in speed that is an action to give way: a quarter of her speed (Rule 8 (b) asks for a substantial one)."""


def judge(exercise: Exercise, objective: Objective) -> Judged:
    """``objective``'s decision in ``exercise`` as it ran."""
    if objective.decision == "acknowledge":
        return _acknowledged(exercise, objective)
    if objective.decision == "give_way":
        return _gave_way(exercise, objective)
    return _acted_before(exercise, objective)


def _acknowledged(exercise: Exercise, objective: Objective) -> Judged:
    names = set(objective.criteria) or {c.label for c in exercise.criteria}
    alarms = [a for a in exercise.alarms if a.name in names]
    end, within = exercise.sim.time, objective.within_s
    late = [a for a in alarms if (a.acknowledged_s if a.acknowledged_s is not None else end) - a.raised_s > within]
    waiting = [a for a in alarms if a.acknowledged_s is None and end - a.raised_s <= within]
    if late:
        first = late[0]
        how = ("never acknowledged" if first.acknowledged_s is None
               else f"acknowledged after {first.acknowledged_s - first.raised_s:.0f} s")
        return Judged("not met", f"{len(late)} of {len(alarms)} alarms late: {first.name} at {first.raised_s:.0f} s "
                                 f"{how} (within {within:g} s asked)")
    if waiting:
        return Judged("not judged", f"the run ended with an alarm waiting for less than {within:g} s")
    if not alarms:
        return Judged("not judged", "no alarm was raised")
    slowest = max(a.acknowledged_s - a.raised_s for a in alarms)
    return Judged("met", f"{len(alarms)} alarm{'s' if len(alarms) > 1 else ''} acknowledged, the slowest after "
                         f"{slowest:.0f} s (within {within:g} s asked)")


def _gave_way(exercise: Exercise, objective: Objective) -> Judged:
    name, asked, early = objective.vessel, objective.passing_m, objective.within_s
    times = np.arange(0.0, exercise.sim.time + 1e-9, PASSING_STEP_S)
    rows = exercise.sim.frame(times)
    ranges, tcpa = rows[f"{name}_range_m"], rows[f"{name}_tcpa_s"]
    situation = _encounter(rows, name).value.replace("_", " ")
    closest = int(np.argmin(ranges))
    passed = f"{situation}: passed {name} at {ranges[closest] / NAUTICAL_MILE:.2f} nm ({ranges[closest]:.0f} m) at " \
             f"{times[closest]:.0f} s"
    if ranges[closest] < asked:
        return Judged("not met", f"{passed}, inside the {asked:.0f} m asked")
    if tcpa[-1] > 0.0 and ranges[-1] <= ranges[closest] + 1e-9:
        return Judged("not judged", f"the run ended before she passed {name}")
    turned = np.abs((rows["heading_deg"] - rows["heading_deg"][0] + 180.0) % 360.0 - 180.0) >= SUBSTANTIAL_TURN_DEG
    slowed = rows["speed_over_ground_kn"] <= (1.0 - SUBSTANTIAL_SLOWING) * rows["speed_over_ground_kn"][0]
    acted = np.flatnonzero(turned | slowed)
    if not acted.size:
        return Judged("met", f"{passed} without a change of course or speed")
    at = int(acted[0])
    how = f"her heading {SUBSTANTIAL_TURN_DEG:g} deg off" if turned[at] else \
        f"her speed {SUBSTANTIAL_SLOWING:.0%} down"
    if tcpa[at] < early:
        return Judged("not met", f"{passed}, but {how} only at {times[at]:.0f} s, {tcpa[at] / 60:.1f} min before the "
                                 f"closest point of approach ({early / 60:.0f} asked)")
    return Judged("met", f"{passed}; {how} at {times[at]:.0f} s, {tcpa[at] / 60:.1f} min before the closest point "
                         "of approach")


def _encounter(rows: dict[str, np.ndarray], name: str) -> Encounter:
    """The encounter with ``name`` at the start (COLREG Rules 13 to 15), from the record's first row."""
    own_heading, own_speed = rows["heading_deg"][0], rows["speed_over_ground_kn"][0] * KNOT
    course = math.radians(rows["course_over_ground_deg"][0])
    own_v = own_speed * np.array([math.sin(course), math.cos(course)])
    heading = math.radians(rows[f"{name}_heading_deg"][0])
    other_v = rows[f"{name}_speed_kn"][0] * KNOT * np.array([math.sin(heading), math.cos(heading)])
    bearing = math.radians(rows[f"{name}_bearing_deg"][0])
    relative = rows[f"{name}_range_m"][0] * np.array([math.sin(bearing), math.cos(bearing)])
    return encounter(float(own_heading), own_v, relative, float(rows[f"{name}_heading_deg"][0]), other_v)


def _acted_before(exercise: Exercise, objective: Objective) -> Judged:
    ordered = next((e["t"] for e in exercise.journal if e["kind"] == "action"
                    and e["action"] in ("order", "change") and STEERING & e.keys() and "vessel" not in e), None)
    labels = [c.label for c in exercise.criteria]
    if any(exercise.expectations.window(labels.index(name), exercise.sim.time) is None for name in objective.criteria):
        return Judged("not judged", "no spectral expectation for its criteria (docs/FORMULAS.md)")
    passed = _expectation_passed(exercise, objective)
    if passed is None:
        if ordered is not None:
            return Judged("met", f"course or speed changed at {ordered:.0f} s; the expectation stayed within the "
                                 "limit")
        if not exercise.complete():
            return Judged("not judged", "the run stopped before the expectation passed the limit")
        return Judged("met", "the expectation stayed within the limit: no change was needed")
    name, at = passed
    when = "no course or speed change" if ordered is None else f"the first course or speed change at {ordered:.0f} s"
    return Judged("not met", f"the expectation of {name} passed its limit at {at:.0f} s; {when}")


def _expectation_passed(exercise: Exercise, objective: Objective) -> tuple[str, float] | None:
    """(criterion name, time s) where the first of the objective's criteria's expectation went above its limit."""
    labels = [c.label for c in exercise.criteria]
    indices = [labels.index(name) for name in objective.criteria]
    for step in range(1, math.floor(exercise.sim.time / STEP_S + 1e-9) + 1):
        t = step * STEP_S
        for i in indices:
            criterion = exercise.criteria[i]
            if criterion.window is not None and t < SETTLE_FRACTION * criterion.window:
                continue
            expected = exercise.expectations.window(i, t)
            if expected is not None and criterion.limit is not None and expected.cdf(criterion.limit) < 0.5:
                return criterion.label, t
    return None
