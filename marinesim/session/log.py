"""The session log: a scenario, its seed and everything that happened in one viewer session, as JSON lines.

The first line says what ran (the scenario's path and sha256, the seed, the run's duration and dt, and
when the session ended); each line after it is one journal entry of the exercise
(:attr:`Exercise.journal`) with its simulation time ``t`` (s): events, alarms, acknowledgements, the
instructor's and the trainee's actions, key presses, pauses, and last the ``end``. No entry lies
outside the session (0 to its end, plus one step): a log that says otherwise is refused. The log is
written with a sidecar (``<log>.json``: its sha256, the hashes of the scenario and the vessel's files,
and its signature) as one unit, when the session ends. A replay (:mod:`marinesim.session.replay`)
reads it back and applies the ``action`` entries again at their times; the other entries are what
the session saw, kept for the debrief.

A debrief is evidence, so every reader gets the log's :class:`Verification`: verified only if the
sidecar is there, its sha256 is the log's, the log ends with its ``end`` entry, and its signature
checks: an HMAC-SHA256 of the log's bytes under this installation's key (:mod:`marinesim.session.signing`,
made on first use, readable by its owner only). A sha256 alone can be computed again by whoever edits the
log; the signature cannot be without the key. A log signed with a key this installation does not hold
cannot be checked here and is said to be so, not called forged. The header names the scenario and the
vessel's files by their sha256, so the signature covers them too: a replay refuses files changed since. The log's bytes hold no key:
the same session gives the same log everywhere; its sidecar's signature is this installation's.
"""

from __future__ import annotations

import hashlib
import hmac
import json
import logging
import math
import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from marinesim import __version__
from marinesim.atomic import sidecar_path
from marinesim.errors import FileFormatError, MarinesimError
from marinesim.formats import SIZE_LIMITS, check_file
from marinesim.manoeuvring.actuators import TELEGRAPH
from marinesim.scenario import Scenario
from marinesim.scenario.model import HELICOPTER_DECISIONS, MAX_DURATION_S
from marinesim.session.exercise import ACTIONS, CHANGE_KEYS, MAX_MESSAGE, MAX_STATION, WEATHER_KEYS, Exercise
from marinesim.session.sidecar import sha256, write_table
from marinesim.session.signing import installation_key, key_id, signature

FORMAT = "marinesim session log"
VERSION = 1

logger = logging.getLogger("marinesim.session")


@dataclass(frozen=True)
class Verification:
    """Whether a session log is whole and, byte for byte, the one a session on this installation wrote:
    :attr:`problems` (a code, then words an instructor reads) says what shows otherwise, none if it is."""

    sha256: str
    """The sha256 of the log's bytes as read (hex)."""
    problems: tuple[tuple[str, str], ...] = ()

    @property
    def verified(self) -> bool:
        return not self.problems

    def summary(self) -> str:
        """One line: verified, or ``UNVERIFIED LOG:`` and why."""
        if self.verified:
            return ("verified: the log is the one the session wrote on this installation (its sha256 and its "
                    "signature match) and it runs to the session's end")
        return "UNVERIFIED LOG: " + "; ".join(words for _, words in self.problems)


@dataclass(frozen=True)
class SessionLog:
    """What ran (:attr:`header`) and what happened (:attr:`entries`, in time order), read from :attr:`path`."""

    header: dict[str, Any]
    entries: list[dict[str, Any]]
    path: Path
    verification: Verification

    def line_of(self, entry: dict[str, Any]) -> int | None:
        """The line of the log ``entry`` was read from (the header is line 1)."""
        return next((i + 2 for i, e in enumerate(self.entries) if e is entry), None)

    @property
    def end_s(self) -> float:
        """When the session ended (s): its last entry's time, or 0."""
        return self.entries[-1]["t"] if self.entries else 0.0

    def actions(self) -> list[dict[str, Any]]:
        """The entries a replay applies again, in order."""
        return [entry for entry in self.entries if entry["kind"] == "action"]


