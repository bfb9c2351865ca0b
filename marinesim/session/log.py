"""The session log: a scenario, its seed and everything that happened in one viewer session, as JSON lines.

The first line says what ran (the scenario's path and sha256, the seed, the run's duration and dt);
each line after it is one journal entry of the exercise (:attr:`Exercise.journal`) with its
simulation time ``t`` (s): events, alarms, acknowledgements, the instructor's and the trainee's
actions, key presses, pauses. The log is written with a sidecar (``<log>.json``: its sha256 and the
hashes of the scenario and the vessel's files) as one unit, when the session ends. A replay
(:mod:`marinesim.session.replay`) reads it back and applies the ``action`` entries again at their
times; the other entries are what the session saw, kept for the debrief.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from marinesim import __version__
from marinesim.errors import FileFormatError
from marinesim.manoeuvring.actuators import TELEGRAPH
from marinesim.scenario import Scenario
from marinesim.session.exercise import ACTIONS, CHANGE_KEYS, MAX_MESSAGE, Exercise
from marinesim.session.sidecar import sha256, write_table

FORMAT = "marinesim session log"
VERSION = 1
MAX_LOG_BYTES = 64 << 20
"""The largest log read (bytes): a day of a busy session is well under 1 MB."""


@dataclass(frozen=True)
class SessionLog:
    """What ran (:attr:`header`) and what happened (:attr:`entries`, in time order), read from :attr:`path`."""

    header: dict[str, Any]
    entries: list[dict[str, Any]]
    path: Path | None = None

    def line_of(self, entry: dict[str, Any]) -> int | None:
        """The line of the log ``entry`` was read from (the header is line 1)."""
        return next((i + 2 for i, e in enumerate(self.entries) if e is entry), None) if self.path else None

    @property
    def end_s(self) -> float:
        """When the session ended (s): its last entry's time, or 0."""
        return self.entries[-1]["t"] if self.entries else 0.0

    def actions(self) -> list[dict[str, Any]]:
        """The entries a replay applies again, in order."""
        return [entry for entry in self.entries if entry["kind"] == "action"]


def header(scenario: Scenario, duration_s: float) -> dict[str, Any]:
    """The first line of a session's log: what ran."""
    return {"format": FORMAT, "version": VERSION, "scenario": str(Path(scenario.path).resolve()),
            "scenario_sha256": sha256(scenario.path), "seed": scenario.run.seed, "duration_s": duration_s,
            "dt_s": scenario.run.dt_s, "marinesim": __version__}


def write_log(path: Path, exercise: Exercise) -> Path:
    """Write ``exercise``'s journal as a session log at ``path`` with its sidecar, as one unit; returns ``path``."""
    scenario = exercise.scenario
    lines = [json.dumps(header(scenario, exercise.duration_s))]
    lines += [json.dumps(entry, allow_nan=False) for entry in exercise.journal]

    def describe() -> dict:
        vessel = scenario.vessel
        files = {"scenario": scenario.path}
        if vessel is not None:
            files |= {"rao": vessel.rao_path, **({"hull": vessel.hull_path} if vessel.hull_path else {})}
        return {"format": FORMAT, "entries": len(exercise.journal), "end_s": exercise.sim.time,
                "files": {key: {"path": str(p), "sha256": sha256(p)} for key, p in files.items()}}

    Path(path).parent.mkdir(parents=True, exist_ok=True)
    write_table(Path(path), lambda temp: temp.write_text("\n".join(lines) + "\n", encoding="utf-8"), describe)
    return Path(path)


