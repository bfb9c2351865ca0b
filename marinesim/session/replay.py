"""A session run again from its log: the scenario and seed it names, its live actions applied at the
simulation times they were taken.

The timeline depends only on the scenario, the seed and the actions with their times (the clock
lands on each action's time to the bit, :meth:`Exercise.advance_to`), so the replay has the
session's events, alarms and motions; the recorder's rows, computed one at a time, are the same
bytes (:mod:`marinesim.session.recorder`). Going back in time starts the run again from the
beginning (a few seconds per simulated hour).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from marinesim.criteria.monitor import Criterion
from marinesim.errors import FileFormatError, MarinesimError, ScenarioError
from marinesim.progress import task
from marinesim.scenario import Scenario, load_scenario, with_run
from marinesim.session.exercise import Exercise, quiet, run_exercise
from marinesim.session.log import SessionLog, read_log, vessel_files
from marinesim.session.recorder import Recorder
from marinesim.session.sidecar import sha256

SKIP = ("t", "kind", "action")
"""An action entry's keys that are not the action's fields."""
PROGRESS_STEP_S = 10.0
"""A headless replay reports its progress every this many simulated seconds."""


def session_scenario(log: SessionLog, where: Path) -> Scenario:
    """The scenario ``log`` (read from ``where``) ran, with its seed and duration; refused if the file
    is gone or has changed since (a replay of another scenario would not be the session)."""
    path = Path(log.header["scenario"])
    if not path.is_file():
        raise ScenarioError(f"{where}: the session's scenario {path} is not there")
    if sha256(path) != log.header["scenario_sha256"]:
        raise ScenarioError(f"{where}: the scenario {path} has changed since the session (its sha256 differs): "
                            "a replay would not be that session")
    scenario = with_run(load_scenario(path), log.header["duration_s"], seed=log.header["seed"])
    logged = log.header.get("vessel_sha256", {})
    for role, file in vessel_files(scenario).items():
        if role in logged and sha256(file) != logged[role]:
            raise ScenarioError(f"{where}: the vessel's {role} file {file} has changed since the session (its sha256 "
                                "differs): a replay would not be that session")
    return scenario


class Replay:
    """Moves ``exercise`` (a fresh one of the session's scenario) through ``actions`` (action entries of a journal,
    in time order), each at its time; more may be added as they come (:meth:`add`: a station following a served
    exercise). ``source``: the log they were read from, named with its line where one is refused."""

    def __init__(self, exercise: Exercise, actions: list[dict], source: SessionLog | None = None) -> None:
        self.exercise, self.source = exercise, source
        self._actions = list(actions)
        self._next = 0

    @property
    def time(self) -> float:
        return self.exercise.sim.time

    def add(self, entries: Sequence[dict]) -> None:
        """Journal ``entries`` that came since: the actions among them are applied at their times."""
        self._actions += [entry for entry in entries if entry.get("kind") == "action"]

    def advance_to(self, t: float, before_action: Callable[[], None] | None = None) -> None:
        """Go on to ``t`` (s), applying the actions on the way; ``before_action()`` runs with the clock at
        each action's time, before it (the recorder catches up there, as it did in the session)."""
        while self._next < len(self._actions) and self._actions[self._next]["t"] <= t:
            entry = self._actions[self._next]
            self.exercise.advance_to(entry["t"])
            if before_action is not None:
                before_action()
            try:
                self.exercise.act(entry["action"], **{k: v for k, v in entry.items() if k not in SKIP})
            except MarinesimError as error:  # an action the session could not have taken: the log was edited
                if self.source is None:
                    raise
                raise FileFormatError(self.source.path, self.source.line_of(entry),
                                      f"{entry['action']}: {error}") from None
            self._next += 1
        self.exercise.advance_to(t)


def replay_session(source: Path | SessionLog, export: Path | None = None, watch: Sequence[Criterion] = (),
                   log: Callable[[str], None] = quiet) -> Exercise:
    """Replay the session log ``source`` (read, or its path) headless to its end, its motions recorded to the
    CSV ``export`` as the session's recorder would have written them; returns the exercise run (``watch``: as
    :class:`Exercise`). Whether the log is verified is the caller's to say (:attr:`SessionLog.verification`)."""
    session = source if isinstance(source, SessionLog) else read_log(source)

    def drive(exercise: Exercise) -> None:
        recorder = Recorder(exercise, export) if export is not None else None
        replay = Replay(exercise, session.actions(), session)
        end = session.end_s
        with task("replay", max(round(end), 1), unit="s") as bar:
            while replay.time < end:
                before = replay.time
                replay.advance_to(min(before + PROGRESS_STEP_S, end),
                                  before_action=recorder.catch_up if recorder is not None else None)
                bar.update(round(replay.time) - round(before))
        if recorder is not None:
            recorder.stop()

    return run_exercise(session_scenario(session, session.path), log=log, watch=watch, drive=drive)