def header(scenario: Scenario, duration_s: float, end_s: float) -> dict[str, Any]:
    """The first line of a session's log: what ran (the scenario and the vessel's files, with their sha256:
    signed with the log, so a replay of other physics is told), planned for ``duration_s`` and ended at
    ``end_s`` (s)."""
    return {"format": FORMAT, "version": VERSION, "scenario": str(Path(scenario.path).resolve()),
            "scenario_sha256": sha256(scenario.path), "seed": scenario.run.seed, "duration_s": duration_s,
            "dt_s": scenario.run.dt_s, "end_s": end_s, "marinesim": __version__,
            "vessel_sha256": {key: sha256(path) for key, path in vessel_files(scenario).items()}}


def vessel_files(scenario: Scenario) -> dict[str, Path]:
    """The files the vessel of ``scenario`` is read from (its RAO table, its hull if any, a vessel keeping station's
    files) and the other vessels' RAO tables, by role."""
    vessel = scenario.vessel
    if vessel is None:
        return {}
    station = scenario.station.files if scenario.station is not None else {}
    others = {role: path for other in scenario.others for role, path in other.files.items()}
    return {"rao": vessel.rao_path, **({"hull": vessel.hull_path} if vessel.hull_path else {}), **station, **others}


def write_log(path: Path, exercise: Exercise) -> Path:
    """Write ``exercise``'s journal as a session log at ``path`` with its sidecar, signed with this installation's
    key, as one unit; returns ``path``. Without a key (one that cannot be made or read) the log is written
    unsigned, with a warning: the session's record is kept, and its readers say it is unverified."""
    scenario = exercise.scenario
    head = header(scenario, exercise.duration_s, exercise.sim.time)
    lines = [json.dumps(head)]
    lines += [json.dumps(entry, allow_nan=False) for entry in exercise.journal]
    data = ("\n".join(lines) + "\n").encode("utf-8")
    try:
        signed = {"signature": signature(installation_key(create=True), data)}
    except MarinesimError as error:
        logger.warning("marinesim: warning: %s; the session log is written unsigned", error)
        signed = {}

    def describe() -> dict:  # the files' hashes as the header gives them: each file read once
        paths = {"scenario": scenario.path} | vessel_files(scenario)
        hashes = {"scenario": head["scenario_sha256"]} | head["vessel_sha256"]
        return {"format": FORMAT, "entries": len(exercise.journal), "end_s": exercise.sim.time,
                "files": {key: {"path": p, "sha256": hashes[key]} for key, p in paths.items()}} | signed

    Path(path).parent.mkdir(parents=True, exist_ok=True)
    write_table(Path(path), lambda temp: temp.write_bytes(data), describe)
    return Path(path)


def read_log(path: Path) -> SessionLog:
    """Read and check a session log (each fault is reported as one line naming the file, line and key) and
    verify it (:attr:`SessionLog.verification`)."""
    path = Path(path)
    check_file(path, "session log")  # its size too (SIZE_LIMITS)
    try:
        data = path.read_bytes()
        text = data.decode("utf-8")
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
        if not is_a(head.get(key), kind):
            raise FileFormatError(path, 1, f"key {key!r}: expected {kind.__name__}, got {head.get(key)!r}")
    hashes = head.get("vessel_sha256", {})
    if not (isinstance(hashes, dict) and all(isinstance(v, str) for v in hashes.values())):
        raise FileFormatError(path, 1, f"key 'vessel_sha256': expected a table of sha256 by file, got {hashes!r}")
    end = _session_end(path, head)
    limit = end + head["dt_s"]
    entries = records[1:]
    last = 0.0
    for number, entry in enumerate(entries, start=2):
        t = entry.get("t")
        if not is_a(t, float) or not last <= t <= limit:
            raise FileFormatError(path, number, f"key 't': expected a time (s) from {last:g} (the entry before) to "
                                                f"{end:g} (the session's end, line 1) plus one step, got {t!r}")
        last = t
        if not isinstance(entry.get("kind"), str):
            raise FileFormatError(path, number, f"key 'kind': expected a string, got {entry.get('kind')!r}")
        if entry["kind"] == "action":
            _check_action(path, number, entry)
    return SessionLog(head, entries, path, verify(path, data, entries))