def read_log(path: Path) -> SessionLog:
    """Read and check a session log: each fault is reported as one line naming the file, line and key."""
    path = Path(path)
    try:
        size = path.stat().st_size
    except OSError as error:
        raise FileFormatError(path, None, f"cannot read the session log ({error.strerror or error})") from None
    if size > MAX_LOG_BYTES:
        raise FileFormatError(path, None, f"{size} bytes is more than a session log holds ({MAX_LOG_BYTES} at most)")
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise FileFormatError(path, None, f"cannot read the session log as UTF-8 text ({error})") from None
    lines = text.splitlines()
    if not lines:
        raise FileFormatError(path, None, "empty; a session log starts with a line naming its scenario")
    records = []
    for number, line in enumerate(lines, start=1):
        try:
            record = json.loads(line, parse_constant=_refuse_constant)
        except (ValueError, RecursionError) as error:
            raise FileFormatError(path, number, f"not a JSON object ({error})") from None
        if not isinstance(record, dict):
            raise FileFormatError(path, number, f"expected a JSON object, got {type(record).__name__}")
        records.append(record)
    head = records[0]
    if head.get("format") != FORMAT or head.get("version") != VERSION:
        raise FileFormatError(path, 1, f"not a {FORMAT} (version {VERSION}): its first line names no such format")
    for key, kind in (("scenario", str), ("scenario_sha256", str), ("seed", int), ("duration_s", float),
                      ("dt_s", float)):
        if not _is(head.get(key), kind):
            raise FileFormatError(path, 1, f"key {key!r}: expected {kind.__name__}, got {head.get(key)!r}")
    entries = records[1:]
    last = 0.0
    for number, entry in enumerate(entries, start=2):
        t = entry.get("t")
        if not _is(t, float) or t < last:
            raise FileFormatError(path, number, f"key 't': expected a time (s) at or after {last:g}, got {t!r}")
        last = t
        if not isinstance(entry.get("kind"), str):
            raise FileFormatError(path, number, f"key 'kind': expected a string, got {entry.get('kind')!r}")
        if entry["kind"] == "action":
            _check_action(path, number, entry)
    return SessionLog(head, entries, path)


def _check_action(path: Path, number: int, entry: dict) -> None:
    action = entry.get("action")
    fields = {key: value for key, value in entry.items() if key not in ("t", "kind", "action")}
    if action not in ACTIONS:
        raise FileFormatError(path, number, f"key 'action': expected one of {', '.join(ACTIONS)}, got {action!r}")
    unknown = sorted(fields.keys() - ACTIONS[action])
    if unknown:
        raise FileFormatError(path, number, f"{action}: unknown key {unknown[0]!r} (known: "
                         f"{', '.join(sorted(ACTIONS[action])) or 'none'})")
    for key, value in fields.items():
        if key in CHANGE_KEYS | {"rudder_deg", "course_deg"} and not _is(value, float):
            raise FileFormatError(path, number, f"key {key!r}: expected a number, got {value!r}")
    if action == "order":
        if "engine" in fields and fields["engine"] not in TELEGRAPH:
            raise FileFormatError(path, number, f"key 'engine': expected one of {', '.join(TELEGRAPH)}, "
                                                f"got {fields['engine']!r}")
        if "autopilot" in fields and not isinstance(fields["autopilot"], bool):
            raise FileFormatError(path, number, f"key 'autopilot': expected true or false, got {fields['autopilot']!r}")
    if action == "trigger" and not _is(fields.get("index"), int):
        raise FileFormatError(path, number, f"key 'index': expected an event's index, got {fields.get('index')!r}")
    if action == "message" and not (isinstance(fields.get("text"), str) and 0 < len(fields["text"]) <= MAX_MESSAGE):
        raise FileFormatError(path, number, f"key 'text': expected 1 to {MAX_MESSAGE} characters")


def _is(value: Any, kind: type) -> bool:
    """Whether ``value`` is a ``kind`` (a float may be written as an integer; a bool is neither)."""
    if isinstance(value, bool):
        return False
    if kind is float:
        return isinstance(value, (int, float)) and math.isfinite(value)
    return isinstance(value, kind)


def _refuse_constant(name: str) -> None:
    raise ValueError(f"{name} is not a number a session log holds")


def describe(log: SessionLog) -> str:
    """One line: what the log holds."""
    kinds: dict[str, int] = {}
    for entry in log.entries:
        kinds[entry["kind"]] = kinds.get(entry["kind"], 0) + 1
    counts = ", ".join(f"{n} {kind}" for kind, n in sorted(kinds.items()))
    return f"{Path(log.header['scenario']).name}, seed {log.header['seed']}, {log.end_s:.1f} s: {counts or 'nothing'}"