def _session_end(path: Path, head: dict) -> float:
    """When the session of ``head`` (line 1 of ``path``) ended (s): its ``end_s``, or in a log that does not say
    (written before logs did; unsigned, so unverified), the longest run a scenario allows: the viewer runs on past
    the planned ``duration_s``. A run length no scenario allows is refused."""
    duration, dt = head["duration_s"], head["dt_s"]
    if not 0.0 < duration <= MAX_DURATION_S:
        raise FileFormatError(path, 1, f"key 'duration_s': expected a run length in (0, {MAX_DURATION_S:g}] s, "
                                       f"got {duration!r}")
    if not 0.0 < dt <= duration:
        raise FileFormatError(path, 1, f"key 'dt_s': expected a step in (0, duration_s] s, got {dt!r}")
    end = head.get("end_s", MAX_DURATION_S)
    if not is_a(end, float) or not 0.0 <= end <= MAX_DURATION_S:
        raise FileFormatError(path, 1, f"key 'end_s': expected the session's end in [0, {MAX_DURATION_S:g}] s, "
                                       f"got {end!r}")
    return end


def verify(path: Path, data: bytes, entries: list[dict[str, Any]]) -> Verification:
    """The :class:`Verification` of the log at ``path``, of bytes ``data`` and ``entries`` (read from them)."""
    digest = hashlib.sha256(data).hexdigest()
    problems = _sidecar_problems(path, data, digest)
    if not entries or entries[-1]["kind"] != "end":
        problems.append(("truncated", "the log is cut short: it has no end entry, so the end of the session may be "
                                      "missing"))
    return Verification(digest, tuple(problems))


def _sidecar_problems(path: Path, data: bytes, digest: str) -> list[tuple[str, str]]:
    """What the sidecar of the log ``path`` (bytes ``data``, sha256 ``digest``) shows against it: nothing if its
    sha256 and this installation's signature match."""
    side = sidecar_path(path)
    try:
        found = os.stat(side)
        if not stat.S_ISREG(found.st_mode) or found.st_size > SIZE_LIMITS["session log sidecar"]:
            return [("bad sidecar", f"its sidecar {side.name} is not a sidecar (not a file, or over "
                                    f"{SIZE_LIMITS['session log sidecar']} bytes)")]
        meta = json.loads(side.read_bytes())
    except FileNotFoundError:
        return [("no sidecar", f"its sidecar {side.name} is missing, so nothing shows that the log is the one the "
                               "session wrote")]
    except (OSError, ValueError, RecursionError) as error:
        reason = getattr(error, "strerror", None) or error
        return [("bad sidecar", f"its sidecar {side.name} cannot be read ({reason})")]
    if not isinstance(meta, dict):
        return [("bad sidecar", f"its sidecar {side.name} is not a sidecar (not a JSON object)")]
    if meta.get("data_sha256") != digest:
        return [("hash mismatch", "the log was changed after the session wrote it: its sha256 is not the one its "
                                  "sidecar gives")]
    signed = meta.get("signature")
    if signed is None:
        return [("unsigned", "the log is not signed, so an edit made together with its sidecar could not be told")]
    if not (isinstance(signed, dict) and isinstance(signed.get("key_id"), str)
            and isinstance(signed.get("hmac_sha256"), str) and re.fullmatch(r"[0-9a-f]{16}", signed["key_id"])
            and re.fullmatch(r"[0-9a-f]{64}", signed["hmac_sha256"])):
        return [("bad sidecar", f"its sidecar {side.name} holds a signature marinesim does not write")]
    try:
        key = installation_key()
    except MarinesimError as error:
        return [("cannot check", f"its signature cannot be checked here: {error}")]
    if key is None or signed["key_id"] != key_id(key):
        return [("signed elsewhere", f"it was signed with a key this installation does not hold (key "
                                     f"{signed['key_id']}: signed on another marinesim installation, or altered): "
                                     "its signature cannot be checked here")]
    if not hmac.compare_digest(signed["hmac_sha256"], signature(key, data)["hmac_sha256"]):
        return [("signature mismatch", "the log and its sidecar were both changed after the session wrote them: the "
                                       "log's signature does not match")]
    return []


def _check_action(path: Path, number: int, entry: dict) -> None:
    problem = action_problem(entry)
    if problem is not None:
        raise FileFormatError(path, number, problem)


def action_problem(entry: dict) -> str | None:
    """What is wrong with the action ``entry`` (``{"action": ..., its fields}``; ``t`` and ``kind`` aside) in one
    line naming the key and what was expected, or None: what a log's reader and the exercise server both ask."""
    action = entry.get("action")
    fields = {key: value for key, value in entry.items() if key not in ("t", "kind", "action")}
    if action not in ACTIONS:
        return f"key 'action': expected one of {', '.join(ACTIONS)}, got {action!r}"
    unknown = sorted(fields.keys() - ACTIONS[action])
    if unknown:
        return f"{action}: unknown key {unknown[0]!r} (known: {', '.join(sorted(ACTIONS[action])) or 'none'})"
    for key, value in fields.items():
        if key in CHANGE_KEYS | WEATHER_KEYS | {"rudder_deg", "course_deg", "set_north_m", "set_east_m", "hoist_m_s",
                                                "slew_deg_s"} \
                and not is_a(value, float):
            return f"key {key!r}: expected a number, got {value!r}"
    if action == "order":
        if "engine" in fields and fields["engine"] not in TELEGRAPH:
            return f"key 'engine': expected one of {', '.join(TELEGRAPH)}, got {fields['engine']!r}"
        if "autopilot" in fields and not isinstance(fields["autopilot"], bool):
            return f"key 'autopilot': expected true or false, got {fields['autopilot']!r}"
        if "helicopter" in fields and fields["helicopter"] not in HELICOPTER_DECISIONS:
            return f"key 'helicopter': expected one of {', '.join(HELICOPTER_DECISIONS)}, got {fields['helicopter']!r}"
        if "fault" in fields and not (isinstance(fields["fault"], str) and 0 < len(fields["fault"]) <= 80):
            return f"key 'fault': expected a fault's name (1 to 80 characters), got {fields['fault']!r}"
        if "vessel" in fields and not (isinstance(fields["vessel"], str) and 0 < len(fields["vessel"]) <= 40):
            return f"key 'vessel': expected another ship's name (1 to 40 characters), got {fields['vessel']!r}"
    if action == "trigger" and not is_a(fields.get("index"), int):
        return f"key 'index': expected an event's index, got {fields.get('index')!r}"
    if action in ("message", "report") and not (isinstance(fields.get("text"), str)
                                                and 0 < len(fields["text"]) <= MAX_MESSAGE):
        return f"key 'text': expected 1 to {MAX_MESSAGE} characters"
    for key in ("to", "station"):
        if key in fields and not (isinstance(fields[key], str) and len(fields[key]) <= MAX_STATION):
            return f"key {key!r}: expected a station's name of at most {MAX_STATION} characters, got {fields[key]!r}"
    return None


def is_a(value: Any, kind: type) -> bool:
    """Whether ``value`` is a ``kind`` (a float may be written as an integer; a bool is neither)."""
    if isinstance(value, bool):
        return False
    if kind is float:
        try:
            return isinstance(value, (int, float)) and math.isfinite(value)
        except OverflowError:  # an integer past any float (10**400)
            return False
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

